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

// The design figures of a linear arm (elements that never slip, EI = 22.8) from the
// closed-form steady state: with x_c = X sin(W t), u = (x, phi) = U sin(W t),
// (K - W^2 M) U = -W^2 X L (K the classical beam's tip stiffness, M and L from m,
// Theta, b). The mass's centre of gravity moves by x - b phi relative to the clamp;
// the curvature of a tip-loaded cantilever is linear in s, kappa = k0 + k1 s, with
// x = k0 l^2/2 + k1 l^3/6 and phi = k0 l + k1 l^2/2 (MODEL.md section 3). Both
// peak at t = T/4, a sample of the period (N = 128).
TEST(DamperClosedForm, DesignFiguresOfALinearArm) {
  const ArmDescription arm = linear_arm(22.8, true);
  const Damper damper = damper_of({arm}, 0.7);
  const double l = arm.cable.length, b = arm.offset;
  const double s0 = damper.arms()[0].cable().positions().front();  // the clamp section's integration point
  for (const double f : {3.0, 15.0, 40.0, 90.0}) {
    const Excitation e = Excitation::from_velocity(f, 0.2);
    const DamperSteadyState s = solve_steady_state(damper, e, hb_options());
    ASSERT_TRUE(s.point.converged()) << s.point.failure;
    const double w = e.angular_frequency();
    const Eigen::Vector2d u = (testing::beam_tip_stiffness(22.8, l) - w * w * testing::arm_mass_matrix(arm)).inverse() *
                              testing::arm_load_vector(arm) * (-w * w * e.displacement_amplitude);
    Eigen::Matrix2d curvature_to_tip;  // (x, phi) over (k0, k1)
    curvature_to_tip << l * l / 2.0, l * l * l / 6.0, l, l * l / 2.0;
    const Eigen::Vector2d k = curvature_to_tip.inverse() * u;
    ASSERT_EQ(s.point.arms.size(), 1u);
    const ArmFigures& figures = s.point.arms[0];
    EXPECT_NEAR(figures.mass_amplitude, std::abs(u(0) - b * u(1)), 1e-8 * std::abs(u(0) - b * u(1))) << "f = " << f;
    EXPECT_NEAR(s.point.messenger_curvature_max, std::abs(k(0) + k(1) * s0), 1e-8 * std::abs(k(0))) << "f = " << f;
    EXPECT_EQ(figures.clamp_curvature_amplitude, s.point.messenger_curvature_max);
    EXPECT_LT(std::abs(figures.power), 1e-12 * e.velocity_amplitude() * e.velocity_amplitude() * std::abs(figures.impedance));
  }
}

// Each arm's power is what its own sliders dissipate per period (to the sampled
// energy balance), and the arms' powers add up to the damper's: two different arms
// (those of examples/asymmetric_damper.toml), a clamp mass that takes no power.
TEST(DamperClosedForm, ArmPowersAreTheirSlidersAndAddUpToTheDampers) {
  ArmDescription long_arm = sauter_arm(), short_arm = sauter_arm();
  long_arm.name = "long";
  long_arm.mass = 1.4;
  long_arm.inertia = 0.0035;
  long_arm.offset = 0.04;
  long_arm.cable = cable::CableDescription::uniform(0.22, 40, 2.8, {{20.0, 0.7}});
  short_arm.name = "short";
  short_arm.mass = 0.7;
  short_arm.inertia = 0.0012;
  short_arm.offset = 0.025;
  short_arm.cable = cable::CableDescription::uniform(0.14, 40, 2.8, {{20.0, 0.7}});
  const Damper damper = damper_of({long_arm, short_arm}, 0.6);
  for (const auto& [f, v] : {std::pair{8.0, 0.2}, std::pair{15.0, 0.1}, std::pair{30.0, 0.1}, std::pair{60.0, 0.1}}) {
    const Excitation e = Excitation::from_velocity(f, v);
    const DamperSteadyState s = solve_steady_state(damper, e, hb_options());
    ASSERT_TRUE(s.point.converged()) << s.point.failure;
    ASSERT_EQ(s.point.arms.size(), 2u);
    double sum = 0.0, largest_curvature = 0.0;
    for (std::size_t k = 0; k < 2; ++k) {
      const ArmFigures& arm = s.point.arms[k];
      const double sliders = s.arms[k].period.dissipated / e.period();
      ASSERT_GT(sliders, 0.0) << "f = " << f << ", arm " << k;
      const double apparent = 0.5 * v * v * std::abs(arm.impedance);  // what the energy error is relative to
      EXPECT_NEAR(arm.power, sliders, 1e-3 * apparent) << "f = " << f << ", arm " << k;
      sum += arm.power;
      largest_curvature = std::max(largest_curvature, arm.clamp_curvature_amplitude);
    }
    EXPECT_NEAR(sum, s.point.power, 1e-9 * s.point.power) << "f = " << f;
    EXPECT_NEAR(sum, s.point.dissipated_power, SolverOptions{}.energy_tolerance * s.point.dissipated_power) << "f = " << f;
    EXPECT_EQ(s.point.messenger_curvature_max, largest_curvature);
    // The arms move differently: each has its own figures.
    EXPECT_NE(s.point.arms[0].power, s.point.arms[1].power);
    EXPECT_NE(s.point.arms[0].mass_amplitude, s.point.arms[1].mass_amplitude);
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
