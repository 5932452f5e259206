#include "stockbridge/damper/time_integration.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "arm_newmark.hpp"

namespace stockbridge::damper {

namespace {
double scaled_max(const Eigen::Vector2d& force_moment, double length) {
  return std::max(std::abs(force_moment(0)), std::abs(force_moment(1)) / length);
}
}  // namespace

namespace detail {

ArmStepOutcome solve_arm_step(const ArmStepSystem& system, cable::Cantilever& cantilever, const Eigen::Vector2d& base,
                              const Eigen::Vector2d& p, Eigen::Vector2d& a) {
  ArmStepOutcome outcome;
  for (int iteration = 0;; ++iteration) {
    const Eigen::Vector2d u = base + system.q * a;
    const cable::StateDetermination solve = cantilever.set_trial_tip(u(0), u(1));
    if (!solve.converged()) {
      cantilever.revert_to_last_commit();
      outcome.termination = Termination::inner_failure;
      outcome.cable_failure = solve;
      return outcome;
    }
    const cable::CableState& trial = cantilever.trial();
    const Eigen::Vector2d f(trial.tip_force, trial.tip_moment(system.length));
    const Eigen::Vector2d inertia = system.mass * a;
    const Eigen::Vector2d residual = inertia + f - p;
    const double scale = std::max({scaled_max(inertia, system.length), scaled_max(f, system.length),
                                   scaled_max(p, system.length)});
    const double norm = scaled_max(residual, system.length);
    if (norm <= system.tolerance * scale) return outcome;
    if (iteration == system.max_newton || !std::isfinite(norm)) {
      cantilever.revert_to_last_commit();
      outcome.termination = std::isfinite(norm) ? Termination::max_iterations : Termination::non_finite;
      outcome.iterations = iteration;
      outcome.residual = scale > 0.0 ? norm / scale : norm;
      return outcome;
    }
    // d residual / d a = M + (h^2/4) K_t, i.e. (h^2/4) (K_t + (4/h^2) M).
    const Eigen::Matrix2d tangent = system.mass + system.q * trial.tip_stiffness(system.length);
    a -= tangent.inverse() * residual;
  }
}

}  // namespace detail

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

void TimeDomainOptions::validate() const {
  require_in_range("steps_per_period", steps_per_period, 8, 1 << 22);
  require_in_range("max_newton", max_newton, 1, 10000);
  require_positive("newton_tolerance", newton_tolerance, "");
  within_field("cantilever", [&] { cantilever.validate(); });
}

NewmarkStepper::NewmarkStepper(const Arm& arm, const TimeDomainOptions& options)
    : mass_(arm.mass_matrix()),
      load_(arm.load_vector()),
      steps_(options.steps_per_period),
      max_newton_(options.max_newton),
      newton_tolerance_(options.newton_tolerance),
      length_(arm.cable().length()),
      mass_inverse_(arm.mass_matrix().inverse()),
      cantilever_(arm.cable(), options.cantilever) {
  assert(steps_ >= 8 && max_newton_ >= 1 && newton_tolerance_ > 0.0);
}

void NewmarkStepper::set_excitation(const Excitation& excitation) {
  period_ = excitation.period();
  h_ = period_ / steps_;
  const double w = excitation.angular_frequency();
  const Eigen::Vector2d amplitude = -w * w * excitation.displacement_amplitude * load_;
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

SolverSummary NewmarkStepper::place(const Eigen::Vector4d& z) {
  periods_since_place_ = 0;
  const cable::StateDetermination solve = cantilever_.set_trial_tip(z(0), z(1));
  if (!solve.converged()) {
    cantilever_.revert_to_last_commit();
    return summary_of(Termination::inner_failure,
                           fmt::format("cable state determination moving the tip to the initial state (x, phi) = "
                                       "({:.6g} m, {:.6g} rad): {}",
                                       z(0), z(1), brief_report(solve)));
  }
  cantilever_.commit();
  const cable::CableState& state = cantilever_.committed();
  u_ = z.head<2>();
  v_ = z.tail<2>();
  a_ = mass_inverse_ * (forcing_.front() - Eigen::Vector2d(state.tip_force, state.tip_moment(length_)));
  return summary_of(Termination::converged);
}

bool NewmarkStepper::step(int j, SolverSummary& failure) {
  const Eigen::Vector2d& p = forcing_[static_cast<std::size_t>((j + 1) % steps_)];
  const double q = 0.25 * h_ * h_;  // u_{n+1} = base + q a_{n+1}
  const Eigen::Vector2d base = u_ + h_ * v_ + q * a_;
  Eigen::Vector2d a = a_;  // predictor: constant acceleration
  const detail::ArmStepOutcome outcome =
      detail::solve_arm_step({mass_, length_, q, max_newton_, newton_tolerance_}, cantilever_, base, p, a);
  if (outcome.termination != Termination::converged) {
    const std::string where = fmt::format("in the time step to t = {:.9g} s (step {} of {} in period {} since the start)",
                                          time() + (j + 1) * h_, j + 1, steps_, periods_since_place_ + 1);
    if (outcome.termination == Termination::inner_failure) {
      failure = summary_of(Termination::inner_failure,
                           fmt::format("cable state determination {}: {}", where, brief_report(outcome.cable_failure)));
    } else {
      failure = summary_of(outcome.termination, fmt::format("{} (relative to the largest term)", where));
      failure.newton_iterations = outcome.iterations;
      failure.residual = outcome.residual;
    }
    return false;
  }
  cantilever_.commit();
  v_ += 0.5 * h_ * (a_ + a);
  u_ = base + q * a;
  a_ = a;
  return true;
}

SolverSummary NewmarkStepper::advance_period(ArmPeriod* record) {
  assert(!forcing_.empty() && "set_excitation() must be called before stepping");
  const double dissipated_before = cantilever_.committed().dissipated;
  if (record) record->resize(steps_);
  for (int j = 0; j < steps_; ++j) {
    if (record) {
      record->kinematics.col(j) = u_;
      record->record_loads(j, cantilever_.committed(), cantilever_.cable());
    }
    SolverSummary failure;
    if (!step(j, failure)) return failure;
  }
  if (record) record->dissipated = cantilever_.committed().dissipated - dissipated_before;
  ++periods_since_place_;
  return summary_of(Termination::converged);
}

// ---------------------------------------------------------------------------
// Periodicity measures

void require_time_domain_start(const Excitation& excitation, const Eigen::VectorXd* initial_state) {
  excitation.validate();
  if (initial_state && initial_state->size() != 4) {
    throw InvalidParameter("initial_state", fmt::format(" has {} values: expected 4 (x, phi, x', phi')",
                                                        initial_state->size()));
  }
  if (initial_state && !initial_state->allFinite()) throw InvalidParameter("initial_state", ": expected finite values");
}

double amplitude_of(const ArmPeriod& period, double length) {
  double amplitude = 0.0;
  for (Eigen::Index j = 0; j < period.kinematics.cols(); ++j) {
    amplitude = std::max({amplitude, std::abs(period.kinematics(0, j)), length * std::abs(period.kinematics(1, j))});
  }
  return amplitude;
}

double state_change_measure(const Eigen::Vector4d& delta, const ArmPeriod& period, double angular_frequency,
                            double length) {
  const double change = std::max({std::abs(delta(0)), length * std::abs(delta(1)), std::abs(delta(2)) / angular_frequency,
                                   length * std::abs(delta(3)) / angular_frequency});
  return change / std::max(amplitude_of(period, length), 1e-300);
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
  TimeDomainOptions::validate();
  require_in_range("max_periods", max_periods, 2, 100000000);
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
}

TimeIntegration::TimeIntegration(Arm arm, TimeIntegrationOptions options)
    : arm_(std::move(arm)), options_(validated(std::move(options))) {}

ArmSolution TimeIntegration::solve(const Excitation& excitation, const Eigen::VectorXd* initial_state) const {
  NewmarkStepper run = stepper();
  return solve(excitation, initial_state, run);
}

ArmSolution TimeIntegration::solve(const Excitation& excitation, const Eigen::VectorXd* initial_state,
                                   NewmarkStepper& stepper) const {
  require_time_domain_start(excitation, initial_state);
  const auto start_time = std::chrono::steady_clock::now();
  const double w = excitation.angular_frequency();
  const double l = arm_.cable().length();
  ArmSolution solution;
  SolverSummary& summary = solution.summary;

  const Eigen::Vector4d z0 =
      initial_state ? Eigen::Vector4d(*initial_state) : linear_discrete_start(arm_, excitation, options_.steps_per_period);
  solution.unknowns = z0;
  stepper.set_excitation(excitation);
  stepper.reset_cable();
  ArmPeriod current, previous;
  Eigen::Vector4d period_start = z0;
  bool have_period = false, step_failed = false;
  if (const SolverSummary placed = stepper.place(z0); !placed.converged()) {
    summary.termination = placed.termination;
    summary.where = "at the start: " + brief_report(placed);
  } else {
    for (int k = 1; k <= options_.max_periods; ++k) {
      if (const SolverSummary period = stepper.advance_period(&current); !period.converged()) {
        summary.termination = period.termination;
        summary.where = fmt::format("{} (after {} complete periods)", brief_report(period), k - 1);
        step_failed = true;
        break;
      }
      have_period = true;
      summary.periods = k;
      const Eigen::Vector4d period_end = stepper.state();
      const double state_change = state_change_measure(period_end - period_start, current, w, l);
      double loads_change = std::numeric_limits<double>::infinity();
      if (k >= 2) loads_change = loads_change_measure(current.loads, previous.loads, l);
      summary.residual = std::max(state_change, loads_change);
      summary.periodicity_defect = loads_change;
      solution.unknowns = period_start;
      if (summary.residual <= options_.periodicity_tolerance) {
        summary.termination = Termination::converged;
        break;
      }
      if (k == options_.max_periods) {
        summary.termination = Termination::not_periodic;
        summary.where = fmt::format(
            "(over the last period the state at the period start changed by {:.3g} of the amplitude and the loads by "
            "{:.3g} of the largest, tolerance {:.3g})",
            state_change, loads_change, options_.periodicity_tolerance);
        break;
      }
      std::swap(previous, current);
      period_start = period_end;
    }
  }
  if (have_period) {
    // After a failed step `current` is incomplete: report the last complete period.
    solution.period = step_failed ? std::move(previous) : std::move(current);
    summary.energy_error = energy_error(solution.period, excitation);
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return solution;
}

}  // namespace stockbridge::damper
