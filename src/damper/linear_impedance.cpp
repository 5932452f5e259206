#include "stockbridge/damper/linear_impedance.hpp"

#include <algorithm>
#include <numbers>

namespace stockbridge::damper {

LinearImpedance::LinearImpedance(const Damper& damper, CableLimit limit)
    : limit_(limit), total_mass_(damper.total_mass()) {
  for (const Arm& arm : damper.arms()) {
    arms_.push_back({linear_tip_stiffness(arm, limit), arm.mass_matrix(), -arm.load_vector()});
    const ArmModes modes = arm_modes(arm, limit);
    for (int i = 0; i < 2; ++i) held_.push_back(2.0 * std::numbers::pi * modes.frequencies_hz(i));
  }
  std::sort(held_.begin(), held_.end());
}

double LinearImpedance::effective_mass(double angular_frequency) const {
  const double w2 = angular_frequency * angular_frequency;
  double mass = total_mass_;
  for (const ArmBlock& arm : arms_) {
    const Eigen::Matrix2d dynamic = arm.stiffness - w2 * arm.mass;
    // The 2 x 2 inverse in closed form: g^T adj(D) g / det(D).
    const double det = dynamic(0, 0) * dynamic(1, 1) - dynamic(0, 1) * dynamic(1, 0);
    const Eigen::Vector2d& g = arm.coupling;
    const double adjugate_form =
        dynamic(1, 1) * g(0) * g(0) - 2.0 * dynamic(0, 1) * g(0) * g(1) + dynamic(0, 0) * g(1) * g(1);
    mass += w2 * adjugate_form / det;
  }
  return mass;
}

std::complex<double> LinearImpedance::impedance(double angular_frequency) const {
  return {0.0, angular_frequency * effective_mass(angular_frequency)};
}

int LinearImpedance::held_modes_below(double angular_frequency) const {
  return static_cast<int>(std::lower_bound(held_.begin(), held_.end(), angular_frequency) - held_.begin());
}

}  // namespace stockbridge::damper
