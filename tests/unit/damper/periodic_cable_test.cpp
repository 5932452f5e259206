// The cable driven along a sampled periodic path (periodic_cable.hpp).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "stockbridge/damper/periodic_cable.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::damper {
namespace {

/// 16 samples of a path with a third harmonic (so that its peaks are not symmetric
/// about them), shifted by `phase` samples.
Eigen::Matrix2Xd shifted_path(double phase) {
  constexpr int n = 16;
  Eigen::Matrix2Xd path(2, n);
  for (int j = 0; j < n; ++j) {
    const double t = 2.0 * std::numbers::pi * (j + phase) / n;
    path(0, j) = 4e-3 * (std::sin(t) + 0.2 * std::sin(3.0 * t + 0.5));
    path(1, j) = 0.04 * (std::cos(t + 0.3) - 0.15 * std::sin(3.0 * t));
  }
  return path;
}

/// The largest difference quotient |d loads| / d phase over one sample interval of
/// phase shifts, in `steps` steps.
double largest_difference_quotient(PeriodicCable& cable, int steps) {
  Eigen::Matrix2Xd last;
  double largest = 0.0;
  const double step = 1.0 / steps;
  for (int k = 0; k <= steps; ++k) {
    const PeriodicCableResult r = cable.evaluate(shifted_path(k * step), 2);
    EXPECT_TRUE(r.summary.converged()) << r.summary.where;
    EXPECT_GT(r.period.dissipated, 0.0);  // slipping: the path's extremes set the loads
    if (k > 0) largest = std::max(largest, (r.period.loads - last).cwiseAbs().maxCoeff() / step);
    last = r.period.loads;
  }
  return largest;
}

// The loads are a continuous (piecewise smooth) function of the path, so Newton can
// meet any tolerance: where the path's extreme passes from one sample interval to
// the next, the turning point driven between the samples moves on continuously.
// A jump would show as a difference quotient growing with the refinement (the
// parabola through three samples had one: at an interval's middle its two candidate
// vertices differ, and harmonic balance stalled at a residual of 4e-6 there); a
// continuous function's quotient is bounded by its slope.
TEST(PeriodicCable, LoadsMoveContinuouslyWithThePath) {
  PeriodicCable cable(cable::Cable(cable::CableDescription::uniform(0.1875, 40, 2.8, {{20.0, 0.7}})), {});
  // Measured: 71.6 N with 400 steps and 71.7 N with 40000; the parabola through
  // three samples gave 107 N and 893 N (jumps of about 0.02 N).
  const int coarse = testing::scaled(400, 200);
  const double coarse_quotient = largest_difference_quotient(cable, coarse);
  const double fine_quotient = largest_difference_quotient(cable, 100 * coarse);
  EXPECT_LT(fine_quotient, 1.5 * coarse_quotient);
  std::printf("largest difference quotients: %.4g N (%d steps), %.4g N (%d steps)\n", coarse_quotient, coarse,
              fine_quotient, 100 * coarse);
}

}  // namespace
}  // namespace stockbridge::damper
