#include "stockbridge/damper/shooting.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/linear_solve.hpp"

namespace stockbridge::damper {

void ShootingOptions::validate() const {
  require_in_range("steps_per_period", steps_per_period, 8, 1 << 22);
  require_in_range("pre_periods", pre_periods, 1, 100000);
  require_in_range("max_pre_periods", max_pre_periods, pre_periods, 100000);
  require_in_range("max_iterations", max_iterations, 1, 10000);
  require_positive("tolerance", tolerance, "");
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
  require_positive("finite_difference_step", finite_difference_step, "");
  require_in_range("max_halvings", max_halvings, 0, 200);
  require_in_range("max_newton", max_newton, 1, 10000);
  require_positive("newton_tolerance", newton_tolerance, "");
  try {
    cantilever.validate();
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(fmt::format("cantilever.{}", e.what()));
  }
}

namespace {
/// max_j max(|x_j|, l |phi_j|), m.
double amplitude_of(const ArmPeriod& period, double length) {
  double amplitude = 0.0;
  for (Eigen::Index j = 0; j < period.kinematics.cols(); ++j) {
    amplitude = std::max({amplitude, std::abs(period.kinematics(0, j)), length * std::abs(period.kinematics(1, j))});
  }
  return amplitude;
}
}  // namespace

Shooting::Shooting(const Arm& arm, ShootingOptions options)
    : arm_(arm),
      options_(validated(std::move(options))),
      stepper_(arm, options_.steps_per_period, options_.max_newton, options_.newton_tolerance, options_.cantilever) {}

bool Shooting::shoot(const Eigen::Vector4d& z0, int pre_periods, Shot& shot, std::string& failure) {
  shot.ok = false;
  stepper_.reset_cable();
  if (!stepper_.place(z0)) {
    failure = stepper_.failure();
    return false;
  }
  ArmPeriod pre;
  for (int k = 1; k <= pre_periods; ++k) {
    ++periods_integrated_;
    if (!stepper_.advance_period(k == pre_periods ? &pre : nullptr)) {
      failure = fmt::format("{} (pre-period {} of {})", stepper_.failure(), k, pre_periods);
      return false;
    }
  }
  shot.pre_loads = std::move(pre.loads);
  if (!stepper_.place(z0)) {  // the mechanical state back to z0, the cable's memory kept
    failure = stepper_.failure() + " (after the pre-periods)";
    return false;
  }
  ++periods_integrated_;
  if (!stepper_.advance_period(&shot.period)) {
    failure = stepper_.failure() + " (final period)";
    return false;
  }
  shot.end = stepper_.state();
  shot.ok = true;
  return true;
}

ArmSolution Shooting::solve(const Excitation& excitation, const Eigen::VectorXd* initial_state) {
  excitation.validate();
  if (initial_state && initial_state->size() != 4) {
    throw InvalidParameter(fmt::format("initial_state has {} values: expected 4 (x, phi, x', phi')",
                                       initial_state->size()));
  }
  if (initial_state && !initial_state->allFinite()) throw InvalidParameter("initial_state: expected finite values");
  const auto start_time = std::chrono::steady_clock::now();
  const double w = excitation.angular_frequency();
  const double l = arm_.cable().length();
  periods_integrated_ = 0;
  stepper_.set_excitation(excitation);

  ArmSolution solution;
  SolverSummary& summary = solution.summary;
  Eigen::Vector4d z =
      initial_state ? Eigen::Vector4d(*initial_state) : linear_discrete_start(arm_, excitation, options_.steps_per_period);
  int pre_periods = options_.pre_periods;
  Shot shot, trial;
  std::string failure;
  bool have_shot = shoot(z, pre_periods, shot, failure);
  if (!have_shot) summary.message = "at the starting point: " + failure;

  // Newton in the scaled unknowns D z0 with the scaled residual D (z(T) - z0). The
  // Jacobian is kept unscaled, of z(T) - z0 with respect to z0: by forward
  // differences, then updated by Broyden's rank-one formula after each accepted
  // step, and recomputed by differences when a Broyden step fails.
  Eigen::Matrix4d jacobian = Eigen::Matrix4d::Zero();
  bool jacobian_fresh = false, have_jacobian = false;
  while (have_shot) {
    const double measure = state_change_measure(shot.end - z, shot.period, w, l);
    const double defect = loads_change_measure(shot.period.loads, shot.pre_loads, l);
    summary.residual = measure;
    summary.periodicity_defect = defect;
    if (measure <= options_.tolerance && defect <= options_.periodicity_tolerance) {
      summary.converged = true;
      break;
    }
    // Solving S = 0 more precisely than the cable's memory has settled is wasted:
    // more pre-periods first.
    if (defect > options_.periodicity_tolerance && measure <= std::max(options_.tolerance, 0.01 * defect)) {
      if (pre_periods == options_.max_pre_periods) {
        summary.message = fmt::format(
            "the cable's memory is not settled after {} pre-periods (max_pre_periods): the loads of the final "
            "period differ from the last pre-period by {:.3g} (relative to the largest), tolerance {:.3g}; "
            "z(T) - z0 is {:.3g} of the amplitude",
            pre_periods, defect, options_.periodicity_tolerance, measure);
        break;
      }
      pre_periods = std::min(2 * pre_periods, options_.max_pre_periods);
      if (!shoot(z, pre_periods, shot, failure)) {
        summary.message = fmt::format("with {} pre-periods: {}", pre_periods, failure);
        have_shot = false;
      }
      continue;
    }
    if (summary.iterations == options_.max_iterations) {
      summary.message = fmt::format(
          "no convergence in {} Newton iterations: z(T) - z0 is {:.3g} of the amplitude (tolerance {:.3g}), "
          "loads of the final period vs the last pre-period {:.3g} (tolerance {:.3g}, {} pre-periods)",
          summary.iterations, measure, options_.tolerance, defect, options_.periodicity_tolerance, pre_periods);
      break;
    }
    ++summary.iterations;
    const double amplitude = std::max(amplitude_of(shot.period, l), 1e-300);
    Eigen::Vector4d scale;  // D
    scale << 1.0, l, 1.0 / w, l / w;
    scale /= amplitude;
    const Eigen::Vector4d residual = shot.end - z;
    const double norm = scale.cwiseProduct(residual).norm();
    bool accepted = false;
    while (!accepted) {
      if (!have_jacobian) {
        const double delta = options_.finite_difference_step;
        bool ok = true;
        for (int i = 0; i < 4 && ok; ++i) {
          Eigen::Vector4d z_i = z;
          z_i(i) += delta / scale(i);
          ok = shoot(z_i, pre_periods, trial, failure);
          if (ok) jacobian.col(i) = ((trial.end - z_i) - residual) * (scale(i) / delta);
        }
        if (!ok) {
          summary.message = fmt::format("finite-difference shot failed at Newton iteration {}: {}",
                                        summary.iterations, failure);
          break;
        }
        have_jacobian = jacobian_fresh = true;
      }
      Eigen::Vector4d step;
      const double reciprocal_condition = numerics::solve_checked(jacobian, Eigen::Vector4d(-residual), step);
      if (numerics::is_singular(reciprocal_condition, step)) {
        if (!jacobian_fresh) {
          have_jacobian = false;
          continue;
        }
        summary.message = fmt::format(
            "singular Jacobian at Newton iteration {} (reciprocal condition number {:.3g}; z(T) - z0 is {:.3g} of the "
            "amplitude): no periodic solution is determined here",
            summary.iterations, reciprocal_condition, measure);
        break;
      }
      double alpha = 1.0;
      // A Broyden Jacobian gets the full step only: if that fails, differences again.
      const int halvings = jacobian_fresh ? options_.max_halvings : 0;
      for (int halving = 0; halving <= halvings; ++halving, alpha *= 0.5) {
        const Eigen::Vector4d z_try = z + alpha * step;
        if (shoot(z_try, pre_periods, trial, failure) &&
            scale.cwiseProduct(trial.end - z_try).norm() <= (1.0 - 1e-4 * alpha) * norm) {
          // Broyden: J += (dS - J dz) dz^T / (dz^T dz), in the scaled unknowns.
          const Eigen::Vector4d dz = alpha * step;
          const Eigen::Vector4d ds = (trial.end - z_try) - residual;
          const Eigen::Vector4d dz_scaled = scale.cwiseProduct(dz);
          jacobian += (ds - jacobian * dz) * (scale.cwiseProduct(dz_scaled)).transpose() / dz_scaled.squaredNorm();
          jacobian_fresh = false;
          z = z_try;
          std::swap(shot, trial);
          accepted = true;
          break;
        }
      }
      if (accepted) break;
      if (!jacobian_fresh) {
        have_jacobian = false;
        continue;
      }
      summary.message = fmt::format("line search failed at Newton iteration {} (z(T) - z0 is {:.3g} of the amplitude)",
                                    summary.iterations, measure);
      break;
    }
    if (!accepted) break;
  }
  summary.periods = pre_periods + 1;
  if (shot.ok) {
    solution.period = shot.period;
    summary.energy_error = energy_error(solution.period, excitation);
  }
  solution.unknowns = z;
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return solution;
}

}  // namespace stockbridge::damper
