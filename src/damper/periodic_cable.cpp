#include "stockbridge/damper/periodic_cable.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

PeriodicCable::PeriodicCable(const cable::Cable& cable, cable::CantileverOptions options)
    : cable_(cable), cantilever_(cable, options) {}

PeriodicCableResult PeriodicCable::evaluate(const Eigen::Matrix2Xd& kinematics, int periods,
                                            const cable::CableState* start, const Eigen::MatrixXd* basis,
                                            Eigen::MatrixXd* sensitivity) {
  require_in_range("periods", periods, 1, 100000);
  const int n_samples = static_cast<int>(kinematics.cols());
  const std::size_t n_sections = cable_.sections();
  const std::size_t m = cable_.elements();
  const bool with_sensitivity = basis && sensitivity;
  if (with_sensitivity) {
    const Eigen::Index p = 2 * basis->cols();
    d_curvature_.setZero(p, static_cast<Eigen::Index>(n_sections));
    d_hysteretic_.resize(p, static_cast<Eigen::Index>(n_sections * m));
    dh_zero_.assign(n_sections * m, 1);  // the columns of d_hysteretic_ are zero where set
    sensitivity->resize(2 * n_samples, p);
  }
  PeriodicCableResult result;
  result.loads.resize(2, n_samples);
  result.clamp_moment.resize(n_samples);
  result.clamp_curvature.resize(n_samples);
  result.clamp_section_moment.resize(n_samples);
  if (start) {
    cantilever_.restore(*start);
  } else {
    cantilever_.reset();
  }
  for (int period = 1; period <= periods; ++period) {
    result.periods = period;
    const double dissipated_before = cantilever_.committed().dissipated;
    if (period == periods) period_start_ = cantilever_.committed();
    for (int j = 0; j < n_samples; ++j) {
      const cable::StateDetermination solve = cantilever_.set_trial_tip(kinematics(0, j), kinematics(1, j));
      result.max_iterations = std::max(result.max_iterations, solve.iterations);
      if (!solve.converged) {
        result.failure = fmt::format("cable state determination did not converge at sample {} of period {} "
                                     "(residual {:.3g} rad after {} iterations)",
                                     j, period, solve.residual, solve.iterations);
        return result;
      }
      const cable::CableState& trial = cantilever_.trial();
      if (with_sensitivity) propagate_sensitivity(cantilever_.committed(), trial, *basis, j, sensitivity);
      result.loads(0, j) = trial.tip_force;
      result.loads(1, j) = trial.tip_moment(cable_.length());
      result.clamp_moment[j] = trial.clamp_moment;
      result.clamp_curvature[j] = trial.curvature[0];
      result.clamp_section_moment[j] = trial.clamp_moment - trial.tip_force * cable_.positions()[0];
      cantilever_.commit();
    }
    result.dissipated = cantilever_.committed().dissipated - dissipated_before;
  }
  result.periodicity_defect = state_change(period_start_, cantilever_.committed());
  result.converged = true;
  return result;
}

double PeriodicCable::state_change(const cable::CableState& start, const cable::CableState& end) const {
  const std::size_t m = cable_.elements();
  double curvature_scale = 0.0, curvature_change = 0.0, moment_change = 0.0;
  for (std::size_t i = 0; i < cable_.sections(); ++i) {
    curvature_scale = std::max(curvature_scale, std::abs(end.curvature[i]));
    curvature_change = std::max(curvature_change, std::abs(end.curvature[i] - start.curvature[i]));
    const auto jenkin = cable_.jenkin(i);
    for (std::size_t e = 0; e < m; ++e) {
      moment_change = std::max(moment_change,
                               std::abs(end.hysteretic[i * m + e] - start.hysteretic[i * m + e]) / jenkin[e].h);
    }
  }
  return std::max(curvature_scale > 0.0 ? curvature_change / curvature_scale : 0.0, moment_change);
}

// On the current piece of the piecewise-linear cable map (sticking sets fixed),
// per section i with tangent k_i = ei + sum_{sticking e} c_e:
//   kappa_new = a_i + M_i / k_i,   a_i = sum_{sticking e} (c_e kappa_old - H_old,e) / k_i (+ slipping terms, constant)
//   M_i = T - F s_i,  and the tip kinematics  u = sum_i w_i [1; l - s_i] kappa_new,i.
// Differentiating: d(T, F) = J^-1 (du - sum_i w_i [1; l - s_i] da_i), J the flexibility;
//   d kappa_new = da_i + dM_i / k_i;  dH_new,e = dH_old,e + c_e (d kappa_new - d kappa_old) if e sticks, else 0.
void PeriodicCable::propagate_sensitivity(const cable::CableState& from, const cable::CableState& to,
                                          const Eigen::MatrixXd& basis, int sample, Eigen::MatrixXd* sensitivity) {
  const std::size_t n_sections = cable_.sections();
  const std::size_t m = cable_.elements();
  const Eigen::Index p = d_curvature_.rows();
  const double l = cable_.length();
  const auto s = cable_.positions();
  const auto w = cable_.weights();
  // du/dq for this sample: q(2c + d) scaled by basis(sample, c).
  rhs_phi_.setZero(p);
  rhs_x_.setZero(p);
  for (Eigen::Index c = 0; c < basis.cols(); ++c) {
    rhs_phi_(2 * c + 1) = basis(sample, c);
    rhs_x_(2 * c) = basis(sample, c);
  }
  Eigen::MatrixXd& dk = d_curvature_;
  Eigen::MatrixXd& dh = d_hysteretic_;
  Eigen::MatrixXd& a_all = a_all_;
  a_all.resize(p, static_cast<Eigen::Index>(n_sections));
  sticking_.resize(n_sections * m);
  has_a_.resize(n_sections);
  dh_zero_.resize(n_sections * m, 1);
  // First pass: a_i and the kinematic right-hand side (the old dk and dH are still
  // needed afterwards, so nothing is overwritten until the loads' derivatives are known).
  // A section where every element slips has a_i = 0 and is skipped.
  for (std::size_t i = 0; i < n_sections; ++i) {
    const double dkappa = to.curvature[i] - from.curvature[i];
    const auto jenkin = cable_.jenkin(i);
    const double k = to.tangent[i];
    const Eigen::Index ci = static_cast<Eigen::Index>(i);
    has_a_[i] = 0;
    for (std::size_t e = 0; e < m; ++e) {
      const bool sticks = !section::jenkin_slips(jenkin[e], from.hysteretic[i * m + e], dkappa);
      sticking_[i * m + e] = sticks;
      if (!sticks) continue;
      auto a = a_all.col(ci);
      if (!has_a_[i]) {
        a = (jenkin[e].c / k) * dk.col(ci);
        has_a_[i] = 1;
      } else {
        a += (jenkin[e].c / k) * dk.col(ci);
      }
      if (!dh_zero_[i * m + e]) a -= (1.0 / k) * dh.col(static_cast<Eigen::Index>(i * m + e));
    }
    if (has_a_[i]) {
      rhs_phi_ -= w[i] * a_all.col(ci);
      rhs_x_ -= (w[i] * (l - s[i])) * a_all.col(ci);
    }
  }
  const Eigen::Matrix2d inverse = to.flexibility.inverse();
  d_clamp_moment_ = inverse(0, 0) * rhs_phi_ + inverse(0, 1) * rhs_x_;
  d_tip_force_ = inverse(1, 0) * rhs_phi_ + inverse(1, 1) * rhs_x_;
  for (std::size_t i = 0; i < n_sections; ++i) {
    const auto jenkin = cable_.jenkin(i);
    const double k = to.tangent[i];
    const Eigen::Index ci = static_cast<Eigen::Index>(i);
    // d kappa_new - d kappa_old, then the new d kappa.
    if (has_a_[i]) {
      a_ = a_all.col(ci) + (1.0 / k) * (d_clamp_moment_ - s[i] * d_tip_force_) - dk.col(ci);
    } else {
      a_ = (1.0 / k) * (d_clamp_moment_ - s[i] * d_tip_force_) - dk.col(ci);
    }
    for (std::size_t e = 0; e < m; ++e) {
      const std::size_t ie = i * m + e;
      auto h = dh.col(static_cast<Eigen::Index>(ie));
      if (!sticking_[ie]) {
        if (!dh_zero_[ie]) h.setZero();
        dh_zero_[ie] = 1;
      } else if (dh_zero_[ie]) {
        h = jenkin[e].c * a_;
        dh_zero_[ie] = 0;
      } else {
        h += jenkin[e].c * a_;
      }
    }
    dk.col(ci) += a_;
  }
  sensitivity->row(2 * sample) = d_tip_force_.transpose();
  sensitivity->row(2 * sample + 1) = (d_clamp_moment_ - l * d_tip_force_).transpose();
}

}  // namespace stockbridge::damper
