#pragma once
// Private to the cable laws: the quadrature sums along the cable for one state.

#include <Eigen/Core>

#include "stockbridge/cable/cantilever.hpp"

namespace stockbridge::cable {

/// The tip kinematics phi = int kappa, x = int (l - s) kappa, the flexibility
/// int [1; l-s] (1/k_t) [1, -s], and the dissipation, summed section by section
/// (and the flexibility's change, where the law has one: CableState::flexibility_change).
struct CableSums {
  double rotation = 0.0, deflection = 0.0, dissipated = 0.0;
  Eigen::Matrix2d flexibility = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 2, 3> flexibility_change = Eigen::Matrix<double, 2, 3>::Zero();

  void add(double weight, double s, double length, double curvature, double compliance, double dissipated_per_length) {
    const double arm = length - s;
    rotation += weight * curvature;
    deflection += weight * arm * curvature;
    dissipated += weight * dissipated_per_length;
    const double g = weight * compliance;
    flexibility(0, 0) += g;
    flexibility(0, 1) -= g * s;
    flexibility(1, 0) += g * arm;
    flexibility(1, 1) -= g * arm * s;
  }

  void store(double clamp_moment, double tip_force, const CableState& from, CableState& to) const {
    to.clamp_moment = clamp_moment;
    to.tip_force = tip_force;
    to.rotation = rotation;
    to.deflection = deflection;
    to.flexibility = flexibility;
    to.flexibility_change = flexibility_change;
    to.dissipated = from.dissipated + dissipated;
  }
};

}  // namespace stockbridge::cable
