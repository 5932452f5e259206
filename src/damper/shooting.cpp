#include "stockbridge/damper/shooting.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/linear_solve.hpp"

namespace stockbridge::damper {

void ShootingOptions::validate() const {
  TimeDomainOptions::validate();
  require_in_range("pre_periods", pre_periods, 1, 100000);
  require_in_range("max_pre_periods", max_pre_periods, pre_periods, 100000);
  require_in_range("max_iterations", max_iterations, 1, 10000);
  require_positive("tolerance", tolerance, "");
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
  require_positive("finite_difference_step", finite_difference_step, "");
  require_in_range("max_halvings", max_halvings, 0, 200);
}

Shooting::Shooting(Arm arm, ShootingOptions options)
    : arm_(std::move(arm)), options_(validated(std::move(options))) {}

void Shooting::shoot(NewmarkStepper& stepper, const Eigen::Vector4d& z0, int pre_periods, Shot& shot,
                     const cable::CableState* memory) const {
  auto failed = [&shot](SolverSummary failure, std::string_view stage) {
    failure.where = fmt::format("{} ({})", failure.where, stage);
    shot.summary = std::move(failure);
  };
  if (memory) {
    stepper.restore_cable(*memory);
  } else {
    stepper.reset_cable();
  }
  if (SolverSummary placed = stepper.place(z0); !placed.converged()) return failed(std::move(placed), "placing the arm at z0");
  ArmPeriod pre;
  for (int k = 1; k <= pre_periods; ++k) {
    if (SolverSummary period = stepper.advance_period(k == pre_periods ? &pre : nullptr); !period.converged()) {
      return failed(std::move(period), fmt::format("pre-period {} of {}", k, pre_periods));
    }
  }
  shot.pre_loads = std::move(pre.loads);
  // The mechanical state back to z0, the memory kept.
  if (SolverSummary placed = stepper.place(z0); !placed.converged()) return failed(std::move(placed), "after the pre-periods");
  if (SolverSummary period = stepper.advance_period(&shot.period); !period.converged()) {
    return failed(std::move(period), "final period");
  }
  shot.end = stepper.state();
  shot.memory = stepper.cantilever().committed();
  shot.summary = summary_of(Termination::converged);
}

namespace {

/// Newton on S(z0) = 0, in named steps (the header's algorithm). Works in the
/// scaled unknowns D z0 with the scaled residual D (z(T) - z0); the Jacobian is
/// kept unscaled, of z(T) - z0 with respect to z0: by forward differences, then
/// updated by Broyden's rank-one formula after each accepted step, and recomputed
/// by differences when a Broyden step fails.
class ShootingNewton {
 public:
  ShootingNewton(const Shooting& shooting, NewmarkStepper& stepper, const ShootingOptions& options,
                 const Excitation& excitation, double length, SolverSummary& summary)
      : shooting_(shooting),
        stepper_(stepper),
        options_(options),
        w_(excitation.angular_frequency()),
        l_(length),
        summary_(summary),
        pre_periods_(options.pre_periods) {}

  /// Runs from z (updated in place); true when converged. shot() is the last accepted shot.
  bool run(Eigen::Vector4d& z);
  const Shooting::Shot& shot() const { return shot_; }

 private:
  enum class Outcome { accepted, failed };
  bool fire(const Eigen::Vector4d& z, Shooting::Shot& into);
  bool fail(Termination termination, std::string where = {});
  /// More pre-periods (the memory has not settled), shooting again from z.
  bool more_pre_periods(const Eigen::Vector4d& z, double measure, double defect);
  bool finite_difference_jacobian(const Eigen::Vector4d& z, const Eigen::Vector4d& scale,
                                  const Eigen::Vector4d& residual);
  /// One Newton step with a line search (a Broyden Jacobian gets the full step only).
  Outcome step(Eigen::Vector4d& z);

  const Shooting& shooting_;
  NewmarkStepper& stepper_;
  const ShootingOptions& options_;
  const double w_, l_;
  SolverSummary& summary_;
  int pre_periods_;
  Shooting::Shot shot_, trial_;
  std::optional<cable::CableState> memory_;  // where every shot's cable starts (virgin until P first grows)
  int memory_periods_ = 0;                   // periods the memory had before the shots start from it
  Eigen::Matrix4d jacobian_ = Eigen::Matrix4d::Zero();
  bool have_jacobian_ = false, jacobian_fresh_ = false;
};

bool ShootingNewton::fail(Termination termination, std::string where) {
  summary_.termination = termination;
  summary_.where = std::move(where);
  return false;
}

bool ShootingNewton::fire(const Eigen::Vector4d& z, Shooting::Shot& into) {
  summary_.periods += pre_periods_ + 1;
  shooting_.shoot(stepper_, z, pre_periods_, into, memory_ ? &*memory_ : nullptr);
  if (into.summary.converged()) return true;
  summary_.termination = into.summary.termination;
  summary_.where = brief_report(into.summary);
  return false;
}

bool ShootingNewton::more_pre_periods(const Eigen::Vector4d& z, double measure, double defect) {
  if (pre_periods_ == options_.max_pre_periods) {
    summary_.periodicity_defect = defect;
    return fail(Termination::not_periodic,
                fmt::format("(the cable's memory is not settled after {} pre-periods ({} periods in all): the loads of the final period "
                            "differ from the last pre-period by {:.3g} of the largest, tolerance {:.3g}; z(T) - z0 is "
                            "{:.3g} of the amplitude)",
                            pre_periods_, memory_periods_ + pre_periods_ + 1, defect, options_.periodicity_tolerance,
                            measure));
  }
  memory_periods_ += pre_periods_ + 1;
  pre_periods_ = std::min(2 * pre_periods_, options_.max_pre_periods);
  memory_ = shot_.memory;  // the memory settles on from where the last accepted shot left it
  jacobian_fresh_ = false;  // its differences were taken with fewer pre-periods: a failure retakes them
  return fire(z, shot_);
}

bool ShootingNewton::finite_difference_jacobian(const Eigen::Vector4d& z, const Eigen::Vector4d& scale,
                                                const Eigen::Vector4d& residual) {
  const double delta = options_.finite_difference_step;
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector4d z_i = z;
    z_i(i) += delta / scale(i);
    if (!fire(z_i, trial_)) {
      summary_.where = fmt::format("in a finite-difference shot: {}", summary_.where);
      return false;
    }
    jacobian_.col(i) = ((trial_.end - z_i) - residual) * (scale(i) / delta);
  }
  have_jacobian_ = jacobian_fresh_ = true;
  return true;
}

ShootingNewton::Outcome ShootingNewton::step(Eigen::Vector4d& z) {
  Eigen::Vector4d scale;  // D
  scale << 1.0, l_, 1.0 / w_, l_ / w_;
  scale /= std::max(amplitude_of(shot_.period, l_), 1e-300);
  const Eigen::Vector4d residual = shot_.end - z;
  const double norm = scale.cwiseProduct(residual).norm();
  while (true) {
    if (!have_jacobian_ && !finite_difference_jacobian(z, scale, residual)) return Outcome::failed;
    Eigen::Vector4d direction;
    const double reciprocal_condition = numerics::solve_checked(jacobian_, Eigen::Vector4d(-residual), direction);
    if (numerics::is_singular(reciprocal_condition, direction)) {
      if (!jacobian_fresh_) {
        have_jacobian_ = false;
        continue;
      }
      summary_.reciprocal_condition = reciprocal_condition;
      fail(Termination::singular_jacobian);
      return Outcome::failed;
    }
    const int halvings = jacobian_fresh_ ? options_.max_halvings : 0;
    double alpha = 1.0;
    for (int halving = 0; halving <= halvings; ++halving, alpha *= 0.5) {
      const Eigen::Vector4d z_try = z + alpha * direction;
      if (fire(z_try, trial_) && scale.cwiseProduct(trial_.end - z_try).norm() <= (1.0 - 1e-4 * alpha) * norm) {
        // Broyden: J += (dS - J dz) dz^T / (dz^T dz), in the scaled unknowns.
        const Eigen::Vector4d dz = alpha * direction;
        const Eigen::Vector4d ds = (trial_.end - z_try) - residual;
        const Eigen::Vector4d dz_scaled = scale.cwiseProduct(dz);
        jacobian_ += (ds - jacobian_ * dz) * (scale.cwiseProduct(dz_scaled)).transpose() / dz_scaled.squaredNorm();
        jacobian_fresh_ = false;
        z = z_try;
        std::swap(shot_, trial_);
        return Outcome::accepted;
      }
    }
    if (!jacobian_fresh_) {
      have_jacobian_ = false;
      continue;
    }
    fail(Termination::line_search_failed);
    return Outcome::failed;
  }
}

bool ShootingNewton::run(Eigen::Vector4d& z) {
  if (!fire(z, shot_)) {
    summary_.where = "at the starting point: " + summary_.where;
    return false;
  }
  while (true) {
    const double measure = state_change_measure(shot_.end - z, shot_.period, w_, l_);
    const double defect = loads_change_measure(shot_.period.loads, shot_.pre_loads, l_);
    summary_.residual = measure;
    summary_.periodicity_defect = defect;
    if (measure <= options_.tolerance && defect <= options_.periodicity_tolerance) {
      summary_.termination = Termination::converged;
      summary_.where.clear();  // failed trial shots on the way are not the result
      return true;
    }
    // Solving S = 0 more precisely than the cable's memory has settled is wasted: more pre-periods first.
    if (defect > options_.periodicity_tolerance && measure <= std::max(options_.tolerance, 0.01 * defect)) {
      if (!more_pre_periods(z, measure, defect)) return false;
      continue;
    }
    if (summary_.newton_iterations == options_.max_iterations) {
      return fail(Termination::max_iterations,
                  fmt::format("(z(T) - z0 is {:.3g} of the amplitude, tolerance {:.3g}; loads of the final period vs "
                              "the last pre-period {:.3g}, tolerance {:.3g}, {} pre-periods)",
                              measure, options_.tolerance, defect, options_.periodicity_tolerance, pre_periods_));
    }
    ++summary_.newton_iterations;
    if (step(z) == Outcome::failed) {
      // A line search that fails where S is already as small as the memory's
      // defect: S is not defined more precisely than the memory has settled; more
      // pre-periods first (while there may be more: else the failure stands).
      const bool memory_limited = summary_.termination == Termination::line_search_failed &&
                                  defect > options_.periodicity_tolerance && measure <= defect &&
                                  pre_periods_ < options_.max_pre_periods;
      if (!memory_limited || !more_pre_periods(z, measure, defect)) return false;
    }
  }
}

}  // namespace

ArmSolution Shooting::solve(const Excitation& excitation, const Eigen::VectorXd* initial_state) const {
  NewmarkStepper run = stepper();
  return solve(excitation, initial_state, run);
}

ArmSolution Shooting::solve(const Excitation& excitation, const Eigen::VectorXd* initial_state,
                            NewmarkStepper& stepper) const {
  require_time_domain_start(excitation, initial_state);
  const auto start_time = std::chrono::steady_clock::now();
  stepper.set_excitation(excitation);
  ArmSolution solution;
  Eigen::Vector4d z =
      initial_state ? Eigen::Vector4d(*initial_state) : linear_discrete_start(arm_, excitation, options_.steps_per_period);
  ShootingNewton newton(*this, stepper, options_, excitation, arm_.cable().length(), solution.summary);
  newton.run(z);
  if (newton.shot().summary.converged()) {
    solution.period = newton.shot().period;
    solution.summary.energy_error = energy_error(solution.period, excitation);
  }
  solution.unknowns = z;
  solution.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return solution;
}

}  // namespace stockbridge::damper
