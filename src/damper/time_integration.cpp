#include "stockbridge/damper/time_integration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

namespace {
double scaled_max(const Eigen::Vector2d& force_moment, double length) {
  return std::max(std::abs(force_moment(0)), std::abs(force_moment(1)) / length);
}
}  // namespace

Eigen::Vector4d linear_discrete_start(const Arm& arm, const Excitation& excitation, int steps_per_period) {
  excitation.validate();
  require_in_range("steps_per_period", steps_per_period, 1, 1 << 30);
  const double w = excitation.angular_frequency();
  const double h = excitation.period() / steps_per_period;
  const double w_h = 2.0 / h * std::tan(std::numbers::pi / steps_per_period);
  const Eigen::Matrix2d dynamic = arm.stick_stiffness() - w_h * w_h * arm.mass_matrix();
  const Eigen::Vector2d amplitude =
      dynamic.partialPivLu().solve(-w * w * excitation.displacement_amplitude * arm.load_vector());
  Eigen::Vector4d z = Eigen::Vector4d::Zero();
  if (amplitude.allFinite()) z.tail<2>() = w_h * amplitude;  // exactly at a discrete resonance: from rest
  return z;
}

// ---------------------------------------------------------------------------
// NewmarkStepper

NewmarkStepper::NewmarkStepper(const Arm& arm, int steps_per_period, int max_newton, double newton_tolerance,
                               const cable::CantileverOptions& cantilever)
    : arm_(arm),
      steps_(steps_per_period),
      max_newton_(max_newton),
      newton_tolerance_(newton_tolerance),
      cantilever_(arm.cable(), cantilever),
      length_(arm.cable().length()),
      mass_inverse_(arm.mass_matrix().inverse()) {
  require_in_range("steps_per_period", steps_per_period, 1, 1 << 30);
  require_in_range("max_newton", max_newton, 1, 10000);
  require_positive("newton_tolerance", newton_tolerance, "");
}

void NewmarkStepper::set_excitation(const Excitation& excitation) {
  excitation.validate();
  period_ = excitation.period();
  h_ = period_ / steps_;
  const double w = excitation.angular_frequency();
  const Eigen::Vector2d amplitude = -w * w * excitation.displacement_amplitude * arm_.load_vector();
  forcing_.resize(static_cast<std::size_t>(steps_));
  for (int j = 0; j < steps_; ++j) {
    forcing_[static_cast<std::size_t>(j)] = std::sin(2.0 * std::numbers::pi * j / steps_) * amplitude;
  }
}

void NewmarkStepper::reset_cable() { cantilever_.reset(); }

Eigen::Vector4d NewmarkStepper::state() const {
  Eigen::Vector4d z;
  z << u_, v_;
  return z;
}

bool NewmarkStepper::place(const Eigen::Vector4d& z) {
  periods_since_place_ = 0;
  failure_.clear();
  const cable::StateDetermination solve = cantilever_.set_trial_tip(z(0), z(1));
  if (!solve.converged) {
    cantilever_.revert_to_last_commit();
    failure_ = fmt::format("cable state determination failed moving the tip to the initial state "
                           "(x, phi) = ({:.6g} m, {:.6g} rad): residual {:.3g} rad after {} iterations",
                           z(0), z(1), solve.residual, solve.iterations);
    return false;
  }
  cantilever_.commit();
  const cable::CableState& state = cantilever_.committed();
  u_ = z.head<2>();
  v_ = z.tail<2>();
  a_ = mass_inverse_ * (forcing_.front() - Eigen::Vector2d(state.tip_force, state.tip_moment(length_)));
  return true;
}

bool NewmarkStepper::step(int j) {
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  const Eigen::Vector2d& p = forcing_[static_cast<std::size_t>((j + 1) % steps_)];
  const double q = 0.25 * h_ * h_;  // u_{n+1} = base + q a_{n+1}
  const Eigen::Vector2d base = u_ + h_ * v_ + q * a_;
  Eigen::Vector2d a = a_;  // predictor: constant acceleration
  Eigen::Vector2d u;
  auto where = [&] {
    return fmt::format("the time step to t = {:.9g} s (step {} of {} in period {} since the start)",
                       time() + (j + 1) * h_, j + 1, steps_, periods_since_place_ + 1);
  };
  for (int iteration = 0;; ++iteration) {
    u = base + q * a;
    const cable::StateDetermination solve = cantilever_.set_trial_tip(u(0), u(1));
    if (!solve.converged) {
      cantilever_.revert_to_last_commit();
      failure_ = fmt::format("cable state determination failed in {}: residual {:.3g} rad after {} iterations",
                             where(), solve.residual, solve.iterations);
      return false;
    }
    const cable::CableState& trial = cantilever_.trial();
    const Eigen::Vector2d f(trial.tip_force, trial.tip_moment(length_));
    const Eigen::Vector2d inertia = mass * a;
    const Eigen::Vector2d residual = inertia + f - p;
    const double scale = std::max({scaled_max(inertia, length_), scaled_max(f, length_), scaled_max(p, length_)});
    const double norm = scaled_max(residual, length_);
    if (norm <= newton_tolerance_ * scale) {
      max_iterations_used_ = std::max(max_iterations_used_, iteration);
      break;
    }
    if (iteration == max_newton_ || !std::isfinite(norm)) {
      cantilever_.revert_to_last_commit();
      failure_ = fmt::format("Newton did not converge in {}: residual {:.3g} of the largest term after {} iterations",
                             where(), scale > 0.0 ? norm / scale : norm, iteration);
      return false;
    }
    // d residual / d a = M + (h^2/4) K_t, i.e. (h^2/4) (K_t + (4/h^2) M).
    const Eigen::Matrix2d tangent = mass + q * trial.tip_stiffness(length_);
    a -= tangent.inverse() * residual;
  }
  cantilever_.commit();
  v_ += 0.5 * h_ * (a_ + a);
  u_ = u;
  a_ = a;
  return true;
}

bool NewmarkStepper::advance_period(ArmPeriod* record) {
  if (forcing_.empty()) throw InvalidParameter("NewmarkStepper: set_excitation() must be called before stepping");
  const double dissipated_before = cantilever_.committed().dissipated;
  if (record) {
    record->kinematics.resize(2, steps_);
    record->loads.resize(2, steps_);
    record->clamp_moment.resize(static_cast<std::size_t>(steps_));
    record->clamp_curvature.resize(static_cast<std::size_t>(steps_));
    record->clamp_section_moment.resize(static_cast<std::size_t>(steps_));
  }
  for (int j = 0; j < steps_; ++j) {
    if (record) {
      const cable::CableState& state = cantilever_.committed();
      record->kinematics.col(j) = u_;
      record->loads.col(j) = Eigen::Vector2d(state.tip_force, state.tip_moment(length_));
      record->clamp_moment[static_cast<std::size_t>(j)] = state.clamp_moment;
      record->clamp_curvature[static_cast<std::size_t>(j)] = state.curvature.front();
      record->clamp_section_moment[static_cast<std::size_t>(j)] =
          state.clamp_moment - state.tip_force * cantilever_.cable().positions()[0];
    }
    if (!step(j)) return false;
  }
  if (record) record->dissipated = cantilever_.committed().dissipated - dissipated_before;
  ++periods_since_place_;
  return true;
}

// ---------------------------------------------------------------------------
// Periodicity measures

double state_change_measure(const Eigen::Vector4d& delta, const ArmPeriod& period, double angular_frequency,
                            double length) {
  double amplitude = 0.0;
  for (Eigen::Index j = 0; j < period.kinematics.cols(); ++j) {
    amplitude = std::max({amplitude, std::abs(period.kinematics(0, j)), length * std::abs(period.kinematics(1, j))});
  }
  const double change = std::max({std::abs(delta(0)), length * std::abs(delta(1)), std::abs(delta(2)) / angular_frequency,
                                   length * std::abs(delta(3)) / angular_frequency});
  return change / std::max(amplitude, 1e-300);
}

double loads_change_measure(const Eigen::Matrix2Xd& loads, const Eigen::Matrix2Xd& previous, double length) {
  double change = 0.0, largest = 0.0;
  for (Eigen::Index j = 0; j < loads.cols(); ++j) {
    change = std::max(change, scaled_max(loads.col(j) - previous.col(j), length));
    largest = std::max(largest, scaled_max(loads.col(j), length));
  }
  return change / std::max(largest, 1e-300);
}

// ---------------------------------------------------------------------------
// TimeIntegration

void TimeIntegrationOptions::validate() const {
  require_in_range("steps_per_period", steps_per_period, 8, 1 << 22);
  require_in_range("max_periods", max_periods, 2, 100000000);
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
  require_in_range("max_newton", max_newton, 1, 10000);
  require_positive("newton_tolerance", newton_tolerance, "");
  try {
    cantilever.validate();
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(fmt::format("cantilever.{}", e.what()));
  }
}

TimeIntegration::TimeIntegration(const Arm& arm, TimeIntegrationOptions options)
    : arm_(arm),
      options_(validated(std::move(options))),
      stepper_(arm, options_.steps_per_period, options_.max_newton, options_.newton_tolerance, options_.cantilever) {}

ArmSolution TimeIntegration::solve(const Excitation& excitation, const Eigen::VectorXd* initial_state) {
  excitation.validate();
  if (initial_state && initial_state->size() != 4) {
    throw InvalidParameter(fmt::format("initial_state has {} values: expected 4 (x, phi, x', phi')",
                                       initial_state->size()));
  }
  if (initial_state && !initial_state->allFinite()) {
    throw InvalidParameter("initial_state: expected finite values");
  }
  const auto start_time = std::chrono::steady_clock::now();
  const double w = excitation.angular_frequency();
  const double l = arm_.cable().length();
  ArmSolution solution;
  SolverSummary& summary = solution.summary;

  const Eigen::Vector4d z0 =
      initial_state ? Eigen::Vector4d(*initial_state) : linear_discrete_start(arm_, excitation, options_.steps_per_period);
  stepper_.set_excitation(excitation);
  stepper_.reset_cable();
  ArmPeriod current, previous;
  Eigen::Vector4d period_start = z0;
  bool have_period = false, step_failed = false;
  if (!stepper_.place(z0)) {
    summary.message = stepper_.failure();
  } else {
    for (int k = 1; k <= options_.max_periods; ++k) {
      if (!stepper_.advance_period(&current)) {
        summary.message = fmt::format("{} (after {} complete periods)", stepper_.failure(), k - 1);
        step_failed = true;
        break;
      }
      have_period = true;
      summary.iterations = k;
      const Eigen::Vector4d period_end = stepper_.state();
      const double state_change = state_change_measure(period_end - period_start, current, w, l);
      double loads_change = std::numeric_limits<double>::infinity();
      if (k >= 2) loads_change = loads_change_measure(current.loads, previous.loads, l);
      summary.residual = std::max(state_change, loads_change);
      summary.periodicity_defect = loads_change;
      solution.unknowns = period_start;
      if (summary.residual <= options_.periodicity_tolerance) {
        summary.converged = true;
        break;
      }
      if (k == options_.max_periods) {
        summary.message = fmt::format(
            "not periodic after {} periods: over the last period the state at the period start changed by {:.3g} "
            "(relative to the amplitude) and the loads by {:.3g} (relative to the largest), tolerance {:.3g}",
            k, state_change, loads_change, options_.periodicity_tolerance);
        break;
      }
      std::swap(previous, current);
      period_start = period_end;
    }
  }
  summary.periods = summary.iterations;
  if (have_period) {
    // After a failed step `current` is incomplete: report the last complete period.
    solution.period = step_failed ? std::move(previous) : std::move(current);
    summary.energy_error = energy_error(solution.period, excitation);
  }
  if (solution.unknowns.size() == 0) solution.unknowns = z0;
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return solution;
}

}  // namespace stockbridge::damper
