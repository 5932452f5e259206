#pragma once
// Dampers and arms used across the damper tests.

#include <complex>
#include <numbers>

#include <Eigen/Dense>

#include "stockbridge/damper/damper.hpp"

namespace stockbridge::testing {

/// One arm of D. Sauter's verification damper (Tables 4.1, 4.2).
inline damper::ArmDescription sauter_arm(int sections = 40) {
  damper::ArmDescription a;
  a.name = "arm";
  a.mass = 0.856;
  a.inertia = 0.001814;
  a.offset = 0.0325;
  a.cable = cable::CableDescription::uniform(0.1875, sections, 2.8, {{20.0, 0.7}});
  return a;
}

/// The same arm with a cable that behaves linearly with bending stiffness `ei`.
inline damper::ArmDescription linear_arm(double ei, bool as_sticking_element) {
  damper::ArmDescription a = sauter_arm();
  a.cable = as_sticking_element ? cable::CableDescription::uniform(0.1875, 40, 2.8, {{ei - 2.8, 1e9}})
                                : cable::CableDescription::uniform(0.1875, 40, ei, {});
  return a;
}

/// A (validated) damper of these arms.
inline damper::Damper damper_of(std::vector<damper::ArmDescription> arms, double clamp_mass = 0.7) {
  damper::DamperDescription d;
  d.clamp_mass = clamp_mass;
  d.arms = std::move(arms);
  return damper::Damper(std::move(d));
}

/// The arm's mass matrix and load vector straight from MODEL.md section 4, from its
/// m, Theta and b (not from damper::Arm): with u = (x, phi),
/// [m, -m b; -m b, Theta + m b^2] u'' + (F, Q) = (-m, m b) x_c''.
inline Eigen::Matrix2d arm_mass_matrix(const damper::ArmDescription& a) {
  const double m = a.mass, b = a.offset;
  Eigen::Matrix2d mass;
  mass << m, -m * b, -m * b, a.inertia + m * b * b;
  return mass;
}

inline Eigen::Vector2d arm_load_vector(const damper::ArmDescription& a) { return {-a.mass, a.mass * a.offset}; }

/// The classical clamped-free beam's tip stiffness K = [[12, -6 l], [-6 l, 4 l^2]] EI / l^3
/// ((F, Q) over (x, phi)).
inline Eigen::Matrix2d beam_tip_stiffness(double ei, double l) {
  Eigen::Matrix2d stiffness;
  stiffness << 12.0 * ei / (l * l * l), -6.0 * ei / (l * l), -6.0 * ei / (l * l), 4.0 * ei / l;
  return stiffness;
}

/// Closed-form impedance of a damper whose arms are linear with the classical beam
/// tip stiffness K = [[12, -6 l], [-6 l, 4 l^2]] EI / l^3 (F, Q over x, phi):
/// Z = i W m_c + sum_k  W^2 (K (K - W^2 M)^-1 L)_0 / (i W), from the phasor
/// x_c = V / (i W), u = (K - W^2 M)^-1 L (-W^2 x_c), F_c = m_c x_c'' - sum F_k.
/// Nothing here comes from the library: M and L from each arm's m, Theta, b.
inline std::complex<double> linear_impedance(const damper::Damper& damper, const std::vector<double>& ei,
                                             double frequency_hz) {
  const damper::DamperDescription& d = damper.description();
  const double w = 2.0 * std::numbers::pi * frequency_hz;
  std::complex<double> z(0.0, w * d.clamp_mass);
  for (std::size_t k = 0; k < d.arms.size(); ++k) {
    const Eigen::Matrix2d stiffness = beam_tip_stiffness(ei[k], d.arms[k].cable.length);
    const Eigen::Vector2d u = (stiffness - w * w * arm_mass_matrix(d.arms[k])).inverse() * arm_load_vector(d.arms[k]);
    const double force_per_acceleration = (stiffness * u)(0);  // F per unit x_c''
    // F_c = m_c x_c'' - F = (m_c - f) (-W^2) x_c, with x_c = V / (i W)
    z += -(-w * w * force_per_acceleration) / std::complex<double>(0.0, w);
  }
  return z;
}

}  // namespace stockbridge::testing
