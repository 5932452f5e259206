// The damper stepped one step at a time under a clamp acceleration given step by
// step (the damper on the conductor in time, MODEL.md 16): under a harmonic clamp it
// is NewmarkStepper step for step; its tangent d F / d x_c'' agrees with differences
// and, for elastic arms, with its closed form; bad options are refused.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper_in_time.hpp"
#include "stockbridge/damper/time_integration.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

using testing::damper_of;
using testing::linear_arm;
using testing::sauter_arm;

/// Sauter's arm and a shorter, lighter one: two distinct arms, both slipping at 0.1 m/s.
Damper two_arm_damper() {
  ArmDescription other = sauter_arm();
  other.name = "short";
  other.mass = 0.6;
  other.cable = cable::CableDescription::uniform(0.15, 40, 2.8, {{20.0, 0.7}});
  return damper_of({sauter_arm(), other, sauter_arm()}, 0.7);
}

// Under x_c'' = -W^2 X sin(W t) the damper's force is -m_c x_c'' plus its arms' tip
// forces from NewmarkStepper's period stepping (the third arm moves as the first),
// to 1e-12 of the force's largest value over five periods, step for step.
TEST(DamperInTime, UnderAHarmonicClampItIsThePeriodSteppersArms) {
  const Damper damper = two_arm_damper();
  const Excitation excitation = Excitation::from_velocity(30.0, 0.1);
  TimeDomainOptions options;
  options.steps_per_period = 64;
  const int n = options.steps_per_period;
  const double w = excitation.angular_frequency(), x = excitation.displacement_amplitude;
  const double dt = excitation.period() / n;
  DamperInTime in_time(damper, dt, options);
  in_time.start(0.0);
  std::vector<NewmarkStepper> arms;
  for (const std::size_t k : {0u, 1u}) {
    arms.emplace_back(damper.arms()[k], options);
    arms.back().set_excitation(excitation);
    ASSERT_TRUE(arms.back().place(Eigen::Vector4d::Zero()).converged());
  }
  std::vector<double> expected, got;
  for (int period = 0; period < 5; ++period) {
    std::vector<std::vector<double>> tip(2);
    for (std::size_t k = 0; k < 2; ++k) {
      ArmPeriod record;
      ASSERT_TRUE(arms[k].advance_period(&record).converged());
      for (int j = 1; j <= n; ++j) {  // the tip force after step j: recorded before step j + 1
        tip[k].push_back(j < n ? record.loads(0, j) : arms[k].cantilever().committed().tip_force);
      }
    }
    for (int j = 1; j <= n; ++j) {
      const double clamp = -w * w * x * std::sin(2.0 * std::numbers::pi * j / n);
      const ClampResponse response = in_time.trial(clamp);
      in_time.commit();
      got.push_back(response.force_n);
      expected.push_back(-damper.clamp_mass() * clamp + 2.0 * tip[0][j - 1] + tip[1][j - 1]);
      EXPECT_EQ(in_time.force(), response.force_n);
    }
  }
  double largest = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < got.size(); ++i) largest = std::max(largest, std::abs(expected[i]));
  for (std::size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(got[i] - expected[i]));
  EXPECT_LT(worst, 1e-12 * largest) << worst << " N against " << largest << " N";
  EXPECT_NEAR(in_time.time(), 5.0 * excitation.period(), 1e-12);
  EXPECT_GT(in_time.dissipated(), 0.0);
}

// The tangent the coupled step's Newton iteration takes, d F / d x_c'', against
// central differences of trial() at every step of two periods (the sliders
// sticking and slipping by turns), where the difference does not straddle a kink.
TEST(DamperInTime, ItsTangentIsTheForcesDerivative) {
  const Damper damper = two_arm_damper();
  const Excitation excitation = Excitation::from_velocity(30.0, 0.1);
  const int n = 64;
  DamperInTime in_time(damper, excitation.period() / n, {});
  in_time.start(0.0);
  const double w = excitation.angular_frequency(), x = excitation.displacement_amplitude;
  int compared = 0, agreed = 0;
  for (int j = 1; j <= 2 * n; ++j) {
    const double clamp = -w * w * x * std::sin(2.0 * std::numbers::pi * j / n);
    const double delta = 1e-7 * w * w * x;
    const double up = in_time.trial(clamp + delta).force_n;
    const double down = in_time.trial(clamp - delta).force_n;
    const double tangent = in_time.trial(clamp).force_per_acceleration_kg;
    in_time.commit();
    ++compared;
    if (std::abs((up - down) / (2.0 * delta) / tangent - 1.0) < 1e-5) ++agreed;
  }
  // A kink inside [a - delta, a + delta] is rare: all but a few steps agree.
  EXPECT_GE(agreed, compared - 4) << agreed << " of " << compared;
}

// For elastic arms the tangent has a closed form: -m_c + sum_k (q K (M + q K)^-1 L)_x,
// q = dt^2 / 4, with K the classical beam's tip stiffness and M, L from the arm's m,
// Theta and b (MODEL.md section 4; nothing from damper::Arm). A long step makes the
// cables rigid within it: the whole damper's mass, -M_total.
TEST(DamperInTime, AnElasticDampersTangentIsItsClosedForm) {
  const ArmDescription arm = linear_arm(22.8, false);
  const Damper damper = damper_of({arm, arm}, 0.7);
  for (const double dt : {1e-4, 1e-3}) {
    const double q = 0.25 * dt * dt;
    const Eigen::Matrix2d k = testing::beam_tip_stiffness(22.8, arm.cable.length);
    const Eigen::Vector2d du = q * (testing::arm_mass_matrix(arm) + q * k).inverse() * testing::arm_load_vector(arm);
    const double expected = -0.7 + 2.0 * k.row(0).dot(du);
    DamperInTime in_time(damper, dt, {});
    in_time.start(0.0);
    for (int j = 1; j <= 20; ++j) {
      const ClampResponse response = in_time.trial(50.0 * std::sin(0.3 * j));
      in_time.commit();
      EXPECT_NEAR(response.force_per_acceleration_kg / expected, 1.0, 1e-9) << dt << " s, step " << j;
    }
  }
  DamperInTime long_step(damper, 10.0, {});
  long_step.start(0.0);
  EXPECT_NEAR(long_step.trial(1.0).force_per_acceleration_kg / -damper.total_mass(), 1.0, 1e-5);
}

TEST(DamperInTime, RefusesBadSteps) {
  const Damper damper = two_arm_damper();
  EXPECT_THROW(DamperInTime(damper, 0.0, {}), InvalidParameter);
  TimeDomainOptions options;
  options.max_newton = 0;
  EXPECT_THROW(DamperInTime(damper, 1e-3, options), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::damper
