#pragma once
// Linear small-amplitude modes of a damper (MODEL.md sections 3 and 4) in the two
// limits of the cable law: every Jenkin element sticking (section tangent
// ei + sum c_j) and every element slipping (tangent ei: the sliders carry no more
// moment). In each limit the arm is linear:
//
//     M u'' + K u = L x_c'',   u = (x, phi) relative to the clamp,
//     M = [[m, -m b], [-m b, Theta + m b^2]],  L = (-m, m b),
//
// K the cable's tip stiffness d(F, Q)/d(x, phi), the inverse of the flexibility
// int_0^l [1; l-s] (1/k_t(s)) [1, -s] ds taken with the cantilever's own
// Gauss-Legendre points (cable::tip_flexibility), so K is exactly the tangent the
// nonlinear cable model has in that limit, profiles included. For a uniform cable
// K = EI/l^3 [[12, -6 l], [-6 l, 4 l^2]].
//
// * Clamp held (x_c = 0): K u = w^2 M u, two frequencies per arm.
// * Clamp free (the whole damper, no force on the clamp): coordinates
//   (x_c, u_1, ..., u_K); kinetic energy m_c x_c'^2/2 + sum_k [m_k (x_c' + x_k' -
//   b_k phi_k')^2 + Theta_k phi_k'^2]/2, stiffness on the u_k only. The rigid-body
//   translation (0 Hz) is removed exactly: with no stiffness on x_c its equation
//   gives x_c = -(sum_k m_k (x_k - b_k phi_k)) / (m_c + sum_k m_k) for any mode at
//   w > 0, which leaves K u = w^2 M_r u with M_r = M - g g^T / (m_c + sum m_k),
//   g = (m_1, -m_1 b_1, ..., m_K, -m_K b_K). This gives the 2K elastic modes. A
//   massless clamp (m_c = 0) makes M_r singular: one mode is then at infinite
//   frequency (the clamp moving against the arms' cables with no inertia of its
//   own) and is left out, leaving 2K - 1.
//
// Facts the tests check: a clamp far heavier than the arms gives the clamp-held
// frequencies; M_r is M less a rank-one term, so the clamp-free frequencies
// interlace with the clamp-held ones of all arms together (held_i <= free_i <=
// held_{i+1}); two identical arms have antisymmetric modes (u_1 = -u_2) that keep
// the clamp still, at the clamp-held frequencies.

#include <cstddef>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/damper/damper.hpp"

namespace stockbridge::damper {

/// The linear limit of the cable law.
enum class CableLimit {
  stick,  ///< every element sticking: tangent ei + sum c_j
  slip,   ///< every element slipping: tangent ei
};
/// "stick" or "slip" (as the modes command's CSV and JSON name them).
std::string_view cable_limit_name(CableLimit limit);

/// The arm's tip stiffness d(F, Q)/d(x, phi) with every section of its cable in
/// `limit`: [[N/m, N/rad], [N m/m, N m/rad]], symmetric positive definite.
Eigen::Matrix2d linear_tip_stiffness(const Arm& arm, CableLimit limit);

/// One arm with the clamp held.
struct ArmModes {
  Eigen::Vector2d frequencies_hz = Eigen::Vector2d::Zero();  ///< ascending, Hz
  /// Column i: (x, phi) of mode i (m, rad), normalised to unit modal mass
  /// (shape^T M shape = 1) with x >= 0.
  Eigen::Matrix2d shapes = Eigen::Matrix2d::Zero();
};

/// One elastic mode of the whole damper with the clamp free.
struct DamperMode {
  double frequency_hz = 0.0;
  /// The clamp's deflection x_c and each arm's (x, phi) relative to the clamp,
  /// normalised to unit modal mass (the kinetic-energy form above = 1), with the
  /// largest of |x_c| and the |x_k| positive (of several equal up to round-off, the
  /// first: the clamp, then the arms in order).
  double clamp_deflection = 0.0;
  std::vector<Eigen::Vector2d> arms;
  /// Each arm's share of the mode's kinetic energy (m_k y_G,k^2 + Theta_k phi_k^2
  /// over the total); the clamp holds the rest. Shares add up to 1.
  std::vector<double> arm_energy_share;
  double clamp_energy_share = 0.0;
  std::size_t dominant_arm = 0;  ///< the arm with the largest share (of equal ones up to round-off, the first)
};

/// The modes of a damper in one limit.
struct LimitModes {
  CableLimit limit = CableLimit::stick;
  std::vector<ArmModes> arms;      ///< clamp held, one per arm
  std::vector<DamperMode> damper;  ///< clamp free, ascending: 2K modes (2K - 1 with a massless clamp)
};

/// Both limits.
struct DamperModes {
  LimitModes stick;
  LimitModes slip;
};

/// The arm's two clamp-held modes in `limit`.
ArmModes arm_modes(const Arm& arm, CableLimit limit);
/// The damper's modes in `limit`: each arm's with the clamp held and the whole
/// damper's with the clamp free (rigid-body mode left out).
LimitModes linear_modes(const Damper& damper, CableLimit limit);
/// linear_modes in both limits.
DamperModes damper_modes(const Damper& damper);

}  // namespace stockbridge::damper
