// The undamped span's energy balance: MODEL.md section 9's check numbers for
// ASTER570, and the generic search for the smallest stable root on functions
// whose roots are known.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/undamped.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

TEST(SpanUndamped, Aster570CheckNumbers) {
  // MODEL.md 9: CIGRE wind, Noiseux 1991 with Lilien's k, T = 0.15 RTS: within 0.5 %.
  const WindModel wind;                // cigre
  const SelfDampingModel noiseux;      // noiseux-1991, Lilien's k
  for (const auto& [f, y] : {std::pair{10.0, 26.5e-3}, std::pair{20.0, 10.6e-3}, std::pair{30.0, 3.04e-3},
                             std::pair{40.0, 1.58e-3}}) {
    const std::optional<double> amplitude = undamped_amplitude(wind, noiseux, aster570(), aster570_tension, 400.0, f);
    ASSERT_TRUE(amplitude.has_value()) << f << " Hz";
    expect_relative(*amplitude, y, 0.005);
  }
}

TEST(SpanUndamped, WindAndSelfDampingBalanceAtTheAmplitude) {
  const WindModel wind;
  const SelfDampingModel noiseux;
  const Conductor c = aster570();
  const double y = *undamped_amplitude(wind, noiseux, c, aster570_tension, 400.0, 25.0);
  const double p_w = wind.power(y, 25.0, c.diameter, 400.0);
  expect_relative(noiseux.power(y, 25.0, c, aster570_tension, 400.0), p_w, 1e-9);
  EXPECT_GT(wind.power(0.99 * y, 25.0, c.diameter, 400.0), noiseux.power(0.99 * y, 25.0, c, aster570_tension, 400.0));
  // the span length cancels
  expect_relative(*undamped_amplitude(wind, noiseux, c, aster570_tension, 50.0, 25.0), y, 1e-9);
}

TEST(SpanRootSearch, FindsTheSmallestCrossingFromPositiveToNegative) {
  // + below 1, - from 1 to 2, + from 2 to 3, - beyond: the smallest stable root is 1,
  // the crossing at 3 is stable too but not reached from rest, the one at 2 unstable.
  auto net = [](double y) { return (1.0 - y) * (y - 2.0) * (y - 3.0); };
  const StableRoot root = smallest_stable_root(net, 1e-3, 10.0);
  ASSERT_TRUE(root.converged()) << brief_report(root.summary);
  EXPECT_NEAR(root.amplitude, 1.0, 1e-11);
  EXPECT_LE(root.summary.residual, 1e-12);
  EXPECT_GT(root.summary.evaluations, 120);  // the grid from 1e-3 to 1 at 40 points a decade, then the refinement
  // starting between 1 and 2 (net < 0 there): nothing builds up
  const StableRoot still = smallest_stable_root(net, 1.5, 10.0);
  EXPECT_TRUE(still.converged());
  EXPECT_EQ(still.amplitude, 0.0);
  EXPECT_EQ(still.summary.evaluations, 1);
  // starting between 2 and 3: the next stable crossing
  EXPECT_NEAR(smallest_stable_root(net, 2.2, 10.0).amplitude, 3.0, 1e-11);
}

TEST(SpanRootSearch, ReportsNoBalanceWhenTheNetPowerStaysPositive) {
  const StableRoot positive = smallest_stable_root([](double y) { return 1.0 + y; }, 1e-6, 1.0);
  EXPECT_EQ(positive.summary.termination, Termination::no_root);
  EXPECT_EQ(brief_report(positive.summary), "no root in the range searched up to Y = 1 m");
  const StableRoot nan = smallest_stable_root([](double y) { return y < 0.1 ? 1.0 : NAN; }, 1e-6, 1.0);
  EXPECT_EQ(nan.summary.termination, Termination::non_finite);
  EXPECT_NE(nan.summary.where.find("at Y = 0.1"), std::string::npos) << nan.summary.where;
  // a root exactly on a grid point
  EXPECT_NEAR(smallest_stable_root([](double y) { return 1.0 - y; }, 0.1, 10.0).amplitude, 1.0, 1e-12);
}

TEST(SpanRootSearch, RejectsABadRange) {
  auto net = [](double y) { return 1.0 - y; };
  EXPECT_EQ(invalid_parameter_message([&] { smallest_stable_root(net, 0.0, 1.0); }),
            "y_min = 0: expected a finite value > 0 (m)");
  EXPECT_EQ(invalid_parameter_message([&] { smallest_stable_root(net, 1.0, 0.5); }),
            "y_max = 0.5: expected a finite value > y_min = 1");
  EXPECT_EQ(invalid_parameter_message([&] { smallest_stable_root(net, 0.1, 1.0, RootSearchOptions{0}); }),
            "points_per_decade = 0: expected an integer from 1 to 100000");
}

}  // namespace
}  // namespace stockbridge::span
