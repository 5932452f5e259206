#include "stockbridge/damper/harmonic_balance.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/LU>
#include <fmt/format.h>

#include "harmonic_balance_newton.hpp"
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
  if (!(settle_ratio >= 0.0 && std::isfinite(settle_ratio))) throw_invalid("settle_ratio", settle_ratio, "a value >= 0");
  require_in_range("stored_jacobian_points", stored_jacobian_points, 0, 1000000);
  cantilever.validate();
}

bool HarmonicBalanceOptions::uses_half_wave() const { return half_wave && !collocation && sample_count() % 2 == 0; }

int HarmonicBalanceOptions::sample_count() const {
  if (collocation) return 2 * harmonics + 1;
  if (samples > 0) return samples;
  // No FFT: any even count serves (half-wave symmetry halves it); multiples of 16 keep
  // the half period's samples a multiple of 8.
  return std::max(64, (8 * harmonics + 15) / 16 * 16);
}

namespace {
using Strided = Eigen::Map<Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>;
using ConstStrided = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>;

}  // namespace

HarmonicBalance::HarmonicBalance(Arm arm, HarmonicBalanceOptions options)
    : arm_(std::move(arm)),
      options_(validated(options)),
      samples_(options_.sample_count()),
      symmetry_(options_.uses_half_wave() ? PathSymmetry::half_wave : PathSymmetry::none),
      driven_samples_(symmetry_ == PathSymmetry::half_wave ? samples_ / 2 : samples_) {
  const bool odd_only = symmetry_ == PathSymmetry::half_wave;
  if (!odd_only) harmonic_.push_back(0);
  for (int k = 1; k <= options_.harmonics; k += odd_only ? 2 : 1) harmonic_.insert(harmonic_.end(), {k, k});
  excitation_column_ = odd_only ? 1 : 2;
  periodic_newton_ = options_.periodic_newton && arm_.cable().law().periodic_coordinates(arm_.cable()) > 0;
  const auto c_count = static_cast<Eigen::Index>(harmonic_.size());
  basis_.resize(driven_samples_, c_count);
  projection_.resize(c_count, driven_samples_);
  // Over half a period the odd harmonics' sums are half the whole period's.
  const double weight = (odd_only ? 2.0 : 1.0) / samples_;
  const int first_cosine = odd_only ? 0 : 1;  // then sine, cosine, sine, ...
  for (int j = 0; j < driven_samples_; ++j) {
    const double theta = 2.0 * std::numbers::pi * j / samples_;
    for (Eigen::Index c = 0; c < c_count; ++c) {
      const int k = harmonic_[static_cast<std::size_t>(c)];
      const bool sine = k > 0 && (c - first_cosine) % 2 == 1;
      basis_(j, c) = k == 0 ? 1.0 : sine ? std::sin(k * theta) : std::cos(k * theta);
      projection_(c, j) = (k == 0 ? 1.0 : 2.0) * weight * basis_(j, c);
    }
  }
}

HarmonicBalanceWorkspace HarmonicBalance::make_workspace() const {
  return HarmonicBalanceWorkspace{PeriodicCable(arm_.cable(), options_.cantilever), Eigen::MatrixXd()};
}

double HarmonicBalance::force_scale(const Excitation& excitation) const {
  const double w = excitation.angular_frequency();
  return arm_.description().mass * w * w * excitation.displacement_amplitude;
}

Eigen::VectorXd HarmonicBalance::linear_guess(const Excitation& excitation) const {
  const double w = excitation.angular_frequency();
  const Eigen::Matrix2d dynamic = arm_.stick_stiffness() - w * w * arm_.mass_matrix();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(unknown_count());
  // p(t) = L x_c'' = -W^2 X L sin(W t).
  q.segment<2>(2 * excitation_column_) = dynamic.inverse() * (-w * w * excitation.displacement_amplitude * arm_.load_vector());
  return q;
}

Eigen::VectorXd HarmonicBalance::whole_period_unknowns(const Eigen::VectorXd& q) const {
  if (symmetry_ != PathSymmetry::half_wave) return q;
  Eigen::VectorXd whole = Eigen::VectorXd::Zero(2 * (1 + 2 * static_cast<Eigen::Index>(options_.harmonics)));
  for (std::size_t c = 0; c < harmonic_.size(); ++c) {
    // Whole periods' columns: the mean, then cos k, sin k for k = 1, 2, ...; here cos k, sin k for odd k.
    const Eigen::Index column = 2 * harmonic_[c] - 1 + static_cast<Eigen::Index>(c % 2);
    whole.segment<2>(2 * column) = q.segment<2>(2 * static_cast<Eigen::Index>(c));
  }
  return whole;
}

Eigen::VectorXd HarmonicBalance::residual_change(const Excitation& from, const Excitation& to,
                                                 const Eigen::VectorXd& q) const {
  const int c_count = static_cast<int>(harmonic_.size());
  const double w0 = from.angular_frequency(), w1 = to.angular_frequency();
  const Eigen::Map<const Eigen::Matrix2Xd> coefficients(q.data(), 2, c_count);
  Eigen::Matrix2Xd d_inertia(2, c_count);  // of M u'': -k^2 W^2 M per harmonic
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_[static_cast<std::size_t>(c)];
    d_inertia.col(c) = -k * k * (w1 * w1 - w0 * w0) * (arm_.mass_matrix() * coefficients.col(c));
  }
  // R holds +W^2 X L sin(W t).
  const Eigen::Vector2d d_excitation =
      (w1 * w1 * to.displacement_amplitude - w0 * w0 * from.displacement_amplitude) * arm_.load_vector();
  Eigen::VectorXd d(unknown_count());
  if (!options_.collocation) {
    Eigen::Map<Eigen::Matrix2Xd> change(d.data(), 2, c_count);
    change = d_inertia;
    change.col(excitation_column_) += d_excitation;
  } else {
    Eigen::Map<Eigen::Matrix2Xd> change(d.data(), 2, samples_);
    change = d_inertia * basis_.transpose() + d_excitation * basis_.col(excitation_column_).transpose();
  }
  return d;
}

HarmonicBalanceEvaluation HarmonicBalance::evaluate(const Excitation& excitation, const Eigen::VectorXd& q,
                                                    const cable::CableState* start, int periods, unsigned derivatives,
                                                    HarmonicBalanceWorkspace& workspace, PeriodicStart mode) const {
  assert(q.size() == unknown_count());
  const int c_count = static_cast<int>(harmonic_.size());
  const int p_count = 2 * c_count;
  const bool with_jacobian = (derivatives & kJacobian) != 0;
  const double w = excitation.angular_frequency();
  const double x_amp = excitation.displacement_amplitude;
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  const Eigen::Vector2d& load = arm_.load_vector();
  const Eigen::Map<const Eigen::Matrix2Xd> coefficients(q.data(), 2, c_count);
  HarmonicBalanceEvaluation out;
  const Eigen::Matrix2Xd kinematics = coefficients * basis_.transpose();
  if (!kinematics.allFinite()) {
    out.cable.termination = Termination::non_finite;
    out.cable.where = "in the tip motion (the Fourier coefficients hold NaN or inf)";
    return out;
  }
  PeriodicCableResult loads =
      workspace.cable.evaluate(kinematics, periods, start, with_jacobian ? &basis_ : nullptr,
                               with_jacobian ? &workspace.sensitivity : nullptr, symmetry_, mode);
  out.cable = std::move(loads.summary);
  out.period = std::move(loads.period);
  if (!out.ok()) return out;
  out.end_state = workspace.cable.final_state();
  if (mode == PeriodicStart::newton) {
    const cable::CableLaw& law = arm_.cable().law();
    Eigen::VectorXd z_start;
    law.coordinates(start ? *start : cable::CableState::virgin(arm_.cable()), z_start);
    law.coordinates(out.end_state, out.state_gap);
    out.state_gap -= z_start;
    out.state_jacobian = std::move(loads.state_jacobian);
  }
  const Eigen::Index columns = with_jacobian ? workspace.sensitivity.cols() : 0;  // q's, then z0's
  // Accelerations' coefficients: -k^2 W^2 per harmonic.
  Eigen::Matrix2Xd acceleration(2, c_count);
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_[static_cast<std::size_t>(c)];
    acceleration.col(c) = -k * k * w * w * coefficients.col(c);
  }
  out.residual.resize(p_count);
  if (!options_.collocation) {
    Eigen::Map<Eigen::Matrix2Xd> residual(out.residual.data(), 2, c_count);
    residual = mass * acceleration + out.period.loads.leftCols(driven_samples_) * projection_.transpose();
    residual.col(excitation_column_) -= -w * w * x_amp * load;  // excitation, sin(W t)
    if (with_jacobian) {
      out.force_jacobian.resize(p_count, columns);
      for (int d = 0; d < 2; ++d) {
        const ConstStrided s(workspace.sensitivity.data() + d, driven_samples_, columns,
                             Eigen::Stride<Eigen::Dynamic, 2>(2 * driven_samples_, 2));
        Strided(out.force_jacobian.data() + d, c_count, columns, Eigen::Stride<Eigen::Dynamic, 2>(2 * c_count, 2)) =
            projection_ * s;
      }
    }
  } else {
    Eigen::Map<Eigen::Matrix2Xd> residual(out.residual.data(), 2, samples_);
    residual = mass * (acceleration * basis_.transpose()) + out.period.loads;
    residual -= (-w * w * x_amp * load) * basis_.col(excitation_column_).transpose();
    if (with_jacobian) out.force_jacobian = workspace.sensitivity;
  }
  if ((derivatives & kFrequency) != 0) {
    // At constant velocity amplitude V = W X: excitation -W V L sin(W t).
    const double v = w * x_amp;
    Eigen::Matrix2Xd d_acceleration(2, c_count);
    for (int c = 0; c < c_count; ++c) {
      const double k = harmonic_[static_cast<std::size_t>(c)];
      d_acceleration.col(c) = -2.0 * k * k * w * coefficients.col(c);
    }
    out.d_frequency.resize(p_count);
    if (!options_.collocation) {
      Eigen::Map<Eigen::Matrix2Xd> d(out.d_frequency.data(), 2, c_count);
      d = mass * d_acceleration;
      d.col(excitation_column_) += v * load;
    } else {
      Eigen::Map<Eigen::Matrix2Xd> d(out.d_frequency.data(), 2, samples_);
      d = mass * (d_acceleration * basis_.transpose());
      d += (v * load) * basis_.col(excitation_column_).transpose();
    }
  }
  return out;
}

Eigen::MatrixXd HarmonicBalance::jacobian(const Excitation& excitation, const Eigen::MatrixXd& force_jacobian) const {
  Eigen::MatrixXd jacobian;
  assemble_jacobian(excitation, force_jacobian, jacobian);
  return jacobian;
}

void HarmonicBalance::assemble_jacobian(const Excitation& excitation, const Eigen::MatrixXd& force_jacobian,
                                        Eigen::MatrixXd& jacobian) const {
  const int c_count = static_cast<int>(harmonic_.size());
  const double w = excitation.angular_frequency();
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  jacobian = force_jacobian;
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_[static_cast<std::size_t>(c)];
    if (!options_.collocation) {
      jacobian.block<2, 2>(2 * c, 2 * c) += -k * k * w * w * mass;
    } else {
      for (int j = 0; j < samples_; ++j) jacobian.block<2, 2>(2 * j, 2 * c) += -k * k * w * w * basis_(j, c) * mass;
    }
  }
}

ArmSolution HarmonicBalance::solve(const Excitation& excitation, const Eigen::VectorXd& initial,
                                   HarmonicBalanceMemory& memory, HarmonicBalanceWorkspace& workspace) const {
  excitation.validate();
  if (initial.size() != unknown_count()) {
    throw InvalidParameter("initial_guess", fmt::format(" has {} values: expected {}", initial.size(), unknown_count()));
  }
  const auto started = std::chrono::steady_clock::now();
  ArmSolution solution;
  solution.unknowns = initial;
  NewtonSolve newton(*this, excitation, memory, workspace, solution.summary);
  const bool converged = newton.run(solution.unknowns);
  if (converged) {
    memory.cable_state = newton.cable_state();
    memory.unknowns = solution.unknowns;
    memory.jacobian_points = solution.summary.jacobians > 0 ? 1 : memory.jacobian_points + 1;
    solution.jacobian_sign = memory.jacobian_sign;
  } else {
    memory.clear();
  }
  if (newton.current().ok()) {
    solution.period = std::move(newton.current().period);
    solution.summary.energy_error = energy_error(solution.period, excitation);
  }
  solution.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return solution;
}

ArmSolution HarmonicBalance::solve(const Excitation& excitation, const Eigen::VectorXd& initial) const {
  HarmonicBalanceMemory memory;
  HarmonicBalanceWorkspace workspace = make_workspace();
  return solve(excitation, initial, memory, workspace);
}

}  // namespace stockbridge::damper
