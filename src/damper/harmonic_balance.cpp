#include "stockbridge/damper/harmonic_balance.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/linear_solve.hpp"

namespace stockbridge::damper {

void HarmonicBalanceOptions::validate() const {
  require_in_range("harmonics", harmonics, 1, 100);
  if (samples != 0) require_in_range("samples", samples, 2 * harmonics + 1, 1 << 16);
  require_in_range("max_iterations", max_iterations, 1, 10000);
  require_positive("tolerance", tolerance, "");
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
  require_in_range("periods", periods, 1, 1000);
  require_in_range("max_settling_periods", max_settling_periods, 0, 1000000);
  if (!(jacobian_refresh_ratio > 0.0 && jacobian_refresh_ratio <= 1.0)) {
    throw_invalid("jacobian_refresh_ratio", jacobian_refresh_ratio, "a value in (0, 1]");
  }
  cantilever.validate();
}

int HarmonicBalanceOptions::sample_count() const {
  if (collocation) return 2 * harmonics + 1;
  if (samples > 0) return samples;
  int n = 64;
  while (n < 8 * harmonics) n *= 2;
  return n;
}

namespace {
using Strided = Eigen::Map<Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>;
using ConstStrided = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>;

/// Harmonic number of coefficient column c: 0, 1, 1, 2, 2, ...
int harmonic_of(int c) { return (c + 1) / 2; }

/// Sign of det(J) from its LU factors.
int determinant_sign(const Eigen::MatrixXd& jacobian) {
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(jacobian);
  double sign = lu.permutationP().determinant();
  for (Eigen::Index i = 0; i < lu.matrixLU().rows(); ++i) sign *= lu.matrixLU()(i, i) < 0.0 ? -1.0 : 1.0;
  return sign < 0.0 ? -1 : 1;
}
}  // namespace

HarmonicBalance::HarmonicBalance(const Arm& arm, HarmonicBalanceOptions options)
    : arm_(arm),
      options_(validated(options)),
      samples_(options_.sample_count()),
      cable_(arm.cable(), options_.cantilever) {
  const int c_count = 2 * options_.harmonics + 1;
  basis_.resize(samples_, c_count);
  projection_.resize(c_count, samples_);
  for (int j = 0; j < samples_; ++j) {
    const double theta = 2.0 * std::numbers::pi * j / samples_;
    basis_(j, 0) = 1.0;
    projection_(0, j) = 1.0 / samples_;
    for (int k = 1; k <= options_.harmonics; ++k) {
      basis_(j, 2 * k - 1) = std::cos(k * theta);
      basis_(j, 2 * k) = std::sin(k * theta);
      projection_(2 * k - 1, j) = 2.0 * std::cos(k * theta) / samples_;
      projection_(2 * k, j) = 2.0 * std::sin(k * theta) / samples_;
    }
  }
}

double HarmonicBalance::force_scale(const Excitation& excitation) const {
  const double w = excitation.angular_frequency();
  return arm_.description().mass * w * w * excitation.displacement_amplitude;
}

Eigen::VectorXd HarmonicBalance::linear_guess(const Excitation& excitation) const {
  const double w = excitation.angular_frequency();
  const Eigen::Matrix2d dynamic = arm_.stick_stiffness() - w * w * arm_.mass_matrix();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(unknown_count());
  // p(t) = L x_c'' = -W^2 X L sin(W t): the sin(W t) column is c = 2.
  q.segment<2>(4) = dynamic.inverse() * (-w * w * excitation.displacement_amplitude * arm_.load_vector());
  return q;
}

bool HarmonicBalance::residual(const Excitation& excitation, const Eigen::VectorXd& q, int periods, Eigen::VectorXd& r,
                               Eigen::MatrixXd* jacobian, Eigen::VectorXd* d_frequency,
                               PeriodicCableResult* loads_out) {
  const int c_count = 2 * options_.harmonics + 1;
  const int p_count = 2 * c_count;
  const double w = excitation.angular_frequency();
  const double x_amp = excitation.displacement_amplitude;
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  const Eigen::Vector2d& load = arm_.load_vector();
  const Eigen::Map<const Eigen::Matrix2Xd> coefficients(q.data(), 2, c_count);
  const Eigen::Matrix2Xd kinematics = coefficients * basis_.transpose();
  if (!kinematics.allFinite()) {
    if (loads_out) {
      loads_out->converged = false;
      loads_out->failure = "non-finite tip motion (the Fourier coefficients hold NaN or inf)";
    }
    return false;
  }
  if (counting_) {
    ++counting_->evaluations;
    counting_->jacobians += jacobian != nullptr;
  }
  PeriodicCableResult loads =
      cable_.evaluate(kinematics, periods, start_ ? &*start_ : nullptr, jacobian ? &basis_ : nullptr,
                      jacobian ? &sensitivity_ : nullptr);
  if (!loads.converged) {
    if (loads_out) *loads_out = std::move(loads);
    return false;
  }
  // Accelerations' coefficients: -k^2 W^2 per harmonic.
  Eigen::Matrix2Xd acceleration(2, c_count);
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_of(c);
    acceleration.col(c) = -k * k * w * w * coefficients.col(c);
  }
  r.resize(p_count);
  if (!options_.collocation) {
    Eigen::Map<Eigen::Matrix2Xd> residual(r.data(), 2, c_count);
    residual = mass * acceleration + loads.loads * projection_.transpose();
    residual.col(2) -= -w * w * x_amp * load;  // excitation, sin(W t)
    if (jacobian) {
      force_jacobian_.resize(p_count, p_count);
      for (int d = 0; d < 2; ++d) {
        const ConstStrided s(sensitivity_.data() + d, samples_, p_count, Eigen::Stride<Eigen::Dynamic, 2>(2 * samples_, 2));
        Strided(force_jacobian_.data() + d, c_count, p_count, Eigen::Stride<Eigen::Dynamic, 2>(2 * c_count, 2)) =
            projection_ * s;
      }
    }
  } else {
    Eigen::Map<Eigen::Matrix2Xd> residual(r.data(), 2, samples_);
    residual = mass * (acceleration * basis_.transpose()) + loads.loads;
    residual -= (-w * w * x_amp * load) * basis_.col(2).transpose();
    if (jacobian) force_jacobian_ = sensitivity_;
  }
  if (jacobian) {
    force_jacobian_stored_ = true;
    assemble_jacobian(excitation, *jacobian);
  }
  if (d_frequency) {
    // At constant velocity amplitude V = W X: excitation -W V L sin(W t).
    const double v = w * x_amp;
    Eigen::Matrix2Xd d_acceleration(2, c_count);
    for (int c = 0; c < c_count; ++c) {
      const double k = harmonic_of(c);
      d_acceleration.col(c) = -2.0 * k * k * w * coefficients.col(c);
    }
    d_frequency->resize(p_count);
    if (!options_.collocation) {
      Eigen::Map<Eigen::Matrix2Xd> d(d_frequency->data(), 2, c_count);
      d = mass * d_acceleration;
      d.col(2) += v * load;
    } else {
      Eigen::Map<Eigen::Matrix2Xd> d(d_frequency->data(), 2, samples_);
      d = mass * (d_acceleration * basis_.transpose());
      d += (v * load) * basis_.col(2).transpose();
    }
  }
  if (loads_out) *loads_out = std::move(loads);
  return true;
}

void HarmonicBalance::assemble_jacobian(const Excitation& excitation, Eigen::MatrixXd& jacobian) const {
  const int c_count = 2 * options_.harmonics + 1;
  const double w = excitation.angular_frequency();
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  jacobian = force_jacobian_;
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_of(c);
    if (!options_.collocation) {
      jacobian.block<2, 2>(2 * c, 2 * c) += -k * k * w * w * mass;
    } else {
      for (int j = 0; j < samples_; ++j) jacobian.block<2, 2>(2 * j, 2 * c) += -k * k * w * w * basis_(j, c) * mass;
    }
  }
}

ArmPeriod HarmonicBalance::period_of(const Eigen::VectorXd& q, const PeriodicCableResult& loads) const {
  const int c_count = 2 * options_.harmonics + 1;
  const Eigen::Map<const Eigen::Matrix2Xd> coefficients(q.data(), 2, c_count);
  ArmPeriod period;
  period.kinematics = coefficients * basis_.transpose();
  period.loads = loads.loads;
  period.clamp_moment = loads.clamp_moment;
  period.clamp_curvature = loads.clamp_curvature;
  period.clamp_section_moment = loads.clamp_section_moment;
  period.dissipated = loads.dissipated;
  return period;
}

bool HarmonicBalance::newton(const Excitation& excitation, Eigen::VectorXd& q, PeriodicCableResult& loads,
                             SolverSummary& summary) {
  const double scale = force_scale(excitation);
  const int periods = options_.periods;
  Eigen::VectorXd r, r_try, q_try;
  Eigen::MatrixXd jacobian;
  // A stored force Jacobian (from the previous frequency) saves a sensitivity pass.
  bool fresh = !force_jacobian_stored_;
  if (!residual(excitation, q, periods, r, fresh ? &jacobian : nullptr, nullptr, &loads)) {
    summary.message = "at the starting point: " + loads.failure;
    return false;
  }
  start_ = cable_.final_state();
  if (!fresh) assemble_jacobian(excitation, jacobian);
  double norm = r.lpNorm<Eigen::Infinity>() / scale;
  int settling_periods = 0;
  if (!r.allFinite()) {
    summary.message = "non-finite residual at the starting point";
    return false;
  }
  for (int iteration = 0;; ++iteration) {
    summary.residual = norm;
    summary.periodicity_defect = loads.periodicity_defect;
    if (norm <= options_.tolerance && loads.periodicity_defect <= options_.periodicity_tolerance) {
      summary.jacobian_sign = determinant_sign(jacobian);
      if (!fresh && summary.jacobian_sign != last_sign_) {
        // A fold is suspected: confirm the sign with the exact Jacobian.
        residual(excitation, q, periods, r, &jacobian, nullptr, &loads);
        start_ = cable_.final_state();
        summary.jacobian_sign = determinant_sign(jacobian);
      }
      last_sign_ = summary.jacobian_sign;
      return true;
    }
    if (norm <= options_.tolerance) {
      // The equations hold but the cable's memory is still settling: run more periods
      // at the same coefficients rather than Newton steps, which would disturb it again.
      if (settling_periods >= options_.max_settling_periods) {
        summary.message = fmt::format("cable state not periodic after {} more periods at the solution "
                                      "(its state still changes by {:.3g} per period)",
                                      settling_periods, loads.periodicity_defect);
        return false;
      }
      settling_periods += periods;
      --iteration;
      if (!residual(excitation, q, periods, r, nullptr, nullptr, &loads)) {
        summary.message = "while settling: " + loads.failure;
        return false;
      }
      start_ = cable_.final_state();
      norm = r.lpNorm<Eigen::Infinity>() / scale;
      if (norm > options_.tolerance) assemble_jacobian(excitation, jacobian);
      continue;
    }
    if (iteration == options_.max_iterations) {
      summary.message = fmt::format("no convergence in {} Newton iterations (residual {:.3g} of the excitation force)",
                                    iteration, norm);
      return false;
    }
    ++summary.iterations;
    Eigen::VectorXd step;
    const double reciprocal_condition = numerics::solve_checked(jacobian, Eigen::VectorXd(-r), step);
    if (numerics::is_singular(reciprocal_condition, step)) {
      if (!fresh) {
        // The stored Jacobian may belong to another piece: an exact one decides.
        residual(excitation, q, periods, r, &jacobian, nullptr, &loads);
        start_ = cable_.final_state();
        fresh = true;
        norm = r.lpNorm<Eigen::Infinity>() / scale;
        --iteration;
        --summary.iterations;
        continue;
      }
      summary.message = fmt::format("singular Jacobian at Newton iteration {} (reciprocal condition number {:.3g}, "
                                    "residual {:.3g}): no periodic solution is determined here",
                                    iteration + 1, reciprocal_condition, norm);
      return false;
    }
    bool accepted = false;
    double alpha = 1.0;
    const double norm2 = r.norm();
    // With a stored Jacobian only the full step is tried: if it fails, an exact one is cheaper than halving.
    const int halvings = fresh ? 30 : 1;
    for (int halving = 0; halving < halvings && !accepted; ++halving, alpha *= 0.5) {
      q_try = q + alpha * step;
      PeriodicCableResult trial_loads;
      // Accept a decrease, or a step that meets the tolerance.
      if (residual(excitation, q_try, periods, r_try, nullptr, nullptr, &trial_loads) &&
          (r_try.norm() <= (1.0 - 1e-4 * alpha) * norm2 || r_try.lpNorm<Eigen::Infinity>() / scale <= options_.tolerance)) {
        q = q_try;
        r = r_try;
        loads = std::move(trial_loads);
        start_ = cable_.final_state();
        accepted = true;
      }
    }
    if (!accepted && !fresh) {
      // The stored Jacobian belongs to another piece: take an exact one here and try again.
      residual(excitation, q, periods, r, &jacobian, nullptr, &loads);
      start_ = cable_.final_state();
      fresh = true;
      norm = r.lpNorm<Eigen::Infinity>() / scale;
      continue;
    }
    if (!accepted) {
      summary.message = fmt::format("line search failed at Newton iteration {} (residual {:.3g})", iteration + 1, norm);
      return false;
    }
    const double new_norm = r.lpNorm<Eigen::Infinity>() / scale;
    // Slow progress means the Jacobian belongs to another piece: refresh it.
    fresh = new_norm > options_.jacobian_refresh_ratio * norm && new_norm > options_.tolerance;
    if (fresh) {
      residual(excitation, q, periods, r, &jacobian, nullptr, &loads);
      start_ = cable_.final_state();
    } else {
      assemble_jacobian(excitation, jacobian);
    }
    norm = new_norm;
  }
}

ArmSolution HarmonicBalance::solve(const Excitation& excitation, const Eigen::VectorXd& initial,
                                   bool continue_from_last) {
  excitation.validate();
  const auto started = std::chrono::steady_clock::now();
  if (initial.size() != unknown_count()) {
    throw InvalidParameter(fmt::format("initial guess has {} values: expected {}", initial.size(), unknown_count()));
  }
  ArmSolution solution;
  SolverSummary& summary = solution.summary;
  counting_ = &summary;
  start_ = continue_from_last ? last_state_ : std::nullopt;
  if (!continue_from_last) force_jacobian_stored_ = false;
  Eigen::VectorXd q = initial;
  PeriodicCableResult loads;
  summary.converged = newton(excitation, q, loads, summary);
  summary.periods = options_.periods;
  if (summary.converged) {
    last_state_ = start_;
  } else {
    last_state_.reset();
    force_jacobian_stored_ = false;
  }
  if (loads.loads.cols() > 0) {
    solution.period = period_of(q, loads);
    summary.energy_error = energy_error(solution.period, excitation);
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  counting_ = nullptr;
  solution.unknowns = q;
  return solution;
}

// y = (q / scale_q, W / scale_w): the unknowns of the arclength continuation, scaled
// so that a unit step changes the response and the frequency by comparable amounts.
bool HarmonicBalance::correct_on_branch(double velocity, Eigen::VectorXd& y, const Eigen::VectorXd& tangent,
                                        const Eigen::VectorXd& y_pred, const Eigen::VectorXd& scale,
                                        Eigen::MatrixXd& jacobian, Eigen::VectorXd& d_frequency) {
  const Eigen::Index p_count = unknown_count();
  Eigen::VectorXd r, q;
  Eigen::MatrixXd bordered(p_count + 1, p_count + 1);
  Eigen::VectorXd g(p_count + 1);
  PeriodicCableResult loads;
  int settling_periods = 0;
  const int max_iterations = std::min(options_.max_iterations, 25);  // a failed corrector halves the step instead
  for (int iteration = 0; iteration <= max_iterations; ++iteration) {
    q = y.head(p_count).cwiseProduct(scale.head(p_count));
    const double w = y(p_count) * scale(p_count);
    if (!(w > 0.0)) return false;
    const Excitation excitation = Excitation::from_velocity(w / (2.0 * std::numbers::pi), velocity);
    if (!residual(excitation, q, options_.periods, r, &jacobian, &d_frequency, &loads)) return false;
    start_ = cable_.final_state();
    const double force = force_scale(excitation);
    const double constraint = tangent.dot(y - y_pred);
    const double norm = r.lpNorm<Eigen::Infinity>() / force;
    if (norm <= options_.tolerance && std::abs(constraint) <= 1e-10) {
      if (loads.periodicity_defect <= options_.periodicity_tolerance) return true;
      if (settling_periods >= options_.max_settling_periods) return false;
      settling_periods += options_.periods;  // let the cable's memory settle at this point
      continue;
    }
    bordered.topLeftCorner(p_count, p_count) = jacobian * scale.head(p_count).asDiagonal() / force;
    bordered.topRightCorner(p_count, 1) = d_frequency * (scale(p_count) / force);
    bordered.bottomRows(1) = tangent.transpose();
    g.head(p_count) = r / force;
    g(p_count) = constraint;
    Eigen::VectorXd step;
    if (numerics::is_singular(numerics::solve_checked(bordered, Eigen::VectorXd(-g), step), step)) return false;
    y += step;
  }
  return false;
}

std::vector<ArmSolution> HarmonicBalance::continue_along_branch(double velocity, const Eigen::VectorXd& q0, double f0_hz,
                                                                double target_hz, int max_steps) {
  require_positive("velocity", velocity, "m/s");
  const Eigen::Index p_count = unknown_count();
  const double w0 = 2.0 * std::numbers::pi * f0_hz, w_target = 2.0 * std::numbers::pi * target_hz;
  const double direction = w_target > w0 ? 1.0 : -1.0;
  Eigen::VectorXd scale(p_count + 1);
  scale.head(p_count).setConstant(std::max(q0.lpNorm<Eigen::Infinity>(), 1e-12));
  scale(p_count) = std::abs(w_target - w0) > 0.0 ? std::abs(w_target - w0) : w0;
  Eigen::VectorXd y(p_count + 1);
  y.head(p_count) = q0.cwiseQuotient(scale.head(p_count));
  y(p_count) = w0 / scale(p_count);
  start_ = last_state_;
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd d_frequency, r;
  // Tangent at the start: [J, R_W] t = 0, pointing toward the target frequency.
  const Excitation start = Excitation::from_velocity(f0_hz, velocity);
  std::vector<ArmSolution> crossings;
  if (!residual(start, q0, options_.periods, r, &jacobian, &d_frequency, nullptr)) return crossings;
  auto tangent_at = [&](const Eigen::MatrixXd& j, const Eigen::VectorXd& dw) {
    Eigen::VectorXd t(p_count + 1);
    t.head(p_count) = -(j * scale.head(p_count).asDiagonal()).partialPivLu().solve(dw * scale(p_count));
    t(p_count) = 1.0;
    return Eigen::VectorXd(t.normalized());
  };
  Eigen::VectorXd tangent = tangent_at(jacobian, d_frequency);
  if (!tangent.allFinite()) return crossings;
  if (tangent(p_count) * direction < 0.0) tangent = -tangent;
  double ds = 0.25;
  for (int step = 0; step < max_steps && ds > 1e-6; ++step) {
    const Eigen::VectorXd y_pred = y + ds * tangent;
    Eigen::VectorXd y_new = y_pred;
    const std::optional<cable::CableState> before = start_;
    if (!correct_on_branch(velocity, y_new, tangent, y_pred, scale, jacobian, d_frequency)) {
      start_ = before;
      ds *= 0.5;
      continue;
    }
    const double wa = y(p_count) * scale(p_count), wb = y_new(p_count) * scale(p_count);
    if ((wa - w_target) * (wb - w_target) <= 0.0 && wa != w_target) {
      // Polish at exactly the target from the interpolated point.
      const double t = (w_target - wa) / (wb - wa);
      const Eigen::VectorXd q_guess =
          ((1.0 - t) * y.head(p_count) + t * y_new.head(p_count)).cwiseProduct(scale.head(p_count));
      last_state_ = start_;
      const std::optional<cable::CableState> on_branch = start_;
      ArmSolution at_target = solve(Excitation::from_velocity(target_hz, velocity), q_guess, true);
      start_ = on_branch;
      if (at_target.summary.converged) {
        at_target.summary.message = "reached by arclength continuation";
        crossings.push_back(std::move(at_target));
      }
    }
    Eigen::VectorXd new_tangent = tangent_at(jacobian, d_frequency);
    if (!new_tangent.allFinite()) break;
    if (new_tangent.dot(tangent) < 0.0) new_tangent = -new_tangent;
    tangent = new_tangent;
    y = y_new;
    ds = std::min(2.0 * ds, 1.0);
    // Done once the branch has passed the target for good (moving on, beyond it).
    if (!crossings.empty() && direction * (wb - w_target) > 0.0 && direction * tangent(p_count) > 0.0 &&
        direction * (wb - w_target) > 0.5 * std::abs(w_target - w0)) {
      break;
    }
  }
  return crossings;
}

}  // namespace stockbridge::damper
