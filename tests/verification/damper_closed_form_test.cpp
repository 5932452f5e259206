// Closed-form checks of the damper impedance (MODEL.md sections 4 and 5).

#include <algorithm>
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

using testing::damper_of;
using testing::linear_arm;
using testing::linear_impedance;
using testing::sauter_arm;

SolverOptions hb_options(int samples = 128) {
  SolverOptions options;
  options.harmonic_balance.samples = samples;
  return options;
}

// Rigid arms: Z = i W (m_c + sum m_k).
TEST(DamperClosedForm, RigidArmsAreAPureMass) {
  ArmDescription rigid = sauter_arm();
  rigid.cable = cable::CableDescription::uniform(0.1875, 8, 1e12, {});
  const Damper damper = damper_of({rigid, rigid}, 0.7);
  for (const double f : {2.0, 10.0, 60.0}) {
    const DamperSteadyState s = solve_steady_state(damper, Excitation::from_velocity(f, 0.1), hb_options());
    ASSERT_TRUE(s.point.converged()) << s.point.failure;
    const double w = 2.0 * std::numbers::pi * f;
    EXPECT_NEAR(s.point.impedance.real(), 0.0, 1e-9 * w * (0.7 + 2 * 0.856));
    EXPECT_NEAR(s.point.impedance.imag(), w * (0.7 + 2 * 0.856), 1e-9 * w * (0.7 + 2 * 0.856));
  }
}

// Linear arms (elements that never slip, EI = 22.8; all slipping, ei = 2.8):
// the closed form of the linear 2-DOF arm, and no dissipation.
TEST(DamperClosedForm, LinearArmsMatchTheTwoDegreeOfFreedomClosedForm) {
  for (const auto& [ei, sticking] : {std::pair{22.8, true}, std::pair{2.8, false}}) {
    const Damper damper = damper_of({linear_arm(ei, sticking)}, 0.7);
    for (const double f : {3.0, 15.0, 40.0, 90.0}) {
      const DamperSteadyState s = solve_steady_state(damper, Excitation::from_velocity(f, 0.2), hb_options());
      ASSERT_TRUE(s.point.converged()) << s.point.failure;
      const std::complex<double> expected = linear_impedance(damper, {ei}, f);
      EXPECT_LT(std::abs(s.point.impedance - expected), 1e-9 * std::abs(expected)) << "ei " << ei << ", f = " << f;
      EXPECT_EQ(s.point.dissipated_power, 0.0);
    }
  }
}

// |Z| of the sticking linear arm peaks at the natural frequencies of its mass and
// stiffness matrices (21.17 and 68.21 Hz for EI = 22.8; MODEL.md rounds to 21.3, 68.5).
TEST(DamperClosedForm, ImpedancePeaksAtTheNaturalFrequencies) {
  const Damper damper = damper_of({linear_arm(22.8, true)}, 0.0);
  const Eigen::Vector2d natural = damper.arms()[0].natural_frequencies(22.8);
  EXPECT_NEAR(natural(0), 21.17, 0.01);
  EXPECT_NEAR(natural(1), 68.21, 0.01);
  for (int mode = 0; mode < 2; ++mode) {
    SweepSpec spec;
    spec.frequencies = log_spaced(0.9 * natural(mode), 1.1 * natural(mode), 41);
    spec.amplitudes = {0.01};
    spec.solver = hb_options(64);
    const SweepRun run = run_sweep(damper, spec).front();
    const auto peak = std::max_element(run.points.begin(), run.points.end(), [](const auto& a, const auto& b) {
      return std::abs(a.impedance) < std::abs(b.impedance);
    });
    ASSERT_TRUE(peak->converged());
    const double spacing = spec.frequencies[1] / spec.frequencies[0];
    EXPECT_LT(std::abs(std::log(peak->frequency_hz / natural(mode))), std::log(spacing)) << "mode " << mode;
  }
}

// Energy: P = V^2 Re(Z) / 2 equals the sliders' dissipation per period / T. The
// two differ by the sampling of the period (second order): 1e-6 at 4096 samples.
TEST(DamperClosedForm, PowerFromImpedanceEqualsSliderDissipation) {
  const Damper damper = damper_of({sauter_arm()});
  for (const auto& [f, v] : {std::pair{12.0, 0.2}, std::pair{16.0, 0.05}, std::pair{50.0, 0.2}}) {
    std::vector<double> errors;
    for (const int samples : {256, 1024, 4096}) {
      const DamperSteadyState s = solve_steady_state(damper, Excitation::from_velocity(f, v), hb_options(samples));
      ASSERT_TRUE(s.point.converged()) << s.point.failure;
      ASSERT_GT(s.point.dissipated_power, 0.0);
      errors.push_back(std::abs(s.point.power - s.point.dissipated_power) / s.point.dissipated_power);
    }
    EXPECT_LT(errors.back(), 1e-6) << "f = " << f;
    EXPECT_LT(errors[1], errors[0]) << "f = " << f;
    EXPECT_LT(errors[2], errors[1]) << "f = " << f;
  }
}

// Two identical arms give twice one arm plus i W m_c.
TEST(DamperClosedForm, TwoIdenticalArmsAreTwiceOneArm) {
  const Damper one = damper_of({sauter_arm()}, 0.0);
  ArmDescription renamed = sauter_arm();
  renamed.name = "other";
  const Damper two = damper_of({sauter_arm(), renamed}, 0.7);
  EXPECT_EQ(two.representative(), (std::vector<std::size_t>{0, 0}));
  // A twin that differs by 1e-12 in mass is solved on its own: the physics, not the sharing.
  ArmDescription twin = sauter_arm();
  twin.mass *= 1.0 + 1e-12;
  const Damper separate = damper_of({sauter_arm(), twin}, 0.7);
  EXPECT_EQ(separate.representative(), (std::vector<std::size_t>{0, 1}));
  for (const double f : {9.0, 25.0}) {
    const Excitation e = Excitation::from_velocity(f, 0.2);
    const std::complex<double> z1 = solve_steady_state(one, e, hb_options()).point.impedance;
    const std::complex<double> expected = 2.0 * z1 + std::complex<double>(0.0, e.angular_frequency() * 0.7);
    EXPECT_LT(std::abs(solve_steady_state(two, e, hb_options()).point.impedance - expected), 1e-12 * std::abs(expected));
    EXPECT_LT(std::abs(solve_steady_state(separate, e, hb_options()).point.impedance - expected), 1e-8 * std::abs(expected));
  }
}

}  // namespace
}  // namespace stockbridge::damper
