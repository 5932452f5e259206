// The span's verdict from its points (span/balance_summary.cpp, summarise): the
// stress the criterion judges, a measured sheet's band turning a verdict within the
// limit into uncertain, a point not converged making it unknown. The points are made
// by hand, so every figure is known.

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "aster570.hpp"
#include "span/balance_summary.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/balance.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::span {
namespace {

using testing::aster570;
using testing::aster570_tension;

constexpr double kNoBand = std::numeric_limits<double>::quiet_NaN();
constexpr double kMegapascal = 1e6;

/// ASTER570 at 15 % RTS under `criterion`: a given 10 MPa (stress), or the IEEE's
/// 150 microstrain, 0.5e-6 * 150 * 68 GPa = 5.1 MPa of Poffenberger-Swart stress.
Span summary_span(FatigueCriterion criterion) {
  FatigueSpec fatigue;
  fatigue.criterion = criterion;
  if (criterion == FatigueCriterion::stress) fatigue.endurance_limit = 10.0 * kMegapascal;
  return Span(aster570(), 400.0, aster570_tension, WindModel{}, SelfDampingModel{}, {}, fatigue);
}

/// A point at `f` Hz of fymax stress `fymax` MPa, the top of its sheet's band `high`
/// MPa (NaN: none), its Poffenberger-Swart stress half the fymax one, the undamped
/// stresses three times the damped ones.
BalancePoint made_point(double f, double fymax, double high = kNoBand, bool converged = true) {
  BalancePoint p;
  p.frequency_hz = f;
  p.stress_fymax = fymax * kMegapascal;
  p.stress_poffenberger_swart = 0.5 * fymax * kMegapascal;
  p.stress_fymax_high = high * kMegapascal;
  p.stress_fymax_low = std::isnan(high) ? kNoBand : (2.0 * fymax - high) * kMegapascal;
  p.undamped_stress_fymax = 3.0 * p.stress_fymax;
  p.undamped_stress_poffenberger_swart = 3.0 * p.stress_poffenberger_swart;
  p.summary.termination = converged ? Termination::converged : Termination::no_root;
  return p;
}

/// The points' undamped judged and life stresses as the balance sets them for a span
/// without masses (the criterion's stress at the clamp; the Poffenberger-Swart one).
BalanceSummary summary_of(FatigueCriterion criterion, std::vector<BalancePoint> points) {
  const Span span = summary_span(criterion);
  for (BalancePoint& p : points) {
    p.undamped_judged_stress = span.judges_poffenberger_swart() ? p.undamped_stress_poffenberger_swart : p.undamped_stress_fymax;
    p.undamped_life_stress = p.undamped_stress_poffenberger_swart;
  }
  return summarise(span, points);
}

TEST(BalanceSummary, ABandReachingAboveTheLimitWithTheStressWithinItIsUncertain) {
  const BalanceSummary s = summary_of(FatigueCriterion::stress, {made_point(10.0, 8.0, 9.0), made_point(20.0, 9.0, 11.0)});
  EXPECT_EQ(s.endurance_limit, 10.0 * kMegapascal);
  EXPECT_EQ(s.verdict, Verdict::uncertain);
  EXPECT_EQ(s.max_judged_stress, 9.0 * kMegapascal);
  EXPECT_EQ(s.max_judged_stress_frequency_hz, 20.0);
  EXPECT_EQ(s.max_judged_stress_high, 11.0 * kMegapascal);
  EXPECT_EQ(s.max_stress_fymax, 9.0 * kMegapascal);
  EXPECT_EQ(verdict_name(s.verdict), "uncertain");
  // The undamped balance has no band: 27 MPa, unsafe.
  EXPECT_EQ(s.undamped_max_judged_stress, 27.0 * kMegapascal);
  EXPECT_EQ(s.undamped_verdict, Verdict::unsafe);
}

TEST(BalanceSummary, AStressAboveTheLimitIsUnsafeWhateverTheBand) {
  const BalanceSummary s = summary_of(FatigueCriterion::stress, {made_point(10.0, 8.0, 9.0), made_point(20.0, 11.0, 12.0)});
  EXPECT_EQ(s.verdict, Verdict::unsafe);
  EXPECT_EQ(s.max_judged_stress, 11.0 * kMegapascal);
  EXPECT_EQ(s.max_judged_stress_high, 12.0 * kMegapascal);
}

TEST(BalanceSummary, WithoutABandOrWithinItTheSpanIsSafe) {
  const BalanceSummary none = summary_of(FatigueCriterion::stress, {made_point(10.0, 8.0), made_point(20.0, 9.0)});
  EXPECT_EQ(none.verdict, Verdict::safe);
  EXPECT_TRUE(std::isnan(none.max_judged_stress_high));
  const BalanceSummary within =
      summary_of(FatigueCriterion::stress, {made_point(10.0, 8.0, 9.0), made_point(20.0, 9.0, 9.5)});
  EXPECT_EQ(within.verdict, Verdict::safe);
  EXPECT_EQ(within.max_judged_stress_high, 9.5 * kMegapascal);
}

// A point that did not converge may hide a larger stress: unknown, even where the
// others' band reaches above the limit; its stress never enters the largest.
TEST(BalanceSummary, APointNotConvergedMakesTheVerdictUnknown) {
  const BalanceSummary s = summary_of(
      FatigueCriterion::stress, {made_point(10.0, 8.0, 9.0), made_point(20.0, 12.0, 13.0, false), made_point(30.0, 9.5, 10.5)});
  EXPECT_EQ(s.converged, 2);
  EXPECT_EQ(s.verdict, Verdict::unknown);
  EXPECT_EQ(s.max_judged_stress, 9.5 * kMegapascal);
  EXPECT_EQ(s.max_judged_stress_high, 10.5 * kMegapascal);
}

// Under the microstrain criterion the verdict judges the Poffenberger-Swart stress
// (half the fymax one here) against 5.1 MPa, and its band's top is that stress
// times the fymax band's ratio, high / fymax.
TEST(BalanceSummary, TheMicrostrainCriterionJudgesThePoffenbergerSwartStressAndItsBand) {
  const Span span = summary_span(FatigueCriterion::microstrain);
  EXPECT_DOUBLE_EQ(span.endurance_limit(), 0.5e-6 * 150.0 * 68e9);
  // fymax 8 MPa is above 5.1 MPa, its Poffenberger-Swart 4 MPa and its top 4.5 MPa within.
  const BalanceSummary safe = summary_of(FatigueCriterion::microstrain, {made_point(10.0, 8.0, 9.0)});
  EXPECT_EQ(safe.verdict, Verdict::safe);
  EXPECT_EQ(safe.max_judged_stress, 4.0 * kMegapascal);
  EXPECT_DOUBLE_EQ(safe.max_judged_stress_high, 4.5 * kMegapascal);
  EXPECT_EQ(safe.max_stress_fymax, 8.0 * kMegapascal);
  EXPECT_DOUBLE_EQ(judged_stress_high(span, made_point(10.0, 8.0, 9.0)), 4.5 * kMegapascal);
  // 5 MPa within, its top 5 * 11 / 10 = 5.5 MPa above.
  const BalanceSummary uncertain = summary_of(FatigueCriterion::microstrain, {made_point(10.0, 8.0, 9.0), made_point(20.0, 10.0, 11.0)});
  EXPECT_EQ(uncertain.verdict, Verdict::uncertain);
  EXPECT_DOUBLE_EQ(uncertain.max_judged_stress_high, 5.5 * kMegapascal);
  // The undamped balance judged alike: 3 * 5 = 15 MPa.
  EXPECT_EQ(uncertain.undamped_max_judged_stress, 15.0 * kMegapascal);
}

// A converged point of no vibration (nothing builds up: Y = 0, stress 0) has no band
// of its own; the band's top of the points before it is still the largest, whatever
// order the points come in.
TEST(BalanceSummary, APointOfNoStressDoesNotEraseTheBandsTop) {
  for (const bool zero_last : {true, false}) {
    SCOPED_TRACE(zero_last ? "the point of no stress last" : "first");
    std::vector<BalancePoint> points{made_point(10.0, 8.0, 11.0), made_point(40.0, 0.0, 0.0)};
    if (!zero_last) std::swap(points[0], points[1]);
    const BalanceSummary s = summary_of(FatigueCriterion::stress, points);
    EXPECT_EQ(s.verdict, Verdict::uncertain);
    EXPECT_EQ(s.max_judged_stress_high, 11.0 * kMegapascal);
  }
}

TEST(BalanceSummary, RefreshingASummaryKeepsItsCountersAndTakesTheBand) {
  const Span span = summary_span(FatigueCriterion::stress);
  SpanBalance balance;
  balance.points = {made_point(10.0, 8.0), made_point(20.0, 9.0)};
  balance.summary = summarise(span, balance.points);
  balance.summary.impedance_nodes = 42;
  balance.summary.failed_impedance_nodes = 1;
  balance.summary.direct_solves = 7;
  ASSERT_EQ(balance.summary.verdict, Verdict::safe);
  balance.points[1].stress_fymax_high = 10.5 * kMegapascal;  // as analyse_span sets a sheet's band
  refresh_summary(span, balance);
  EXPECT_EQ(balance.summary.verdict, Verdict::uncertain);
  EXPECT_EQ(balance.summary.impedance_nodes, 42);
  EXPECT_EQ(balance.summary.failed_impedance_nodes, 1);
  EXPECT_EQ(balance.summary.direct_solves, 7);
}

// A caller that takes the points as they are balanced (AnalysisOptions::take_point, as
// the design's candidates do) gets the held analysis' points, in the band's order,
// and the same summary, life included, while the analysis holds none: the example
// span (its climate gives a life) on a band of its own.
TEST(SummaryBuilder, PointsTakenAsTheyComeAreTheHeldOnesAndSoIsTheSummary) {
  const io::SpanFile file = io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml");
  const std::vector<double> f = band_frequencies(file.span, stockbridge::testing::scaled(12, 4));
  AnalysisOptions options;
  options.balance = file.balance;
  const SpanAnalysis held = analyse_span(file.span, f, options);
  std::vector<BalancePoint> taken;
  options.take_point = [&taken](const Span&, BalancePoint&& p) { taken.push_back(std::move(p)); };
  const SpanAnalysis streamed = analyse_span(file.span, f, options);
  EXPECT_TRUE(streamed.balance.points.empty());
  EXPECT_FALSE(streamed.stopped_early());
  ASSERT_EQ(taken.size(), held.balance.points.size());
  for (std::size_t i = 0; i < taken.size(); ++i) {
    const BalancePoint &a = held.balance.points[i], &b = taken[i];
    EXPECT_EQ(b.frequency_hz, a.frequency_hz);
    EXPECT_EQ(b.amplitude, a.amplitude);
    EXPECT_EQ(b.stress_fymax, a.stress_fymax);
    EXPECT_EQ(b.undamped_stress_fymax, a.undamped_stress_fymax);
    ASSERT_EQ(b.dampers.size(), a.dampers.size());
    for (std::size_t d = 0; d < a.dampers.size(); ++d) EXPECT_EQ(b.dampers[d].clamp_velocity, a.dampers[d].clamp_velocity);
  }
  const BalanceSummary &h = held.balance.summary, &s = streamed.balance.summary;
  EXPECT_EQ(s.points, h.points);
  EXPECT_EQ(s.converged, h.converged);
  EXPECT_EQ(s.max_judged_stress, h.max_judged_stress);
  EXPECT_EQ(s.max_judged_stress_frequency_hz, h.max_judged_stress_frequency_hz);
  EXPECT_EQ(s.max_judged_stress_place, h.max_judged_stress_place);
  EXPECT_EQ(s.undamped_max_judged_stress, h.undamped_max_judged_stress);
  EXPECT_EQ(s.verdict, h.verdict);
  ASSERT_TRUE(h.life.has_value());
  ASSERT_TRUE(s.life.has_value());
  EXPECT_EQ(s.life->life_years, h.life->life_years);
  EXPECT_EQ(s.undamped_life->life_years, h.undamped_life->life_years);
  EXPECT_EQ(streamed.warnings, held.warnings);
  // The summary of the points taken, made again from them, is the streamed one.
  EXPECT_EQ(summarise(streamed.span, taken).max_judged_stress, s.max_judged_stress);
}

}  // namespace
}  // namespace stockbridge::span
