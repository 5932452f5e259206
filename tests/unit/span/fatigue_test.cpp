// Bending stresses on hand-computed numbers, the Poffenberger-Swart stress of the
// clamped beam's shape against the fymax stress (two ways to one number), the
// Safe Border Line's values, its step at the knee, and its inverse.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

TEST(Fatigue, FymaxStressOnHandNumbers) {
  // pi * 3.45 mm * 68 GPa = 7.370265e8 Pa m; sqrt(1.571 / 28.28) = 0.2356938 s/m;
  // times f S = 10 Hz * 10 mm = 0.1 m/s: 17.37106 MPa
  expect_relative(fymax_stress(aster570(), 10.0, 0.01), 17.37106e6, 1e-6);
}

TEST(Fatigue, PoffenbergerSwartFactorOnHandNumbers) {
  // p = 31.35044 1/m, p x_b = 2.790189, exp(-2.790189) - 1 + 2.790189 = 1.851605;
  // K = 68e9 * 0.00345 * 982.85 / (4 * 1.851605) = 3.113210e10 Pa/m
  expect_relative(poffenberger_swart_factor(aster570(), aster570_tension), 3.113210e10, 1e-6);
  expect_relative(poffenberger_swart_stress(aster570(), aster570_tension, 1e-3), 3.113210e7, 1e-6);
}

TEST(Fatigue, PointForceStressOnHandNumbers) {
  // 68e9 * 0.00345 * 100 N / (4 * 31.35044 * 28.28) = 2.346e10 / 3546.362 = 6.615230 MPa
  expect_relative(point_force_stress(aster570(), aster570_tension, 100.0), 6.615230e6, 1e-6);
  EXPECT_EQ(point_force_stress(aster570(), aster570_tension, -100.0),
            point_force_stress(aster570(), aster570_tension, 100.0));
}

TEST(Fatigue, PoffenbergerSwartOfTheClampedBeamAgreesWithFymax) {
  // Both are the outer wire's stress at the clamp: they agree to within (k x_b)^2
  // (0.25 % at 40 Hz), while the string shape alone overstates Y_b by half.
  const Conductor c = aster570();
  for (double f : {10.0, 20.0, 30.0, 40.0}) {
    const double s = 0.005;
    const double y_b = bending_amplitude(c, aster570_tension, f, s);
    const double ps = poffenberger_swart_stress(c, aster570_tension, y_b);
    expect_relative(ps, fymax_stress(c, f, s), 0.003);
    const double string_shape = 2.0 * s * std::sin(wavenumber(c, aster570_tension, f) * poffenberger_swart_distance);
    EXPECT_GT(string_shape / y_b, 1.45) << f << " Hz";
  }
}

TEST(Fatigue, SafeBorderLineValues) {
  const SafeBorderLine one = safe_border_line(1);
  const SafeBorderLine several = safe_border_line(4);
  expect_relative(one.endurance_limit(1e6), 46.05989e6, 1e-6);      // 730 (1e6)^-0.2
  expect_relative(one.endurance_limit(5e8), 14.27722e6, 1e-6);      // 430 (5e8)^-0.17
  expect_relative(several.endurance_limit(1e6), 28.39308e6, 1e-6);  // 450 (1e6)^-0.2
  expect_relative(several.endurance_limit(1e9), 7.761680e6, 1e-6);  // 263 (1e9)^-0.17
  EXPECT_EQ(safe_border_line(2).a_low, several.a_low);
  EXPECT_EQ(invalid_parameter_message([] { safe_border_line(0); }),
            "aluminium_layers = 0: expected an integer from 1 to 1000");
}

TEST(Fatigue, SafeBorderLineStepsDownAtTheKnee) {
  // The published branches do not meet: one layer 730 (2e7)^-0.2 = 25.300 MPa against
  // 430 (2e7)^-0.17 = 24.677 MPa; several layers 16.390 against 15.744 MPa at 1.56e7.
  const SafeBorderLine one = safe_border_line(1);
  expect_relative(one.endurance_limit(2e7), 25.29979e6, 1e-6);
  expect_relative(one.endurance_limit(2e7 * (1 + 1e-12)), 24.67706e6, 1e-6);
  const SafeBorderLine several = safe_border_line(3);
  expect_relative(several.endurance_limit(1.56e7), 16.39033e6, 1e-6);
  expect_relative(several.endurance_limit(1.56e7 * (1 + 1e-12)), 15.74434e6, 1e-6);
  // a stress inside the step fails at the knee
  EXPECT_EQ(one.cycles_to_failure(25.0e6), 2e7);
  EXPECT_EQ(several.cycles_to_failure(16.0e6), 1.56e7);
}

TEST(Fatigue, CyclesToFailureInvertsTheEnduranceLimit) {
  for (int layers : {1, 2}) {
    const SafeBorderLine line = safe_border_line(layers);
    for (double n : {1e4, 1e6, 1e7, line.knee, 3e7, 1e9, 1e12}) {
      expect_relative(line.cycles_to_failure(line.endurance_limit(n)), n, 1e-10);
    }
  }
  const SafeBorderLine one = safe_border_line(1);
  EXPECT_EQ(one.cycles_to_failure(0.0), std::numeric_limits<double>::infinity());
  EXPECT_GT(one.cycles_to_failure(10e6), one.cycles_to_failure(11e6));  // less stress, longer life
}

}  // namespace
}  // namespace stockbridge::span
