// The span's energy balance with the nonlinear damper: the undamped limit, the
// energy identity at every point, the fixed point against harmonic balance solved
// directly at the converged clamp velocity, the weak-damper limit, today's
// one-damper results, a failed point kept out of the life and the verdict, the
// life's stress, the position search against a brute-force scan, and validation.
// Several dampers per end: tests/verification/span_reference_test.cpp.

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "aster570.hpp"
#include "span/balance_run.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/position_search.hpp"
#include "stockbridge/span/travelling_wave.hpp"
#include "stockbridge/span/undamped.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::span {
namespace {

using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

damper::Damper sauter_damper() {
  const damper::ArmDescription arm = stockbridge::testing::sauter_arm();
  return stockbridge::testing::damper_of({arm, arm}, 0.7);
}

Span aster_span(std::vector<SpanDamper> dampers) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  return Span(aster570(), 400.0, aster570_tension, WindModel{}, SelfDampingModel{}, std::move(dampers), fatigue);
}

BalanceOptions fast_options() { return BalanceOptions{}; }  // the defaults: a coarse table, the polish

TEST(SpanBalance, WithoutDampersItIsTheUndampedBalanceOfTheCheckNumbers) {
  const Span span = aster_span({});
  const std::vector<double> f{10.0, 20.0, 30.0, 40.0};
  const SpanBalance b = run_balance(span, SpanTables(span, f, {}), BalanceOptions{});
  const double expected[] = {26.5e-3, 10.6e-3, 3.04e-3, 1.58e-3};
  for (std::size_t i = 0; i < f.size(); ++i) {
    ASSERT_TRUE(b.points[i].converged()) << brief_report(b.points[i].summary);
    expect_relative(b.points[i].amplitude, expected[i], 0.005);
    EXPECT_EQ(b.points[i].amplitude, b.points[i].undamped_amplitude);
    EXPECT_EQ(b.points[i].clamp_loop_amplitude, b.points[i].amplitude);
    EXPECT_EQ(b.points[i].damper_power, 0.0);
  }
}

class NonlinearSpan : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    span_ = new Span(aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}}));
    // Half the frequencies of the same band under the sanitizers (STOCKBRIDGE_TEST_SCALE=short).
    frequencies_ = damper::log_spaced(6.0, 40.0, stockbridge::testing::scaled(8, 4));
    tables_ = new SpanTables(*span_, frequencies_, fast_options().table);
    balance_ = new SpanBalance(run_balance(*span_, *tables_, fast_options()));
  }
  static void TearDownTestSuite() {
    delete balance_;
    delete tables_;
    delete span_;
  }
  static Span* span_;
  static std::vector<double> frequencies_;
  static SpanTables* tables_;
  static SpanBalance* balance_;
};
Span* NonlinearSpan::span_ = nullptr;
std::vector<double> NonlinearSpan::frequencies_;
SpanTables* NonlinearSpan::tables_ = nullptr;
SpanBalance* NonlinearSpan::balance_ = nullptr;

TEST_F(NonlinearSpan, EveryPointBalancesAndKeepsTheEnergyIdentity) {
  for (const BalancePoint& p : balance_->points) {
    SCOPED_TRACE(p.frequency_hz);
    ASSERT_TRUE(p.converged()) << brief_report(p.summary);
    EXPECT_LE(p.identity_error, 1e-10);
    EXPECT_NEAR(p.wind_power - p.self_damping_power - p.damper_power, 0.0, 1e-8 * p.wind_power);
    double dampers = 0.0;
    for (const DamperAtBalance& d : p.dampers) dampers += d.power;
    EXPECT_NEAR(dampers, p.damper_power, 1e-10 * p.damper_power);
    ASSERT_EQ(p.dampers.size(), 2u);  // one damper at each end, alike by symmetry
    EXPECT_NEAR(p.dampers[0].clamp_velocity, p.dampers[1].clamp_velocity, 1e-9 * p.dampers[0].clamp_velocity);
    EXPECT_LT(p.amplitude, p.undamped_amplitude);  // the damper lowers the vibration
  }
  EXPECT_LT(balance_->summary.max_stress_fymax, balance_->summary.undamped_max_stress_fymax);
}

// Z solved again (a lone harmonic-balance point from a cold start, no table, no
// tracking) at the damper's converged clamp velocity, and the end's response
// recomputed with it: the velocity it gives back and the power balance agree to the
// polish's tolerance.
void expect_the_direct_solution(const Span& span, const BalancePoint& p) {
  SCOPED_TRACE(p.frequency_hz);
  ASSERT_TRUE(p.converged()) << brief_report(p.summary);
  const Conductor c = aster570();
  const double v = p.dampers[0].clamp_velocity;
  damper::SweepSpec lone;
  lone.frequencies = {p.frequency_hz};
  lone.amplitudes = {v};
  const damper::ImpedancePoint direct = damper::run_sweep(*span.dampers()[0].damper, lone).front().points.front();
  ASSERT_TRUE(direct.converged()) << direct.failure;
  EXPECT_LE(std::abs(direct.impedance - p.dampers[0].impedance), 1e-3 * std::abs(direct.impedance));
  const double w = 2.0 * std::numbers::pi * p.frequency_hz;
  const StringWave wave{w, wavenumber(c, aster570_tension, p.frequency_hz), wave_impedance(c, aster570_tension)};
  const EndResponse again = end_response(wave, {span.dampers()[0].position}, {direct.impedance}, p.amplitude);
  EXPECT_LE(std::abs(w * std::abs(again.damper_displacement[0]) - v), 1e-4 * v);
  EXPECT_LE(std::abs(p.wind_power - p.self_damping_power - 2.0 * again.absorbed_power), 1e-3 * p.wind_power);
}

// The table interpolates Z in log v and the polish corrects it with Z solved
// directly (tracked along the band). Without the polish the table alone (13 nodes)
// is off by up to 47 % in Z at 13.5 Hz.
TEST_F(NonlinearSpan, TheFixedPointAgreesWithHarmonicBalanceSolvedDirectly) {
  for (const BalancePoint& p : balance_->points) expect_the_direct_solution(*span_, p);
}

// A band finer than the table's columns (every other frequency solved, the others
// interpolated in log f): the polish still ends on the direct solution.
TEST(SpanBalance, InterpolatedColumnsArePolishedToTheDirectSolution) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f = damper::log_spaced(6.0, 30.0, 15);
  BalanceOptions options = fast_options();
  options.table.column_ratio = 1.3;  // 15 frequencies 1.12 apart: every other one solved
  const SpanTables tables(span, f, options.table);
  ASSERT_EQ(tables.tables()[0].nodes(), 8 * options.table.velocities);
  const SpanBalance b = run_balance(span, tables, options);
  EXPECT_GT(b.summary.direct_solves, 0);
  for (const BalancePoint& p : b.points) expect_the_direct_solution(span, p);
}

// Newton's last trials of the polish continue from the damper's last solve at the
// frequency (within 1e-3 in log v) rather than from the frequency's first: the same
// self-consistent states as with every trial from the first (a polish tolerance
// below 1e-7 keeps that), to the polish's tolerance, with two dampers per end.
TEST(SpanBalance, ThePolishsNearTrialsFindTheStatesEveryFirstStartFinds) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "a", nullptr, std::nullopt},
                                {sauter_damper(), 2.2, true, "b", nullptr, std::nullopt}});
  const std::vector<double> f = damper::log_spaced(6.0, 30.0, stockbridge::testing::scaled(24, 4));
  BalanceOptions near = fast_options(), first = fast_options();
  first.polish_tolerance = 5e-8;  // below 1e-7: every trial from the frequency's first solution
  const SpanTables tables(span, f, near.table);
  const SpanBalance a = run_balance(span, tables, near), b = run_balance(span, tables, first);
  ASSERT_EQ(a.summary.converged, static_cast<int>(f.size()));
  ASSERT_EQ(b.summary.converged, static_cast<int>(f.size()));
  for (std::size_t i = 0; i < f.size(); ++i) {
    SCOPED_TRACE(f[i]);
    expect_relative(a.points[i].amplitude, b.points[i].amplitude, 1e-5);
    expect_relative(a.points[i].stress_fymax, b.points[i].stress_fymax, 1e-5);
    for (std::size_t k = 0; k < a.points[i].dampers.size(); ++k) {
      expect_relative(a.points[i].dampers[k].clamp_velocity, b.points[i].dampers[k].clamp_velocity, 1e-5);
    }
  }
}

/// A candidate of examples/design_aster570.toml on the span: the example damper with
/// both arms' mass and cable length set (the inertia keeping the arm's radius of
/// gyration, as the study does), both span ends' dampers at `position`.
Span design_candidate_span(double mass, double cable_length, double position) {
  damper::ArmDescription arm = stockbridge::testing::sauter_arm();
  arm.inertia *= mass / arm.mass;
  arm.mass = mass;
  arm.cable = cable::CableDescription::uniform(cable_length, 40, 2.8, {{20.0, 0.7}});
  return aster_span({{stockbridge::testing::damper_of({arm, arm}), position, true, "candidate", nullptr, std::nullopt}});
}

// A candidate of examples/design_aster570.toml (heavier masses on longer cables, far
// out on the span) whose direct solve at 14.15 Hz finds no steady state with
// half-wave symmetry (the line search stalls); harmonic balance over whole periods
// finds it, and the point converges.
TEST(SpanBalance, ADirectSolveWithoutASymmetricSteadyStateFallsBackToWholePeriods) {
  const Span span = design_candidate_span(1.4206291098962538, 0.2921970480191521, 2.433679807698354);
  const std::vector<double> f{14.148462654115345};
  const BalanceOptions options = fast_options();
  const SpanBalance b = run_balance(span, SpanTables(span, f, options.table), options);
  ASSERT_TRUE(b.points[0].converged()) << brief_report(b.points[0].summary);
  expect_the_direct_solution(span, b.points[0]);
}

// Another candidate of the example design study (lighter masses on long cables,
// near the span's end): at 12.57 Hz the balance's clamp velocity with the damper
// solved directly at a trial v, G(v), is above v from 0.07 to 0.38 m/s, h = log G -
// log v dipping to 0.035 near 0.13 m/s, and meets it only at 0.527 m/s. The secant
// pointed back and forth across the dip until the polish gave up after 60 trials;
// until a bracket is found a step now goes where h points.
TEST(SpanBalance, APolishWhoseSecantPointsAwayFromTheRootStillFindsIt) {
  const Span span = design_candidate_span(0.8737541098962538, 0.2853220480191521, 0.8711798076983541);
  const std::vector<double> f = band_frequencies(span, 100);
  const BalanceOptions options = fast_options();
  const SpanBalance b = run_balance(span, SpanTables(span, f, options.table), options);
  for (const BalancePoint& p : b.points) ASSERT_TRUE(p.converged()) << p.frequency_hz << " Hz: " << brief_report(p.summary);
  const BalancePoint& p = b.points[38];
  ASSERT_NEAR(p.frequency_hz, 12.5745, 1e-4);
  EXPECT_NEAR(p.dampers[0].clamp_velocity, 0.527, 0.001);
  expect_the_direct_solution(span, p);
}

/// The dissertation's damper with every mass and every cable stiffness and slip
/// moment times `scale`: the same motion at the same clamp velocity, Z times `scale`.
damper::Damper scaled_damper(double scale) {
  damper::ArmDescription arm = stockbridge::testing::sauter_arm();
  arm.mass *= scale;
  arm.inertia *= scale;
  arm.cable = cable::CableDescription::uniform(arm.cable.length, 40, 2.8 * scale, {{20.0 * scale, 0.7 * scale}});
  return stockbridge::testing::damper_of({arm, arm}, 0.7 * scale);
}

// The weak-damper form is the travelling waves' limit as |Z| / Z0 -> 0 (MODEL.md
// section 9): the dissertation's damper scaled down (scaled_damper: it still slips
// and dissipates), the two models' amplitudes agree to first order in |Z| / Z0,
// the gap shrinking with it.
TEST(SpanBalance, TheWeakFormIsTheLimitOfTheTravellingWavesForSmallDampers) {
  const std::vector<double> f{8.0, 15.0, 30.0};
  double last_gap = std::numeric_limits<double>::infinity();
  for (const double scale : {0.2, 0.05, 0.0125}) {
    SCOPED_TRACE(scale);
    const Span span = aster_span({{scaled_damper(scale), 1.0, true, "small", nullptr, std::nullopt}});
    BalanceOptions travelling = fast_options(), weak = fast_options();
    weak.damper_model = DamperModel::weak;
    const SpanTables tables(span, f, travelling.table);
    const SpanBalance t = run_balance(span, tables, travelling), w = run_balance(span, tables, weak);
    double gap = 0.0, ratio = 0.0;  // largest relative gap, largest |Z| / Z0
    for (std::size_t i = 0; i < f.size(); ++i) {
      ASSERT_TRUE(t.points[i].converged() && w.points[i].converged())
          << brief_report(t.points[i].summary) << brief_report(w.points[i].summary);
      gap = std::max(gap, std::abs(t.points[i].amplitude - w.points[i].amplitude) / w.points[i].amplitude);
      ratio = std::max(ratio, std::abs(t.points[i].dampers[0].impedance) / wave_impedance(aster570(), aster570_tension));
      EXPECT_EQ(w.points[i].clamp_loop_amplitude, w.points[i].amplitude);
      // The weak form's dampers sit in the string's own standing wave.
      const double k = wavenumber(aster570(), aster570_tension, f[i]);
      EXPECT_NEAR(w.points[i].dampers[0].clamp_velocity,
                  2.0 * std::numbers::pi * f[i] * w.points[i].amplitude * std::abs(std::sin(k * 1.0)),
                  1e-12 * w.points[i].dampers[0].clamp_velocity);
    }
    // Not a damper that does nothing (all-stick: Re Z = 0, both models the undamped span).
    EXPECT_GT(t.points[1].damper_power, 0.01 * t.points[1].wind_power);
    EXPECT_LE(gap, 2.0 * ratio) << "|Z| / Z0 up to " << ratio;
    EXPECT_LT(gap, 0.5 * last_gap);
    last_gap = gap;
  }
}

// Today's one-damper results are those of the per-damper secant polish before all
// dampers' clamp velocities became one system (commit 1de6bc3, the example span,
// 8 frequencies): the same self-consistent state, to 1e-6.
TEST(SpanBalance, OneDamperPerEndIsAsBeforeTheSystemSolve) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f = damper::log_spaced(6.0, 40.0, 8);
  const double amplitude[] = {0.021436744074653284, 0.007034530159752719, 0.002025640277516735, 0.0006025901457516682,
                              0.0006447120287117451, 0.0008462400705875818, 0.0013321856570961707, 0.0010393696066111238};
  const double velocity[] = {0.26066418166042515, 0.16260291809629418, 0.0951933432181172, 0.05074267511458991,
                             0.04040656370408647,  0.11941860780536694, 0.22335968985483443, 0.1656708923132106};
  const SpanBalance b = run_balance(span, SpanTables(span, f, fast_options().table), fast_options());
  for (std::size_t i = 0; i < f.size(); ++i) {
    SCOPED_TRACE(f[i]);
    ASSERT_TRUE(b.points[i].converged()) << brief_report(b.points[i].summary);
    expect_relative(b.points[i].amplitude, amplitude[i], 1e-6);
    expect_relative(b.points[i].dampers[0].clamp_velocity, velocity[i], 1e-6);
  }
}

// A balance run a frequency at a time and finished after a point (the line's race
// leaves an arrangement so): the points kept are the whole balance's first ones, bit
// for bit (each frequency continues from the ones before it, as in the whole
// balance), and the summary is of them alone.
TEST(SpanBalance, StoppedAfterAPointItIsTheWholeBalancesFirstPoints) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f = damper::log_spaced(6.0, 40.0, 8);
  const SpanTables tables(span, f, fast_options().table);
  const SpanBalance whole = run_balance(span, tables, fast_options());
  // The first point whose clamp stress exceeds the third's: where the stop must fall.
  const double threshold = whole.points[2].stress_fymax;
  std::size_t first = 0;
  while (!(whole.points[first].stress_fymax > threshold)) ++first;
  ASSERT_LT(first + 1, f.size()) << "the threshold must stop the balance before its end";
  int asked = 0;
  const BalanceOptions options = fast_options();
  BalanceRun run(span, tables, options);
  while (!run.done()) {
    const BalancePoint& p = run.next();
    ++asked;
    if (p.converged() && p.stress_fymax > threshold) break;
  }
  const SpanBalance stopped = run.finish();
  ASSERT_EQ(stopped.points.size(), first + 1);
  EXPECT_EQ(asked, static_cast<int>(first + 1));
  double largest = 0.0;
  for (std::size_t i = 0; i <= first; ++i) {
    EXPECT_EQ(stopped.points[i].amplitude, whole.points[i].amplitude) << f[i];
    EXPECT_EQ(stopped.points[i].stress_fymax, whole.points[i].stress_fymax) << f[i];
    largest = std::max(largest, whole.points[i].stress_fymax);
  }
  EXPECT_EQ(stopped.summary.points, static_cast<int>(first + 1));
  EXPECT_EQ(stopped.summary.max_stress_fymax, largest);
}

// Below its table's lowest node a damper's Z is held there: where every damper is
// that slow, the ends are linear and the balance (which then takes the powers in
// proportion to the amplitude instead of solving the ends again) is the root of
// P_w - P_s - c Y^2 of the string with those impedances, c from the travelling waves.
TEST(SpanBalance, DampersSlowerThanTheirTablesLowestNodeBalanceAsALinearString) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f = damper::log_spaced(6.0, 40.0, 6);
  BalanceOptions options;
  options.polish = false;
  options.table.velocity_min = 0.5;  // Z held below 0.5 m/s: everywhere in this balance
  options.table.velocity_max = 0.6;
  options.table.velocities = 2;
  const SpanTables tables(span, f, options.table);
  const SpanBalance b = run_balance(span, tables, options);
  const Conductor& c = span.conductor();
  for (std::size_t i = 0; i < f.size(); ++i) {
    SCOPED_TRACE(f[i]);
    ASSERT_TRUE(b.points[i].converged()) << brief_report(b.points[i].summary);
    ASSERT_LT(b.points[i].dampers[0].clamp_velocity, 0.5);
    const double w = 2.0 * std::numbers::pi * f[i];
    const StringWave wave{w, wavenumber(c, span.tension(), f[i]), wave_impedance(c, span.tension())};
    const std::complex<double> z = *tables.tables()[0].at(i, 0.1);
    const double per_square = 2.0 * end_response(wave, {1.0}, {z}, 1.0).absorbed_power;
    const auto net = [&](double y) {
      return span.wind().power(y, f[i], c.diameter, span.length()) -
             span.self_damping().power(y, f[i], c, span.tension(), span.length()) - per_square * y * y;
    };
    const StableRoot linear = smallest_stable_root(net, options.amplitude_min_over_diameter * c.diameter,
                                                   options.amplitude_max_over_diameter * c.diameter, options.root);
    ASSERT_TRUE(linear.converged());
    expect_relative(b.points[i].amplitude, linear.amplitude, 1e-9);
  }
}

// A point that did not converge (here: no balance below the amplitude limit, set
// to 0.2 D, at 10 and 20 Hz, where the span vibrates at 0.85 and 0.34 D) never
// enters a life, a verdict or a largest stress as if it were known.
TEST(SpanBalance, AFailedPointNeverEntersTheLifeOrTheVerdict) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  fatigue.life = LifeModel{{2.0, 4.0}, 0.3};
  const std::vector<double> f{10.0, 20.0, 30.0, 40.0};
  BalanceOptions options;
  options.amplitude_max_over_diameter = 0.2;
  for (const bool exceeded : {true, false}) {
    SCOPED_TRACE(exceeded ? "a converged point exceeds the limit" : "every converged point within it");
    if (!exceeded) {
      fatigue.cycles.reset();
      fatigue.criterion = FatigueCriterion::stress;
      fatigue.endurance_limit = 1e9;
    }
    const Span span(aster570(), 400.0, aster570_tension, WindModel{}, SelfDampingModel{}, {}, fatigue);
    const SpanBalance b = run_balance(span, SpanTables(span, f, options.table), options);
    ASSERT_EQ(b.points[0].summary.termination, Termination::no_root);
    EXPECT_NE(brief_report(b.points[0].summary).find("the wind's power exceeds the dissipation up to Y = 0.00621 m"),
              std::string::npos)
        << brief_report(b.points[0].summary);
    EXPECT_EQ(b.points[1].summary.termination, Termination::no_root);
    EXPECT_TRUE(b.points[2].converged() && b.points[3].converged());
    const BalanceSummary& s = b.summary;
    EXPECT_EQ(s.converged, 2);
    EXPECT_FALSE(s.life.has_value());
    EXPECT_EQ(s.life_missing_points, 2);
    ASSERT_TRUE(s.undamped_life.has_value());  // the undamped balance searches up to 10 D: all four known
    EXPECT_EQ(s.undamped_life_missing_points, 0);
    EXPECT_EQ(s.max_stress_fymax, std::max(b.points[2].stress_fymax, b.points[3].stress_fymax));
    EXPECT_EQ(s.verdict, exceeded ? Verdict::unsafe : Verdict::unknown);
    EXPECT_EQ(s.undamped_verdict, exceeded ? Verdict::unsafe : Verdict::safe);
  }
}

// The life is Miner's sum over the Poffenberger-Swart stresses (the Safe Border
// Line's), not the fymax ones.
TEST(SpanBalance, TheLifeUsesThePoffenbergerSwartStress) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  fatigue.life = LifeModel{{2.0, 4.0}, 0.3};
  const Span span(aster570(), 400.0, aster570_tension, WindModel{}, SelfDampingModel{}, {}, fatigue);
  const std::vector<double> f = damper::log_spaced(6.0, 40.0, 6);
  const SpanBalance b = run_balance(span, SpanTables(span, f, {}), BalanceOptions{});
  std::vector<double> ps, fymax;
  for (const BalancePoint& p : b.points) {
    ps.push_back(p.stress_poffenberger_swart);
    fymax.push_back(p.stress_fymax);
    EXPECT_NE(p.stress_poffenberger_swart, p.stress_fymax);
  }
  const SafeBorderLine line = safe_border_line(4);
  const LifeEstimate by_ps = estimate_life(f, ps, span.wind(), span.conductor().diameter, *fatigue.life, line);
  const LifeEstimate by_fymax = estimate_life(f, fymax, span.wind(), span.conductor().diameter, *fatigue.life, line);
  ASSERT_TRUE(b.summary.life.has_value());
  EXPECT_EQ(b.summary.life->damage_per_year, by_ps.damage_per_year);
  EXPECT_NE(b.summary.life->damage_per_year, by_fymax.damage_per_year);
}

// Several [[damper]] of one file have one impedance: its table is solved once.
TEST(SpanTables, DampersAlikeShareOneTable) {
  const std::vector<double> f{8.0, 12.0};
  const SpanTables one(aster_span({{sauter_damper(), 1.0, true, "a", nullptr, std::nullopt}}), f, {});
  const SpanTables alike(aster_span({{sauter_damper(), 1.0, true, "a", nullptr, std::nullopt}, {sauter_damper(), 2.0, true, "b", nullptr, std::nullopt}}), f, {});
  const SpanTables apart(aster_span({{sauter_damper(), 1.0, true, "a", nullptr, std::nullopt}, {scaled_damper(0.5), 2.0, true, "b", nullptr, std::nullopt}}), f, {});
  ASSERT_EQ(alike.tables().size(), 2u);
  EXPECT_EQ(alike.nodes(), one.nodes());
  EXPECT_EQ(apart.nodes(), 2 * one.nodes());
  for (const double v : {0.01, 0.1, 0.5}) {
    EXPECT_EQ(*alike.tables()[1].at(1, v), *one.tables()[0].at(1, v));
    EXPECT_NEAR(std::abs(*apart.tables()[1].at(1, v)), 0.5 * std::abs(*one.tables()[0].at(1, v)),
                1e-5 * std::abs(*one.tables()[0].at(1, v)));
  }
}

TEST(SpanBalance, ThePositionSearchFindsTheBestOfAFineScan) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f{12.0, 25.0};
  BalanceOptions options = fast_options();
  options.polish = false;  // as the search balances
  const SpanTables tables(span, f, options.table);
  PositionRules rules;
  rules.position_min = 0.3;
  rules.position_max = 3.0;
  rules.scan_points = 21;
  const PositionSearch found = optimise_positions(span, tables, options, rules);
  double best = std::numeric_limits<double>::infinity(), best_at = 0.0;
  for (int k = 0; k <= 270; ++k) {
    const double a = 0.3 + 0.01 * k;
    const double s = run_balance(span.with_dampers_at(a), tables, options).summary.max_stress_fymax;
    if (s < best) best = s, best_at = a;
  }
  EXPECT_LE(found.max_stress_fymax, best * (1.0 + 1e-6)) << "scan's best " << best << " Pa at " << best_at << " m";
  ASSERT_EQ(found.positions.size(), 1u);
  EXPECT_NEAR(found.positions[0], best_at, 0.02);
}

// The search balances an arrangement's frequencies largest stress first and stops it
// where a point shows it above the arrangement it is compared with: the same scan and
// golden sections on whole balances end at the same position, with the same
// objective, and the search balanced fewer points than its balances hold.
TEST(SpanBalance, APositionShownWorseStopsEarlyAndTheSearchEndsWhereWholeBalancesDo) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}});
  BalanceOptions options = fast_options();
  options.polish = false;
  const SpanTables tables(span, band_frequencies(span, 16), options.table);
  PositionRules rules;
  rules.position_min = 0.3;
  rules.position_max = 3.0;
  rules.scan_points = 11;
  const PositionSearch found = optimise_positions(span, tables, options, rules);
  const auto whole = [&](double x) { return position_objective(run_balance(span.with_dampers_at(x), tables, options), rules.objective); };
  // search_one on whole balances.
  const double step = (rules.position_max - rules.position_min) / (rules.scan_points - 1);
  int k_best = 0;
  double f_best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < rules.scan_points; ++k) {
    if (const double f = whole(rules.position_min + k * step); f < f_best) f_best = f, k_best = k;
  }
  double lo = std::max(rules.position_min, rules.position_min + (k_best - 1.0) * step);
  double hi = std::min(rules.position_max, rules.position_min + (k_best + 1.0) * step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo), f1 = whole(x1), f2 = whole(x2);
  double best = std::min(f_best, std::min(f1, f2)), best_at = f1 <= f2 ? x1 : x2;
  if (f_best <= best) best_at = rules.position_min + k_best * step;
  while (hi - lo > 1e-3 * step) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - ratio * (hi - lo), f1 = whole(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + ratio * (hi - lo), f2 = whole(x2);
    }
    for (const auto& [x, f] : {std::pair{x1, f1}, std::pair{x2, f2}}) {
      if (f < best) best = f, best_at = x;
    }
  }
  ASSERT_EQ(found.positions.size(), 1u);
  EXPECT_EQ(found.positions[0], best_at);
  EXPECT_EQ(found.objective, best);
  const int whole_points = found.balances * static_cast<int>(tables.frequencies().size());
  EXPECT_LT(found.points, whole_points * 3 / 4) << found.balances << " balances";
}

// Two dampers per end, each its own position: the search (the usual starts and
// arrangements spread over the range, then COBYLA) comes within 1 % of the best of a
// 0.1 m grid of both positions (some 350 balances against its 100), and keeps the
// spacing.
TEST(SpanBalance, TwoDampersPositionsSearchedTogetherNearlyMatchAGrid) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}, {sauter_damper(), 2.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f = band_frequencies(span, 20);
  BalanceOptions options = fast_options();
  options.polish = false;
  const SpanTables tables(span, f, options.table);
  PositionRules rules;
  rules.position_min = 0.5;
  rules.position_max = 3.5;
  rules.spacing_min = 0.4;
  const PositionSearch found = optimise_positions(span, tables, options, rules);
  ASSERT_EQ(found.positions.size(), 2u);
  EXPECT_GE(found.positions[1] - found.positions[0], rules.spacing_min - 1e-9);
  EXPECT_GE(found.positions[0], rules.position_min - 1e-9);
  EXPECT_LE(found.positions[1], rules.position_max + 1e-9);
  double grid = std::numeric_limits<double>::infinity(), grid_a = 0.0, grid_b = 0.0;
  for (double a = 0.5; a <= 3.5 + 1e-9; a += 0.1) {
    for (double b = a + 0.4; b <= 3.5 + 1e-9; b += 0.1) {
      std::vector<SpanDamper> d = span.dampers();
      d[0].position = a, d[1].position = b;
      const double s = run_balance(span.with_dampers(d), tables, options).summary.max_stress_fymax;
      if (s < grid) grid = s, grid_a = a, grid_b = b;
    }
  }
  EXPECT_LE(found.max_stress_fymax, grid * 1.01) << "found " << found.positions[0] << ", " << found.positions[1]
                                                 << "; the grid's best " << grid_a << ", " << grid_b;
  // Its objective is the stress it reports, over the endurance limit.
  std::vector<SpanDamper> d = span.dampers();
  d[0].position = found.positions[0], d[1].position = found.positions[1];
  const SpanBalance at = run_balance(span.with_dampers(d), tables, options);
  EXPECT_DOUBLE_EQ(found.objective, at.summary.max_stress_fymax / at.summary.endurance_limit);
}

// Each objective is minimised: the position of least damage per year has no more
// damage than the position of least stress, and no less stress (the two differ:
// the life weighs the frequencies by how often the wind blows there).
TEST(SpanBalance, ThePositionSearchMinimisesTheObjectiveItIsGiven) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  fatigue.life = LifeModel{};
  fatigue.life->wind_weibull = {2.0, 4.0};
  fatigue.life->aeolian_fraction = 0.3;
  const Span span(aster570(), 400.0, aster570_tension, WindModel{}, SelfDampingModel{},
                  {{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}}, fatigue);
  BalanceOptions options = fast_options();
  options.polish = false;
  const SpanTables tables(span, band_frequencies(span, 12), options.table);
  PositionRules rules;
  rules.position_max = 4.0;
  rules.scan_points = 21;
  const PositionSearch by_stress = optimise_positions(span, tables, options, rules);
  rules.objective = PositionObjective::life;
  const PositionSearch by_life = optimise_positions(span, tables, options, rules);
  EXPECT_EQ(by_life.criterion, PositionObjective::life);
  const auto balance_at = [&](double x) { return run_balance(span.with_dampers_at(x), tables, options); };
  const SpanBalance at_stress = balance_at(by_stress.positions[0]), at_life = balance_at(by_life.positions[0]);
  ASSERT_TRUE(at_stress.summary.life && at_life.summary.life);
  EXPECT_LE(at_life.summary.life->damage_per_year, at_stress.summary.life->damage_per_year * (1 + 1e-9));
  EXPECT_LE(at_stress.summary.max_stress_fymax, at_life.summary.max_stress_fymax * (1 + 1e-9));
  EXPECT_DOUBLE_EQ(by_life.objective, std::log10(at_life.summary.life->damage_per_year));
}

TEST(SpanBalance, ThePositionSearchStopsWhenAsked) {
  const Span span = aster_span({{sauter_damper(), 1.0, true, "sauter", nullptr, std::nullopt}, {sauter_damper(), 2.0, true, "sauter", nullptr, std::nullopt}});
  const std::vector<double> f{12.0, 25.0};
  BalanceOptions options = fast_options();
  const SpanTables tables(span, f, options.table);
  int asked = 0;
  EXPECT_THROW(optimise_positions(span, tables, options, PositionRules{}, [&] { return ++asked > 7; }), Interrupted);
  EXPECT_EQ(asked, 8);
}

TEST(SpanBalance, ASpanIsCheckedWhereItsFileSpellsIt) {
  const auto error_of = [](auto build) {
    try {
      build();
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(error_of([] { aster_span({{sauter_damper(), 250.0, true, "", nullptr, std::nullopt}}); }).find("damper[0].position = 250"),
            std::string::npos);
  FatigueSpec both;
  both.cycles = 5e8;
  both.endurance_limit = 8e6;
  EXPECT_NE(error_of([&] { Span(aster570(), 400.0, aster570_tension, {}, {}, {}, both); })
                .find("fatigue.endurance_limit: given beside criterion = \"safe-border-line\", which does not use it"),
            std::string::npos);
  FatigueSpec none;
  none.criterion = FatigueCriterion::stress;
  EXPECT_NE(error_of([&] { Span(aster570(), 400.0, aster570_tension, {}, {}, {}, none); })
                .find("fatigue.endurance_limit: missing: criterion \"stress\" takes endurance_limit_mpa"),
            std::string::npos);
  FatigueSpec sbl;
  sbl.cycles = 5e8;
  EXPECT_NE(error_of([&] { Span(aster570(), 400.0, 1e7, {}, {}, {}, sbl); }).find("span.tension"), std::string::npos);
}

}  // namespace
}  // namespace stockbridge::span
