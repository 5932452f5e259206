#include "stockbridge/damper/periodic_cable.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

PeriodicCable::PeriodicCable(const cable::Cable& cable, cable::CantileverOptions options)
    : cantilever_(cable, options), sensitivity_(cantilever_.cable().law().load_sensitivity(cantilever_.cable())) {}

PeriodicCableResult PeriodicCable::evaluate(const Eigen::Matrix2Xd& kinematics, int passes,
                                            const cable::CableState* start, const Eigen::MatrixXd* basis,
                                            Eigen::MatrixXd* sensitivity, PathSymmetry symmetry, PeriodicStart mode) {
  require_in_range("passes", passes, 1, 100000);
  const int n_samples = static_cast<int>(kinematics.cols());
  const bool half_wave = symmetry == PathSymmetry::half_wave;
  const bool with_sensitivity = basis && sensitivity;
  const bool newton = mode == PeriodicStart::newton;
  if (with_sensitivity) {
    const Eigen::Index path_columns = 2 * basis->cols();
    const auto coordinates = newton ? static_cast<Eigen::Index>(cable().law().periodic_coordinates(cable())) : 0;
    columns_ = path_columns + coordinates;
    sensitivity_->start(columns_);
    if (coordinates > 0) sensitivity_->seed_coordinates(path_columns);
    sensitivity->resize(2 * n_samples, columns_);
  }
  PeriodicCableResult result;
  SolverSummary& summary = result.summary;
  ArmPeriod& period = result.period;
  period.resize(half_wave ? 2 * n_samples : n_samples);
  find_turning_points(kinematics, half_wave, with_sensitivity ? basis : nullptr);
  if (start) {
    cantilever_.restore(*start);
  } else {
    cantilever_.reset();
  }
  for (int k = 1; k <= passes; ++k) {
    summary.periods = k;
    const double dissipated_before = cantilever_.committed().dissipated;
    if (k == passes) period_start_ = cantilever_.committed();
    if (with_sensitivity) sensitivity_->begin_pass();
    std::size_t next_turn = 0;
    for (int j = 0; j < n_samples; ++j) {
      // The path's turning points before this sample, then the sample.
      for (; next_turn < turning_points_.size() && turning_points_[next_turn].time < j; ++next_turn) {
        const TurningPoint& t = turning_points_[next_turn];
        if (with_sensitivity) {
          rhs_x_ = t.d_x;
          rhs_phi_ = t.d_phi;
        }
        if (!drive_to(t.kinematics, -1, with_sensitivity, sensitivity, summary, k, half_wave)) return result;
      }
      if (with_sensitivity) set_sample_derivative(*basis, j);
      if (!drive_to(kinematics.col(j), j, with_sensitivity, sensitivity, summary, k, half_wave)) return result;
      if (k == passes) period.record_loads(j, cantilever_.trial(), cantilever_.cable());
      cantilever_.commit();
    }
    period.dissipated = cantilever_.committed().dissipated - dissipated_before;
    if (half_wave) mirror(with_sensitivity);
  }
  if (half_wave) {
    period.dissipated *= 2.0;
    period.complete_half_wave();
  }
  period.kinematics.leftCols(n_samples) = kinematics;
  if (half_wave) period.kinematics.rightCols(n_samples) = -kinematics;
  summary.periodicity_defect = state_change(period_start_, cantilever_.committed());
  if (newton && with_sensitivity && columns_ > 2 * basis->cols()) {
    state_derivatives(result.state_jacobian);
    if (half_wave) result.state_jacobian.topRows<2>() *= -1.0;  // the loads' derivatives before the mirror
  }
  if (half_wave && !newton) settle_locked_moments();
  summary.termination = Termination::converged;
  return result;
}

// Under the mirror an element that sticks over the whole half period maps its moment
// H0 to -(H0 + D) (D its change over the half): a two-cycle about the centred moment
// -D / 2, never settling (in whole periods any H0 is steady: friction locks it in).
// Halfway between the last pass's start and its mirrored end is that centre, reached
// in one step, while slipping elements, settled or settling, stay where they were or
// go on settling. The mean of two cable states is one: the moments are statically
// admissible, the curvatures and the tip kinematics linear in them, each slider's
// moment within its bound (under the modified Masing model, whose bound depends on
// |M| / |F|, the next step sets any excess back, as it does for a bound that shrinks).
void PeriodicCable::settle_locked_moments() { cantilever_.commit_halfway_to(period_start_); }

bool PeriodicCable::drive_to(const Eigen::Vector2d& tip, int sample, bool with_sensitivity, Eigen::MatrixXd* sensitivity,
                             SolverSummary& summary, int pass, bool half_wave) {
  const cable::StateDetermination solve = cantilever_.set_trial_tip(tip(0), tip(1));
  summary.newton_iterations = std::max(summary.newton_iterations, solve.newton_iterations);
  if (!solve.converged()) {
    summary.termination = Termination::inner_failure;
    summary.where = fmt::format("cable state determination at {} of {} {}: {}",
                                sample >= 0 ? fmt::format("sample {}", sample) : std::string("a turning point"),
                                half_wave ? "half period" : "period", pass, brief_report(solve));
    return false;
  }
  if (with_sensitivity) propagate_sensitivity(cantilever_.committed(), cantilever_.trial(), sample, sensitivity);
  if (sample < 0) cantilever_.commit();
  return true;
}

void PeriodicCable::mirror(bool with_sensitivity) {
  cantilever_.mirror();
  if (with_sensitivity) sensitivity_->mirror();
}

double PeriodicCable::state_change(const cable::CableState& start, const cable::CableState& end) const {
  double curvature_scale = 0.0, curvature_change = 0.0;
  for (std::size_t i = 0; i < cable().sections(); ++i) {
    curvature_scale = std::max(curvature_scale, std::abs(end.curvature[i]));
    curvature_change = std::max(curvature_change, std::abs(end.curvature[i] - start.curvature[i]));
  }
  return std::max(curvature_scale > 0.0 ? curvature_change / curvature_scale : 0.0,
                  cable().law().internal_change(start, end));
}

void PeriodicCable::state_derivatives(Eigen::MatrixXd& out) {
  sensitivity_->internal_derivatives(internal_derivatives_);
  out.resize(internal_derivatives_.rows() + 2, columns_);
  out.row(0) = d_clamp_moment_.transpose();
  out.row(1) = d_tip_force_.transpose();
  out.bottomRows(internal_derivatives_.rows()) = internal_derivatives_;
}

void PeriodicCable::set_sample_derivative(const Eigen::MatrixXd& basis, int sample) {
  // du/dq for this sample: q(2c + d) scaled by basis(sample, c); zero for the start's coordinates.
  rhs_phi_.setZero(columns_);
  rhs_x_.setZero(columns_);
  for (Eigen::Index c = 0; c < basis.cols(); ++c) {
    rhs_phi_(2 * c + 1) = basis(sample, c);
    rhs_x_(2 * c) = basis(sample, c);
  }
}

void PeriodicCable::propagate_sensitivity(const cable::CableState& from, const cable::CableState& to, int sample,
                                          Eigen::MatrixXd* sensitivity) {
  sensitivity_->step(from, to, rhs_phi_, rhs_x_, d_clamp_moment_, d_tip_force_);
  if (sample < 0) return;
  sensitivity->row(2 * sample) = d_tip_force_.transpose();
  sensitivity->row(2 * sample + 1) = (d_clamp_moment_ - cable().length() * d_tip_force_).transpose();
}

// The path between samples j and j + 1 is the cubic through u_{j-1} .. u_{j+2} with
// the central differences as its slopes at j and j + 1 (Catmull-Rom): one C1 curve
// through every sample, for both coordinates alike. A coordinate turns where the
// cubic's slope, a quadratic in tau (0 < tau < 1), changes sign. A turning point so
// defined moves continuously with the samples (through a sample, where the slope
// there is zero, from one interval into the next), and so does the residual; the
// parabola through three samples had two candidates at each interval's middle,
// whose values differ. There the turning coordinate's value depends on the samples
// through the cubic's weights only (its slope is zero); the other coordinate's also
// through tau*, d tau* / d u_k = -w_k'(tau*) / p''(tau*).
namespace {

struct CubicWeights {
  double value[4], slope[4];  // w_k(tau), w_k'(tau) for u_{j-1}, u_j, u_{j+1}, u_{j+2}
  explicit CubicWeights(double t)
      : value{0.5 * t * (-1.0 + t * (2.0 - t)), 1.0 + t * t * (-2.5 + 1.5 * t), 0.5 * t * (1.0 + t * (4.0 - 3.0 * t)),
              0.5 * t * t * (t - 1.0)},
        slope{0.5 * (-1.0 + t * (4.0 - 3.0 * t)), t * (-5.0 + 4.5 * t), 0.5 * (1.0 + t * (8.0 - 9.0 * t)),
              t * (1.5 * t - 1.0)} {}
};

/// The roots of the cubic's slope c1 + 2 c2 tau + 3 c3 tau^2 strictly inside (0, 1),
/// away from the samples (within 1e-6 of one the turning point is the sample).
int slope_roots(double c1, double c2, double c3, double roots[2]) {
  int count = 0;
  auto keep = [&](double tau) {
    if (tau > 1e-6 && tau < 1.0 - 1e-6) roots[count++] = tau;
  };
  const double a = 3.0 * c3, b = 2.0 * c2;
  if (std::abs(a) <= 1e-12 * (std::abs(b) + std::abs(c1))) {
    if (b != 0.0) keep(-c1 / b);
    return count;
  }
  const double discriminant = b * b - 4.0 * a * c1;
  if (!(discriminant > 0.0)) return 0;
  // The root of larger magnitude first, then the other from the product: no cancellation.
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  const double r1 = q / a, r2 = q != 0.0 ? c1 / q : r1;
  keep(std::min(r1, r2));
  keep(std::max(r1, r2));
  return count;
}

}  // namespace

void PeriodicCable::find_turning_points(const Eigen::Matrix2Xd& kinematics, bool half_wave,
                                        const Eigen::MatrixXd* basis) {
  const int n = static_cast<int>(kinematics.cols());
  const double wrap = half_wave ? -1.0 : 1.0;  // u_{j + n} = wrap u_j
  turning_points_.clear();
  if (n < 3) return;
  // Sample j of the periodic path, j from -1 to n + 1: which column, with which sign.
  struct Wrapped {
    int column;
    double sign;
  };
  auto wrapped = [&](int j) { return j < 0 ? Wrapped{j + n, wrap} : j >= n ? Wrapped{j - n, wrap} : Wrapped{j, 1.0}; };
  auto sample = [&](int j, int d) {
    const Wrapped w = wrapped(j);
    return w.sign * kinematics(d, w.column);
  };
  // A turning point of coordinate d at j + tau, where the cubic's p'' is `curvature`.
  auto add = [&](int j, int d, double tau, double curvature) {
    const CubicWeights w(tau);
    TurningPoint t;
    t.time = j + tau;
    for (int e = 0; e < 2; ++e) {
      t.kinematics(e) = 0.0;
      for (int k = 0; k < 4; ++k) t.kinematics(e) += w.value[k] * sample(j - 1 + k, e);
    }
    if (basis) {
      t.d_x.setZero(columns_);
      t.d_phi.setZero(columns_);
      const int other = 1 - d;
      double other_slope = 0.0;
      for (int k = 0; k < 4; ++k) other_slope += w.slope[k] * sample(j - 1 + k, other);
      Eigen::VectorXd& d_other = other == 0 ? t.d_x : t.d_phi;
      for (int k = 0; k < 4; ++k) {
        const Wrapped at = wrapped(j - 1 + k);
        const double d_tau = -w.slope[k] / curvature;
        for (Eigen::Index c = 0; c < basis->cols(); ++c) {
          const double bk = at.sign * (*basis)(at.column, c);
          t.d_x(2 * c) += w.value[k] * bk;
          t.d_phi(2 * c + 1) += w.value[k] * bk;
          // The other coordinate moves with tau*, which the turning one's samples set.
          d_other(2 * c + d) += other_slope * d_tau * bk;
        }
      }
    }
    turning_points_.push_back(std::move(t));
  };
  for (int j = 0; j < n; ++j) {
    for (int d = 0; d < 2; ++d) {
      const double u[4] = {sample(j - 1, d), sample(j, d), sample(j + 1, d), sample(j + 2, d)};
      // The cubic's slope, 0.5 (c1 + 2 c2 tau + 3 c3 tau^2).
      const double c1 = u[2] - u[0], c2 = 2.0 * u[0] - 5.0 * u[1] + 4.0 * u[2] - u[3],
                   c3 = -u[0] + 3.0 * u[1] - 3.0 * u[2] + u[3];
      double roots[2];
      const int count = slope_roots(c1, c2, c3, roots);
      for (int r = 0; r < count; ++r) add(j, d, roots[r], c2 + 3.0 * c3 * roots[r]);
    }
  }
  // In time order; those past the last sample come before the next pass's first.
  for (TurningPoint& t : turning_points_) {
    if (t.time > n - 1) {
      t.time -= n;
      t.kinematics *= wrap;
      t.d_x *= wrap;
      t.d_phi *= wrap;
    }
  }
  std::sort(turning_points_.begin(), turning_points_.end(),
            [](const TurningPoint& x, const TurningPoint& y) { return x.time < y.time; });
}

}  // namespace stockbridge::damper
