// The conductor in time (MODEL.md 16): the Hermite beam's natural frequencies
// converge on the pinned beam-string's formula as the mesh is refined, Newmark's
// average acceleration keeps the undamped beam's energy, and under the EBM's own
// wind the span without dampers settles on the EBM's amplitude.

#include <algorithm>
#include <memory>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/conductor_in_time.hpp"
#include "stockbridge/span/impedance_sheet.hpp"
#include "stockbridge/span/undamped.hpp"
#include "support/test_scale.hpp"
#include "unit/span/aster570.hpp"

namespace stockbridge::span {
namespace {

using testing::aster570;
using testing::aster570_tension;

/// The largest relative error of the first `modes` frequencies against the formula.
double largest_frequency_error(const BeamProperties& beam, int elements, int modes) {
  const std::vector<double> f = BeamModel(beam, elements).natural_frequencies(modes);
  double worst = 0.0;
  for (int n = 1; n <= modes; ++n) {
    worst = std::max(worst, std::abs(f[n - 1] / beam.pinned_frequency(n) - 1.0));
  }
  return worst;
}

// The first 20 frequencies of the pinned beam-string, the example's conductor and a
// beam stiff enough that bending doubles the 20th: the error falls as h^4 (by about
// 16 at each halving of the elements) and is below 1e-4 at 20 elements per
// wavelength of the 20th mode.
TEST(ConductorInTime, NaturalFrequenciesConvergeOnThePinnedBeamString) {
  const BeamProperties conductor{100.0, aster570().mass_per_length, aster570_tension, aster570().ei_min, BeamEnds::pinned};
  BeamProperties stiff = conductor;
  stiff.ei = 3.0 * aster570_tension * std::pow(100.0 / (20.0 * std::numbers::pi), 2);  // (n pi / L)^2 EI / T = 3 at n = 20
  for (const BeamProperties& beam : {conductor, stiff}) {
    SCOPED_TRACE(beam.ei);
    const double coarse = largest_frequency_error(beam, 50, 20);   // 5 elements per wavelength of mode 20
    const double medium = largest_frequency_error(beam, 100, 20);  // 10
    const double fine = largest_frequency_error(beam, 200, 20);    // 20
    EXPECT_GT(coarse / medium, 12.0) << coarse << " " << medium;
    EXPECT_GT(medium / fine, 12.0) << medium << " " << fine;
    EXPECT_LT(fine, 1e-4);
  }
  EXPECT_NEAR(stiff.pinned_frequency(20) / conductor.pinned_frequency(20), 2.0, 1e-3);
}

// Clamped ends hold the slope too: each frequency above the pinned beam's, and for
// the string-like conductor only slightly (the bending boundary layer is short).
TEST(ConductorInTime, ClampedEndsStiffenTheBeam) {
  BeamProperties beam{100.0, aster570().mass_per_length, aster570_tension, aster570().ei_min, BeamEnds::pinned};
  const std::vector<double> pinned = BeamModel(beam, 200).natural_frequencies(10);
  beam.ends = BeamEnds::clamped;
  const std::vector<double> clamped = BeamModel(beam, 200).natural_frequencies(10);
  for (int n = 0; n < 10; ++n) {
    EXPECT_GT(clamped[n], pinned[n]);
    EXPECT_LT(clamped[n], 1.01 * pinned[n]);
  }
}

/// The example's conductor on a clamped 50 m span in 60 elements.
BeamModel clamped_50m() {
  return BeamModel({50.0, aster570().mass_per_length, aster570_tension, aster570().ei_min, BeamEnds::clamped}, 60);
}

/// The same in elements of 1 m: a node at every metre, where the dampers go.
BeamModel clamped_50m_in_metres() {
  return BeamModel({50.0, aster570().mass_per_length, aster570_tension, aster570().ei_min, BeamEnds::clamped}, 50);
}

/// Random displacements (about 1 mm) and velocities (about 50 mm/s) of every free
/// degree of freedom.
std::pair<Eigen::VectorXd, Eigen::VectorXd> random_motion(const BeamModel& model, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1e-3);
  Eigen::VectorXd u(model.size()), v(model.size());
  for (Eigen::Index i = 0; i < model.size(); ++i) {
    u(i) = normal(random);
    v(i) = 50.0 * normal(random);
  }
  return {u, v};
}

// Without load or damping, Newmark's average acceleration conserves the energy of
// any motion (here a random mix of displacements and velocities on a clamped span)
// to round-off: within 1e-6 at every step of 10 s.
TEST(ConductorInTime, TheUndampedBeamKeepsItsEnergy) {
  const BeamModel model = clamped_50m();
  const auto [u0, v0] = random_motion(model, 7);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  NewmarkStepper stepper(model, 2e-4, u0, v0, zero);
  const double e0 = stepper.energy();
  ASSERT_GT(e0, 0.0);
  double worst = 0.0;
  while (stepper.time() < 10.0) {
    stepper.step(zero);
    worst = std::max(worst, std::abs(stepper.energy() / e0 - 1.0));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(stepper.displacement().norm(), 0.0);
}

/// D. Sauter's verification damper, as the examples ship it.
damper::Damper sauter_damper() {
  return io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml");
}

// The beam and two of Sauter's dampers, 1 m from each clamp, solved together each
// step, without load: the beam's energy plus what the dashpot took minus the work the
// dampers' forces did on it stays at its start to 1e-9 at every step of 2 s (the
// rule's own balance, which holds only if each step's forces are the ones the beam
// moved under), while the dampers take energy out and their cables dissipate it.
TEST(ConductorInTime, TheBeamAndItsDampersAccountForTheEnergy) {
  const BeamModel model = clamped_50m_in_metres();
  const auto [u0, v0] = random_motion(model, 5);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  const double dt = 2e-4;
  const damper::Damper sauter = sauter_damper();
  std::vector<BeamDamper> dampers;
  for (const double x : {1.0, 49.0}) dampers.push_back({x, damper::DamperInTime(sauter, dt, {})});
  NewmarkStepper stepper(model, dt, u0, v0, zero, model.damping({{20.0, 5.0}}), std::move(dampers));
  const double e0 = stepper.energy();
  double worst = 0.0;
  while (stepper.time() < 2.0) {
    stepper.step(zero);
    worst = std::max(worst, std::abs((stepper.energy() + stepper.dissipated() - stepper.dampers_work()) / e0 - 1.0));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(stepper.dampers_work(), -0.1 * e0);
  double sliders = 0.0;
  for (const BeamDamper& d : stepper.dampers()) sliders += d.damper.dissipated();
  EXPECT_GT(sliders, 0.0);
  EXPECT_LT(sliders, -stepper.dampers_work());  // part is still in the dampers' motion
  EXPECT_NEAR(stepper.clamp_displacement(0), model.at(stepper.displacement(), 1.0).first, 1e-15);
}

Span example_span() {
  return io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml").span;
}

double ebm_amplitude(const Span& span, double f) {
  return *undamped_amplitude(span.wind(), span.self_damping(), span.conductor(), span.tension(), span.length(), f);
}

// Dashpots take energy and the rule accounts for it: without load, the energy left
// plus the energy the dashpots took stays at the start's to 1e-9 over 5 s, while
// the dashpots take most of it.
TEST(ConductorInTime, DashpotsTakeTheEnergyTheBeamLoses) {
  const BeamModel model = clamped_50m();
  const auto [u0, v0] = random_motion(model, 11);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  NewmarkStepper stepper(model, 2e-4, u0, v0, zero, model.damping({{1.0, 100.0}, {49.0, 100.0}, {20.3, 30.0}}));
  const double e0 = stepper.energy();
  double worst = 0.0;
  while (stepper.time() < 5.0) {
    stepper.step(zero);
    worst = std::max(worst, std::abs((stepper.energy() + stepper.dissipated()) / e0 - 1.0));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(stepper.dissipated(), 0.5 * e0);
  EXPECT_THROW(model.damping({{50.0, 10.0}}), InvalidParameter);  // at the clamp
  EXPECT_THROW(model.damping({{10.0, 0.0}}), InvalidParameter);
}

// The example span without its dampers under the EBM's wind (a), started 10 % below
// the EBM's amplitude (and at 30 Hz also 10 % above): it settles on it within 2 % at
// three frequencies of the band, at the mode nearest each (within half a mode's
// spacing, and Newmark's period elongation of (pi / steps)^2 / 3), from either side
// to within 0.5 % of each other.
TEST(ConductorInTime, TheEbmWindSettlesTheSpanOnTheEbmsAmplitude) {
  if (stockbridge::testing::short_tests()) GTEST_SKIP() << "minutes of simulated time: the Release build runs it";
  const Span span = example_span();
  const double spacing = 0.5 * std::sqrt(span.tension() / span.conductor().mass_per_length) / span.length();
  for (const double f : {12.0, 20.0, 30.0}) {
    SCOPED_TRACE(f);
    std::vector<double> settled_at;
    for (const double start : f == 30.0 ? std::vector<double>{0.9, 1.1} : std::vector<double>{0.9}) {
      EbmWindOptions options;
      options.frequency_hz = f;
      options.duration_s = 300.0;
      options.start_amplitude_m = start * ebm_amplitude(span, f);
      const EbmWindHistory history = settle_on_ebm_wind(span.without_dampers(), BeamEnds::pinned, options);
      const double expected = ebm_amplitude(span, history.frequency_hz);
      EXPECT_TRUE(history.settled) << history.time_s << " s";
      EXPECT_NEAR(history.antinode_amplitude_m / expected, 1.0, 0.02)
          << history.antinode_amplitude_m << " m against " << expected << " m at " << history.frequency_hz << " Hz, "
          << history.elements << " elements, " << history.time_s << " s";
      const double elongation = std::pow(std::numbers::pi / options.steps_per_period, 2) / 3.0;
      EXPECT_LE(std::abs(history.frequency_hz - f), 0.5 * spacing * 1.01 + elongation * f);
      settled_at.push_back(history.antinode_amplitude_m);
    }
    if (settled_at.size() == 2) {
      EXPECT_NEAR(settled_at[0] / settled_at[1], 1.0, 5e-3);
    }
  }
}

// The wind's net power has the EBM's sign: below the EBM's amplitude it grows the
// motion, above it it takes the motion down; two seconds settle nothing.
TEST(ConductorInTime, TheEbmWindGrowsASmallMotionAndTakesALargeOneDown) {
  const Span span = example_span();
  for (const double start : {0.5, 2.0}) {
    SCOPED_TRACE(start);
    EbmWindOptions options;
    options.frequency_hz = 30.0;
    options.duration_s = 2.0;
    options.start_amplitude_m = start * ebm_amplitude(span, 30.0);
    const EbmWindHistory history = settle_on_ebm_wind(span.without_dampers(), BeamEnds::clamped, options);
    EXPECT_FALSE(history.settled);
    ASSERT_GT(history.envelope_m.size(), 50u);
    for (std::size_t i = 1; i < history.envelope_m.size(); ++i) {
      EXPECT_EQ(history.envelope_m[i] > history.envelope_m[i - 1], start < 1.0) << i;
    }
    EXPECT_EQ(history.x_m.size(), static_cast<std::size_t>(history.elements + 1));
    EXPECT_NEAR(*std::max_element(history.amplitude_m.begin(), history.amplitude_m.end()),
                history.antinode_amplitude_m, 0.05 * history.antinode_amplitude_m);
  }
}

// A light dashpot (10 N s/m, 1 m from each clamp; it takes a quarter of the span's
// amplitude at 30 Hz) under the EBM's wind: the amplitude at mid-span settles within
// 2 % of the balance's with a damper of the same impedance (a measured sheet of
// constant Z = 10 N s/m), and the dashpots take the power the balance gives them.
TEST(ConductorInTime, ALightDashpotSettlesWhereTheBalanceSays) {
  if (stockbridge::testing::short_tests()) GTEST_SKIP() << "minutes of simulated time: the Release build runs it";
  const double c = 10.0, position = 1.0, f = 30.0;
  damper::ImpedanceMeasurement sheet;
  for (const double v : {0.001, 3.0}) {
    for (const double fr : {1.0, 10.0, 50.0, 200.0}) sheet.points.push_back({damper::Excitation::from_velocity(fr, v), {c, 0.0}});
  }
  SpanDamper dashpot;
  dashpot.position = position;
  dashpot.name = "dashpot";
  dashpot.sheet = std::make_shared<const ImpedanceSheet>(sheet, "dashpot");
  const Span span = example_span().with_dampers({dashpot}).with_masses({});
  EbmWindOptions options;
  options.frequency_hz = f;
  options.duration_s = 120.0;
  options.start_amplitude_m = 0.9 * ebm_amplitude(span, f);  // the undamped span's
  const EbmWindHistory history =
      settle_on_ebm_wind(span.without_dampers(), BeamEnds::pinned, options, {{position, c}, {span.length() - position, c}});
  const BalanceOptions balance_options;
  const SpanBalance balance = run_balance(span, SpanTables(span, {history.frequency_hz}, balance_options.table), balance_options);
  ASSERT_TRUE(balance.points.at(0).converged());
  const BalancePoint& p = balance.points[0];
  EXPECT_TRUE(history.settled) << history.time_s << " s";
  EXPECT_LT(p.amplitude, 0.85 * ebm_amplitude(span, history.frequency_hz));  // the dashpots matter
  EXPECT_NEAR(history.antinode_amplitude_m / p.amplitude, 1.0, 0.02) << history.antinode_amplitude_m << " m against " << p.amplitude;
  ASSERT_EQ(history.dashpot_power_w.size(), 2u);
  EXPECT_NEAR(history.dashpot_power_w[0] / p.dampers.at(0).power, 1.0, 0.03)
      << history.dashpot_power_w[0] << " W against " << p.dampers.at(0).power << ", settled by "
      << settled_by_name(history.settled_by) << " at " << history.time_s << " s, Y " << history.antinode_amplitude_m / p.amplitude;
}

// Alone (no motion of the conductor), the wake oscillator is a van der Pol oscillator:
// from q = 0.1 it grows by exp(pi epsilon) over its first period, onto the limit
// cycle, whose amplitude is 2.00092 and period 1.005611 / f at epsilon = 0.3 (an
// adaptive integration at 1e-11), the latter longer by Newmark's (pi / steps)^2 / 3.
TEST(WakeOscillatorInTime, AloneItIsAVanDerPolOscillatorOfAmplitudeTwo) {
  const double f = 20.0, w = 2.0 * std::numbers::pi * f;
  const int steps = 160;
  const double dt = 1.0 / (f * steps);
  WakeOscillators wake(3, WakeParameters{}, w, 0.031, dt, 0.1);
  const Eigen::VectorXd still = Eigen::VectorXd::Zero(3);
  std::vector<double> q, crossings;
  for (int i = 1; i <= 200 * steps; ++i) {
    const double before = wake.q()(0);
    wake.step(still);
    q.push_back(wake.q()(0));
    if (before < 0.0 && wake.q()(0) >= 0.0) crossings.push_back((i - 1 + before / (before - wake.q()(0))) * dt);
  }
  EXPECT_EQ(wake.q()(0), wake.q()(2));  // each oscillator its own, alike
  const double largest = *std::max_element(q.end() - 2 * steps, q.end());
  EXPECT_NEAR(largest, 2.00092, 1e-3);
  EXPECT_NEAR(*std::max_element(q.begin(), q.begin() + steps), 0.1 * std::exp(std::numbers::pi * 0.3), 0.005);
  ASSERT_GT(crossings.size(), 100u);
  const double period = (crossings.back() - crossings[crossings.size() - 51]) / 50.0;
  const double expected = 1.005611 * (1.0 + std::pow(std::numbers::pi / steps, 2) / 3.0) / f;
  EXPECT_NEAR(period / expected, 1.0, 2e-4) << period * f;
}

// The wake's wind on the bare example span, shedding at its mode near 20 Hz (lock-in):
// from below and from above the span settles on one amplitude (a limit cycle, within
// 1 %), where the lift's power equals the self-damping's (within 1 %).
TEST(WakeOscillatorInTime, TheWakeSettlesTheSpanOnOneAmplitudeWhereItsPowerIsTheDampings) {
  if (stockbridge::testing::short_tests()) GTEST_SKIP() << "minutes of simulated time: the Release build runs it";
  const Span span = example_span().without_dampers();
  std::vector<double> settled_at;
  for (const double start : {0.004, 0.016}) {
    SCOPED_TRACE(start);
    EbmWindOptions options;
    options.frequency_hz = 19.92;  // the bare pinned span's mode 50
    options.duration_s = 400.0;
    options.start_amplitude_m = start;
    options.wind = WindInTime::wake;
    const EbmWindHistory history = settle_on_ebm_wind(span, BeamEnds::pinned, options);
    ASSERT_TRUE(history.settled) << history.time_s << " s";
    EXPECT_NEAR(history.wind_speed_m_s, options.frequency_hz * span.conductor().diameter / span.wind().strouhal, 1e-12);
    EXPECT_NEAR(history.wind_power_w / history.damping_power_w, 1.0, 0.01)
        << history.wind_power_w << " W against " << history.damping_power_w << " W";
    EXPECT_GT(history.damping_power_w, 0.0);
    settled_at.push_back(history.antinode_amplitude_m);
  }
  EXPECT_NEAR(settled_at[0] / settled_at[1], 1.0, 0.01) << settled_at[0] << " m and " << settled_at[1] << " m";
  EXPECT_GT(settled_at[0], 0.004);
  EXPECT_LT(settled_at[0], 0.016);
}

TEST(ConductorInTime, RefusesWhatItCannotModel) {
  BeamProperties beam{100.0, 1.5, 20000.0, 30.0, BeamEnds::pinned};
  EXPECT_THROW(BeamModel(beam, 1), InvalidParameter);
  beam.tension = 0.0;
  EXPECT_THROW(BeamModel(beam, 10), InvalidParameter);
  EXPECT_EQ(parse_beam_ends("clamped"), BeamEnds::clamped);
  EXPECT_THROW(parse_beam_ends("hinged"), InvalidParameter);
  EXPECT_EQ(parse_wind_in_time("wake"), WindInTime::wake);
  EXPECT_THROW(parse_wind_in_time("breeze"), InvalidParameter);
  WakeParameters wake;
  wake.epsilon = 0.0;
  EXPECT_THROW(wake.validate(), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::span
