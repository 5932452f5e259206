// Masses and dampers along the span (MODEL.md section 15): zero masses give back the
// span without them, the stretches' amplitudes follow the transfer chain worked by
// hand, the energy identity and the balance hold with spheres and dampers beside
// them, a mass's clamp stress is the point force's, and the verdict judges the
// governing place (both span clamps and the masses' clamps).

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "aster570.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::span {
namespace {

using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

constexpr double kLength = 400.0;

damper::Damper sauter() {
  const damper::ArmDescription arm = stockbridge::testing::sauter_arm();
  return stockbridge::testing::damper_of({arm, arm}, 0.7);
}

SpanDamper at_both_ends(double position) { return {sauter(), position, true, "sauter", nullptr, std::nullopt}; }

SpanDamper along(std::vector<double> positions) {
  SpanDamper d{sauter(), 0.0, false, "beside", nullptr, std::nullopt};
  d.along = std::move(positions);
  return d;
}

Span aster_span(std::vector<SpanDamper> dampers, std::vector<SpanMass> masses = {}) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  return Span(aster570(), kLength, aster570_tension, WindModel{}, SelfDampingModel{}, std::move(dampers), fatigue,
              std::nullopt, std::move(masses));
}

SpanBalance balance_of(const Span& span, const std::vector<double>& frequencies,
                       const BalanceOptions& options = BalanceOptions{}) {
  return run_balance(span, SpanTables(span, frequencies, options.table), options);
}

std::vector<double> band() { return damper::log_spaced(8.0, 38.0, stockbridge::testing::scaled(5, 3)); }

/// `b` gives `a`'s figures to 1e-9 at every point (each converged), and its verdict.
void expect_same_figures(const SpanBalance& b, const SpanBalance& a) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const BalancePoint &p = a.points[i], &q = b.points[i];
    SCOPED_TRACE(p.frequency_hz);
    ASSERT_TRUE(p.converged() && q.converged()) << brief_report(q.summary);
    expect_relative(q.amplitude, p.amplitude, 1e-9);
    expect_relative(q.stress_fymax, p.stress_fymax, 1e-9);
    expect_relative(q.stress_poffenberger_swart, p.stress_poffenberger_swart, 1e-9);
    expect_relative(q.undamped_amplitude, p.undamped_amplitude, 1e-9);
    expect_relative(q.wind_power, p.wind_power, 1e-9);
    ASSERT_EQ(q.dampers.size(), p.dampers.size());
    for (std::size_t d = 0; d < p.dampers.size(); ++d) {
      expect_relative(q.dampers[d].clamp_velocity, p.dampers[d].clamp_velocity, 1e-9);
    }
  }
  EXPECT_EQ(b.summary.verdict, a.summary.verdict);
}

// Masses of zero weight anywhere (inside an end's damper zone too) leave every
// figure as it was. The masses split the span into stretches and make the two ends'
// chains differ (two clamp velocities where there was one by symmetry), so the
// solvers take other paths: with the polish converged to 1e-12 (the default 1e-6
// leaves some 1e-8 in the stresses) the figures agree to 1e-9.
TEST(SpanAttachments, ZeroMassesGiveTheSpanWithoutThem) {
  const Span bare = aster_span({at_both_ends(1.0)});
  const Span zero = aster_span({at_both_ends(1.0)}, {SpanMass{"nothing", 0.0, {0.5, 60.0, 200.0, 345.5}, 1.0}});
  BalanceOptions tight;
  tight.polish_tolerance = 1e-12;
  const SpanBalance a = balance_of(bare, band(), tight), b = balance_of(zero, band(), tight);
  expect_same_figures(b, a);
  for (const BalancePoint& q : b.points) EXPECT_EQ(q.masses.size(), 4u);
  expect_relative(b.summary.max_judged_stress, a.summary.max_judged_stress, 1e-9);
}

/// The span examples, by file name (examples/*.toml with a [span] table).
constexpr const char* kSpanExamples[] = {"aster570_400m.toml",    "aster570_800m.toml",
                                          "aster570_recorder.toml", "drake_300m.toml",
                                          "drake_one_velocity_sheet.toml", "opgw_600m_spheres.toml"};

// Every shipped span example, its dampers at the ends only and no masses, against the
// same span with zero masses at three places (one near an end): the same figures to
// 1e-9, each example with its own balance options, the polish converged to 1e-12.
TEST(SpanAttachments, ZeroMassesGiveEveryShippedExampleBack) {
  for (const char* name : kSpanExamples) {
    SCOPED_TRACE(name);
    const io::SpanFile file = io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/" + name);
    std::vector<SpanDamper> at_ends;
    for (const SpanDamper& d : file.span.dampers()) {
      if (!d.in_span()) at_ends.push_back(d);
    }
    const Span bare = file.span.with_dampers(at_ends).with_masses({});
    const double length = bare.length();
    const Span zero = bare.with_masses({SpanMass{"nothing", 0.0, {0.004 * length, 0.31 * length, 0.77 * length}, 1.0}});
    BalanceOptions tight = file.balance;
    tight.polish_tolerance = 1e-12;
    const std::vector<double> frequencies = band_frequencies(bare, stockbridge::testing::scaled(4, 2));
    expect_same_figures(balance_of(zero, frequencies, tight), balance_of(bare, frequencies, tight));
  }
}

/// The string's wave from end 1 through one mass M at a, worked by hand: Y = sin(kx)/k
/// before it; after it A e^{-jkx} + B e^{jkx} with the slope's jump -w^2 M Y(a) / T.
struct HandChain {
  double before = 0.0;  ///< the antinode amplitude between the clamp and the mass (unit slope at the clamp)
  double after = 0.0;   ///< |A| + |B| past it
};
HandChain hand_chain(double k, double w, double mass, double a, double tension) {
  const double y = std::sin(k * a) / k, slope = std::cos(k * a) - w * w * mass * y / tension;
  // y = A e^{-jka} + B e^{jka}, slope = jk (-A e^{-jka} + B e^{jka})
  const std::complex<double> j(0.0, 1.0);
  const std::complex<double> b = 0.5 * (y + slope / (j * k)) * std::exp(-j * k * a);
  const std::complex<double> a_wave = 0.5 * (y - slope / (j * k)) * std::exp(j * k * a);
  return {1.0 / k, std::abs(a_wave) + std::abs(b)};
}

// No dampers, one 15 kg sphere at 100 m: the stretch between the clamp and the sphere
// and the free span beyond it stand in the ratio of the hand chain, and the sphere's
// clamp stress is the point force w^2 M |Y| on the tensioned beam.
TEST(SpanAttachments, AMassSplitsTheSpanAsTheHandChainSays) {
  const double mass = 15.0, a = 100.0;
  const Span span = aster_span({}, {SpanMass{"sphere", mass, {a}, 1.0}});
  const SpanBalance b = balance_of(span, {12.0, 25.0});
  const Conductor c = aster570();
  for (const BalancePoint& p : b.points) {
    SCOPED_TRACE(p.frequency_hz);
    ASSERT_TRUE(p.converged()) << brief_report(p.summary);
    const double w = 2.0 * std::numbers::pi * p.frequency_hz, k = wavenumber(c, aster570_tension, p.frequency_hz);
    const HandChain h = hand_chain(k, w, mass, a, aster570_tension);
    const double loop = p.amplitude * h.before / h.after;  // the stretch [0, a] scaled to Y past the sphere
    expect_relative(p.clamp_loop_amplitude, loop, 1e-9);
    expect_relative(p.max_subspan_amplitude, std::max(loop, p.amplitude), 1e-9);
    ASSERT_EQ(p.masses.size(), 1u);
    expect_relative(p.masses[0].displacement, loop * std::abs(std::sin(k * a)), 1e-9);
    expect_relative(p.masses[0].clamp_stress,
                    point_force_stress(c, aster570_tension, w * w * mass * p.masses[0].displacement), 1e-12);
    // The balance over the two stretches, each at its own amplitude.
    const WindModel wind;
    const SelfDampingModel sd;
    const double expected_wind = wind.power(loop, p.frequency_hz, c.diameter, a) +
                                 wind.power(p.amplitude, p.frequency_hz, c.diameter, kLength - a);
    expect_relative(p.wind_power, expected_wind, 1e-12);
    const double expected_sd = sd.power(loop, p.frequency_hz, c, aster570_tension, a) +
                               sd.power(p.amplitude, p.frequency_hz, c, aster570_tension, kLength - a);
    expect_relative(p.self_damping_power, expected_sd, 1e-12);
    EXPECT_NEAR(p.wind_power - p.self_damping_power, 0.0, 1e-6 * p.wind_power);
    // Without dampers the undamped balance is the same balance.
    expect_relative(p.undamped_amplitude, p.amplitude, 1e-9);
  }
}

// Four 10 kg spheres with a damper on either side of the middle two, and dampers at
// both ends: every point balances, the energy identity holds, the dampers' powers
// add up to what the ends absorb.
TEST(SpanAttachments, SpheresWithDampersBesideThemKeepTheEnergyIdentity) {
  const Span span = aster_span({at_both_ends(1.0), along({149.0, 151.0, 249.0, 251.0})},
                               {SpanMass{"sphere", 10.0, {100.0, 150.0, 250.0, 300.0}, 1.0}});
  const SpanBalance b = balance_of(span, band());
  int converged = 0;
  for (const BalancePoint& p : b.points) {
    SCOPED_TRACE(p.frequency_hz);
    if (!p.converged()) continue;
    ++converged;
    EXPECT_LE(p.identity_error, 1e-8);
    EXPECT_NEAR(p.wind_power - p.self_damping_power - p.damper_power, 0.0, 1e-6 * p.wind_power);
    double dampers = 0.0;
    for (const DamperAtBalance& d : p.dampers) dampers += d.power;
    EXPECT_NEAR(dampers, p.damper_power, 1e-9 * p.damper_power);
    EXPECT_EQ(p.dampers.size(), 6u);
    EXPECT_EQ(p.masses.size(), 4u);
    EXPECT_LT(p.amplitude, p.undamped_amplitude);
  }
  EXPECT_GE(converged, static_cast<int>(0.99 * static_cast<double>(b.points.size())));
}

// Dampers at one end only: the other span clamp's loop is the free span's, and the
// verdict judges the larger of the two clamps' stresses: either can govern.
TEST(SpanAttachments, TheVerdictJudgesBothSpanClamps) {
  SpanDamper one_end = at_both_ends(1.0);
  one_end.both_ends = false;
  const Span span = aster_span({one_end});
  const SpanBalance b = balance_of(span, {8.0, 15.0, 38.0});
  double largest = 0.0;
  std::string place;
  for (const BalancePoint& p : b.points) {
    ASSERT_TRUE(p.converged());
    EXPECT_EQ(p.clamp_loop_amplitude_end2, p.amplitude);
    EXPECT_EQ(p.stress_fymax_end2, fymax_stress(aster570(), p.frequency_hz, p.amplitude));
    const GoverningPlace g = governing_place(span, p);
    EXPECT_EQ(g.stress, std::max(p.stress_fymax, p.stress_fymax_end2));
    EXPECT_EQ(g.place, p.stress_fymax_end2 > p.stress_fymax ? "span clamp 2" : "span clamp 1");
    if (g.stress > largest) largest = g.stress, place = g.place;
  }
  // 8 Hz: the damper (nearly a mass there) lifts its own clamp's loop above the
  // free span's (12.4 against 9.5 MPa); 38 Hz: it lowers it (6.0 against 8.3 MPa).
  EXPECT_EQ(governing_place(span, b.points.front()).place, "span clamp 1");
  EXPECT_EQ(governing_place(span, b.points.back()).place, "span clamp 2");
  EXPECT_EQ(b.summary.max_judged_stress, largest);
  EXPECT_EQ(b.summary.max_judged_stress_place, place);
}

// A heavy sphere whose clamp is a stress raiser governs the verdict and the life.
TEST(SpanAttachments, AMassClampCanGovern) {
  const Span plain = aster_span({at_both_ends(1.0)});
  Span raised = aster_span({at_both_ends(1.0)}, {SpanMass{"sphere", 20.0, {200.0}, 50.0}});
  const std::vector<double> f{15.0, 30.0};
  const SpanBalance b = balance_of(raised, f);
  for (const BalancePoint& p : b.points) {
    ASSERT_TRUE(p.converged());
    ASSERT_EQ(p.masses.size(), 1u);
    const GoverningPlace g = governing_place(raised, p);
    if (p.masses[0].clamp_stress > std::max(p.stress_fymax, p.stress_fymax_end2)) {
      EXPECT_EQ(g.place, "sphere at 200 m");
      EXPECT_EQ(judged_stress(raised, p), p.masses[0].clamp_stress);
    }
  }
  EXPECT_EQ(b.summary.max_judged_stress_place, "sphere at 200 m");
  EXPECT_GT(b.summary.max_judged_stress, balance_of(plain, f).summary.max_judged_stress);
}

TEST(SpanAttachments, PositionsOutsideTheSpanAndTheWeakFormAreRefused) {
  try {
    aster_span({}, {SpanMass{"sphere", 10.0, {100.0, 400.0}, 1.0}});
    FAIL() << "a mass at the far clamp was taken";
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("mass[0].positions[1]"), std::string::npos) << e.what();
  }
  try {
    aster_span({along({-1.0})});
    FAIL() << "a damper before end 1 was taken";
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("damper[0].positions[0]"), std::string::npos) << e.what();
  }
  const Span span = aster_span({}, {SpanMass{"sphere", 10.0, {100.0}, 1.0}});
  BalanceOptions weak;
  weak.damper_model = DamperModel::weak;
  EXPECT_THROW(run_balance(span, SpanTables(span, {20.0}, weak.table), weak), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::span
