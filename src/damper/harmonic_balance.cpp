#include "stockbridge/damper/harmonic_balance.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

void HarmonicBalanceOptions::validate() const {
  require_in_range("harmonics", harmonics, 1, 100);
  if (samples != 0) require_in_range("samples", samples, 2 * harmonics + 1, 1 << 16);
  require_in_range("max_iterations", max_iterations, 1, 10000);
  require_positive("tolerance", tolerance, "");
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
  require_in_range("max_periods", max_periods, 2, 100000);
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

HarmonicBalanceOptions validated(HarmonicBalanceOptions options) {
  options.validate();
  return options;
}

/// Harmonic number of coefficient column c: 0, 1, 1, 2, 2, ...
int harmonic_of(int c) { return (c + 1) / 2; }
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
  PeriodicCableResult loads =
      cable_.evaluate(kinematics, periods, jacobian ? &basis_ : nullptr, jacobian ? &sensitivity_ : nullptr);
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
      jacobian->setZero(p_count, p_count);
      for (int d = 0; d < 2; ++d) {
        const ConstStrided s(sensitivity_.data() + d, samples_, p_count, Eigen::Stride<Eigen::Dynamic, 2>(2 * samples_, 2));
        Strided(jacobian->data() + d, c_count, p_count, Eigen::Stride<Eigen::Dynamic, 2>(2 * c_count, 2)) =
            projection_ * s;
      }
    }
  } else {
    Eigen::Map<Eigen::Matrix2Xd> residual(r.data(), 2, samples_);
    residual = mass * (acceleration * basis_.transpose()) + loads.loads;
    residual -= (-w * w * x_amp * load) * basis_.col(2).transpose();
    if (jacobian) *jacobian = sensitivity_;
  }
  if (jacobian) {
    for (int c = 0; c < c_count; ++c) {
      const double k = harmonic_of(c);
      if (!options_.collocation) {
        jacobian->block<2, 2>(2 * c, 2 * c) += -k * k * w * w * mass;
      } else {
        for (int j = 0; j < samples_; ++j) jacobian->block<2, 2>(2 * j, 2 * c) += -k * k * w * w * basis_(j, c) * mass;
      }
    }
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

bool HarmonicBalance::newton(const Excitation& excitation, int periods, Eigen::VectorXd& q,
                             PeriodicCableResult& loads, SolverSummary& summary) {
  const double scale = force_scale(excitation);
  Eigen::VectorXd r, r_try, q_try;
  Eigen::MatrixXd jacobian;
  if (!residual(excitation, q, periods, r, &jacobian, nullptr, &loads)) {
    summary.message = "at the starting point: " + loads.failure;
    return false;
  }
  double norm = r.lpNorm<Eigen::Infinity>() / scale;
  for (int iteration = 0;; ++iteration) {
    summary.residual = norm;
    if (norm <= options_.tolerance) {
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(jacobian);
      double sign = lu.permutationP().determinant();
      for (Eigen::Index i = 0; i < lu.matrixLU().rows(); ++i) sign *= lu.matrixLU()(i, i) < 0.0 ? -1.0 : 1.0;
      summary.jacobian_sign = sign < 0.0 ? -1 : 1;
      return true;
    }
    if (iteration == options_.max_iterations) {
      summary.message = fmt::format("no convergence in {} Newton iterations (residual {:.3g} of the excitation force)",
                                    iteration, norm);
      return false;
    }
    ++summary.iterations;
    const Eigen::VectorXd step = -jacobian.partialPivLu().solve(r);
    if (!step.allFinite()) {
      summary.message = fmt::format("singular Jacobian at Newton iteration {} (residual {:.3g})", iteration + 1, norm);
      return false;
    }
    bool accepted = false;
    double alpha = 1.0;
    const double norm2 = r.norm();
    for (int halving = 0; halving < 30 && !accepted; ++halving, alpha *= 0.5) {
      q_try = q + alpha * step;
      PeriodicCableResult trial_loads;
      // The full step usually succeeds: evaluate the Jacobian with it; shorter steps without.
      const bool ok = residual(excitation, q_try, periods, r_try, halving == 0 ? &jacobian : nullptr, nullptr, &trial_loads);
      if (ok && r_try.norm() <= (1.0 - 1e-4 * alpha) * norm2) {
        if (halving > 0) residual(excitation, q_try, periods, r_try, &jacobian, nullptr, &trial_loads);
        q = q_try;
        r = r_try;
        loads = std::move(trial_loads);
        accepted = true;
      }
    }
    if (!accepted) {
      summary.message = fmt::format("line search failed at Newton iteration {} (residual {:.3g})", iteration + 1, norm);
      return false;
    }
    norm = r.lpNorm<Eigen::Infinity>() / scale;
  }
}

ArmSolution HarmonicBalance::solve(const Excitation& excitation, const Eigen::VectorXd& initial, int periods) {
  excitation.validate();
  const auto start = std::chrono::steady_clock::now();
  if (initial.size() != unknown_count()) {
    throw InvalidParameter(fmt::format("initial guess has {} values: expected {}", initial.size(), unknown_count()));
  }
  ArmSolution solution;
  SolverSummary& summary = solution.summary;
  Eigen::VectorXd q = initial;
  PeriodicCableResult loads;
  periods = std::clamp(periods, 2, options_.max_periods);
  while (newton(excitation, periods, q, loads, summary)) {
    if (loads.periodicity_defect <= options_.periodicity_tolerance) {
      summary.converged = true;
      break;
    }
    if (periods == options_.max_periods) {
      summary.message = fmt::format("cable state not periodic after {} periods (loads change by {:.3g} per period)",
                                    periods, loads.periodicity_defect);
      break;
    }
    periods = std::min(2 * periods, options_.max_periods);
  }
  summary.periods = periods;
  summary.periodicity_defect = loads.periodicity_defect;
  if (loads.loads.cols() > 0) {
    solution.period = period_of(q, loads);
    summary.energy_error = energy_error(solution.period, excitation);
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  solution.unknowns = q;
  return solution;
}

}  // namespace stockbridge::damper
