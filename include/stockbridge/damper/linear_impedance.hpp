#pragma once
// The damper's clamp impedance in a linear limit of its cable law (MODEL.md sections
// 4, 5 and 15): with every Jenkin element sticking (or every one slipping) each arm
// is the linear system of damper/modes.hpp,
//
//     M_k u_k'' + K_k u_k = -g_k x_c'',   g_k = (m_k, -m_k b_k) = -(the arm's load vector),
//
// and the force the clamp takes from the conductor is the rate of the damper's
// momentum, F = M_tot x_c'' + sum_k g_k^T u_k'' (M_tot: the clamp's and every arm's
// mass). At x_c = X e^{jwt}:
//
//     F / (j w X) = Z(w) = j w M_eff(w),
//     M_eff(w) = M_tot + w^2 sum_k g_k^T (K_k - w^2 M_k)^{-1} g_k      (kg).
//
// Nothing dissipates, so Z is purely reactive: the damper on the conductor is a
// frequency-dependent mass. M_eff(0) = M_tot; it has a pole at each arm's clamp-held
// frequency (arm_modes) and a zero at each clamp-free frequency of the whole damper
// (linear_modes: no force on the clamp). In the stick limit it is the impedance the
// nonlinear damper tends to as its amplitude vanishes (every element sticks).

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/damper/modes.hpp"

namespace stockbridge::damper {

class LinearImpedance {
 public:
  LinearImpedance(const Damper& damper, CableLimit limit);

  CableLimit limit() const { return limit_; }
  /// M_tot: the clamp's and every arm's mass, kg (M_eff at 0 Hz).
  double total_mass() const { return total_mass_; }
  /// M_eff(w), kg, at angular frequency w (rad/s, >= 0). Negative above a pole; at a
  /// clamp-held frequency itself (K - w^2 M singular) it is +-inf or NaN.
  double effective_mass(double angular_frequency) const;
  /// Z(w) = j w M_eff(w), N s/m.
  std::complex<double> impedance(double angular_frequency) const;
  /// Every arm's clamp-held angular frequencies (two an arm, rad/s), ascending: the poles.
  const std::vector<double>& held_angular_frequencies() const { return held_; }
  /// How many of them lie below w (the damper's share of the Wittrick-Williams count
  /// of a structure it is attached to: its modes with the clamp held).
  int held_modes_below(double angular_frequency) const;

 private:
  struct ArmBlock {
    Eigen::Matrix2d stiffness;  ///< K_k in the limit
    Eigen::Matrix2d mass;       ///< M_k
    Eigen::Vector2d coupling;   ///< g_k
  };
  CableLimit limit_;
  double total_mass_ = 0.0;
  std::vector<ArmBlock> arms_;
  std::vector<double> held_;
};

}  // namespace stockbridge::damper
