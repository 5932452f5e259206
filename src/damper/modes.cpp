#include "stockbridge/damper/modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

namespace {

/// The section tangents of the cable in one limit.
std::vector<double> limit_tangents(const cable::Cable& cable, CableLimit limit) {
  std::vector<double> tangent(cable.sections());
  for (std::size_t i = 0; i < cable.sections(); ++i) {
    tangent[i] = limit == CableLimit::stick ? cable.law().stick_stiffness(i) : cable.law().slip_stiffness(i);
  }
  return tangent;
}

/// Values this close (relative) are equal but for round-off: ties go to the first.
constexpr double kModesTie = 1e-9;

double hz_of_squared_angular(double w2) { return std::sqrt(w2) / (2.0 * std::numbers::pi); }

/// Eigen's verdict on a decomposition of valid data: a failure would be a bug.
void require_modes_success(Eigen::ComputationInfo info, const char* what) {
  if (info != Eigen::Success) throw NumericalError(std::string("modes: the eigenvalue solver failed for ") + what);
}

}  // namespace

std::string_view cable_limit_name(CableLimit limit) { return limit == CableLimit::stick ? "stick" : "slip"; }

Eigen::Matrix2d linear_tip_stiffness(const Arm& arm, CableLimit limit) {
  const cable::Cable& cable = arm.cable();
  const Eigen::Matrix2d k =
      cable::tip_stiffness(cable::tip_flexibility(cable, limit_tangents(cable, limit)), cable.length());
  return 0.5 * (k + k.transpose());  // symmetric up to round-off
}

ArmModes arm_modes(const Arm& arm, CableLimit limit) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(linear_tip_stiffness(arm, limit),
                                                                         arm.mass_matrix());
  require_modes_success(solver.info(), "an arm");
  ArmModes modes;
  for (int i = 0; i < 2; ++i) {
    modes.frequencies_hz(i) = hz_of_squared_angular(solver.eigenvalues()(i));
    Eigen::Vector2d shape = solver.eigenvectors().col(i);  // shape^T M shape = 1
    if (shape(0) < 0.0 || (shape(0) == 0.0 && shape(1) < 0.0)) shape = -shape;
    modes.shapes.col(i) = shape;
  }
  return modes;
}

LimitModes linear_modes(const Damper& damper, CableLimit limit) {
  const std::vector<Arm>& arms = damper.arms();
  const std::size_t n_arms = arms.size();
  const Eigen::Index n = static_cast<Eigen::Index>(2 * n_arms);
  LimitModes out;
  out.limit = limit;
  for (const Arm& arm : arms) out.arms.push_back(arm_modes(arm, limit));

  // Relative coordinates u = (x_1, phi_1, ..., x_K, phi_K): block-diagonal K and M,
  // g the clamp's coupling (m_k, -m_k b_k), total mass m_c + sum m_k.
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd coupling(n);
  double total_mass = damper.clamp_mass();
  for (std::size_t k = 0; k < n_arms; ++k) {
    const Eigen::Index at = static_cast<Eigen::Index>(2 * k);
    stiffness.block<2, 2>(at, at) = linear_tip_stiffness(arms[k], limit);
    mass.block<2, 2>(at, at) = arms[k].mass_matrix();
    coupling.segment<2>(at) = -arms[k].load_vector();
    total_mass += arms[k].description().mass;
  }
  const Eigen::MatrixXd reduced_mass = mass - coupling * coupling.transpose() / total_mass;

  // M_r v = mu K v with K positive definite (M_r is singular for a massless clamp):
  // mu = 1 / w^2 ascending, v^T K v = 1.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(reduced_mass, stiffness);
  require_modes_success(solver.info(), "the damper");
  // A massless clamp: exactly one mu is 0 (w infinite), the first; leave it out.
  const Eigen::Index first = damper.clamp_mass() == 0.0 ? 1 : 0;
  for (Eigen::Index i = n - 1; i >= first; --i) {  // descending mu: ascending frequency
    const double mu = solver.eigenvalues()(i);
    DamperMode mode;
    mode.frequency_hz = hz_of_squared_angular(1.0 / mu);
    Eigen::VectorXd u = solver.eigenvectors().col(i) / std::sqrt(mu);  // u^T M_r u = 1: unit modal mass
    double clamp = -coupling.dot(u) / total_mass;
    // Sign: the largest of |x_c| and the |x_k| positive; of several equal up to
    // round-off (identical arms), the first.
    std::vector<double> translations{clamp};
    for (std::size_t k = 0; k < n_arms; ++k) translations.push_back(u(static_cast<Eigen::Index>(2 * k)));
    double largest = 0.0;
    for (const double t : translations) largest = std::max(largest, std::abs(t));
    const auto leading = std::find_if(translations.begin(), translations.end(),
                                      [&](double t) { return std::abs(t) >= (1.0 - kModesTie) * largest; });
    if (*leading < 0.0) {
      u = -u;
      clamp = -clamp;
    }
    mode.clamp_deflection = clamp;
    mode.clamp_energy_share = damper.clamp_mass() * clamp * clamp;
    double total_energy = mode.clamp_energy_share;
    for (std::size_t k = 0; k < n_arms; ++k) {
      const Eigen::Vector2d arm_u = u.segment<2>(static_cast<Eigen::Index>(2 * k));
      const ArmDescription& d = arms[k].description();
      const double centre = clamp + arm_u(0) - d.offset * arm_u(1);  // y_G
      mode.arms.push_back(arm_u);
      mode.arm_energy_share.push_back(d.mass * centre * centre + d.inertia * arm_u(1) * arm_u(1));
      total_energy += mode.arm_energy_share.back();
    }
    mode.clamp_energy_share /= total_energy;
    for (double& share : mode.arm_energy_share) share /= total_energy;
    const double most = *std::max_element(mode.arm_energy_share.begin(), mode.arm_energy_share.end());
    while (mode.arm_energy_share[mode.dominant_arm] < (1.0 - kModesTie) * most) ++mode.dominant_arm;
    out.damper.push_back(std::move(mode));
  }
  return out;
}

DamperModes damper_modes(const Damper& damper) {
  return {linear_modes(damper, CableLimit::stick), linear_modes(damper, CableLimit::slip)};
}

}  // namespace stockbridge::damper
