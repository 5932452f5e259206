// Harmonic balance's Newton solve in named steps (harmonic_balance_newton.hpp): the
// evaluation adopted, the criteria, the settling of the memory, the step with its
// line search, Broyden's update and Newton on the periodic state.
#include "harmonic_balance_newton.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/linear_solve.hpp"

namespace stockbridge::damper {

bool NewtonSolve::fail(Termination termination, std::string where) {
  summary_.termination = termination;
  summary_.where = std::move(where);
  return false;
}

bool NewtonSolve::adopt_evaluation(const Eigen::VectorXd& q, bool exact, std::string_view stage) {
  const unsigned derivatives = exact ? HarmonicBalance::kJacobian : HarmonicBalance::kNone;
  HarmonicBalanceEvaluation e =
      model_.evaluate(excitation_, q, start_ ? &*start_ : nullptr, passes(), derivatives, workspace_, mode());
  ++summary_.evaluations;
  summary_.jacobians += exact;
  summary_.periods += passes();
  if (e.cable.termination == Termination::non_finite) {
    return fail(Termination::non_finite, fmt::format("{} {}", stage, e.cable.where));
  }
  if (!e.ok()) return fail(Termination::inner_failure, fmt::format("{}: {}", stage, brief_report(e.cable)));
  bool chain = false;
  if (exact) {
    if (!periodic_newton_) {
      memory_.force_jacobian = std::move(e.force_jacobian);
    } else if (!store_periodic_state_terms(e)) {
      // G_z - I singular: a memory the pass barely forgets (whole periods near
      // stick), which no Newton step on the state resolves; chained periods settle it.
      memory_.force_jacobian = e.force_jacobian.leftCols(model_.unknown_count());
      chain = true;
    }
  }
  start_ = next_start(e, nullptr);
  current_ = std::move(e);
  norm_ = norm_of(current_);
  effective_ = effective_residual(current_);
  if (chain) chain_periods();
  model_.assemble_jacobian(excitation_, memory_.force_jacobian, jacobian_);
  factors_.clear();
  exact_ = exact;
  if (!current_.residual.allFinite()) return fail(Termination::non_finite, fmt::format("{} in the residual", stage));
  return true;
}

NewtonSolve::Finish NewtonSolve::finish(const Eigen::VectorXd& q) {
  int sign = newton_matrix_sign();
  if (!exact_ && sign != memory_.jacobian_sign) {
    // A fold is suspected: confirm the sign with the exact Jacobian.
    if (!adopt_evaluation(q, true, "confirming the Jacobian's sign")) return Finish::failed;
    if (!criteria_met()) return Finish::not_yet;
    sign = newton_matrix_sign();
  }
  memory_.jacobian_sign = sign;
  summary_.residual = norm_;
  summary_.periodicity_defect = current_.cable.periodicity_defect;
  summary_.termination = Termination::converged;
  return Finish::converged;
}

bool NewtonSolve::settle(const Eigen::VectorXd& q) {
  if (settling_periods_ >= options_.max_settling_periods) {
    const std::string where =
        norm_ <= options_.tolerance
            ? std::string("the equations hold")
            : fmt::format("the residual {:.3g} below {} times the periodicity defect {:.3g}", norm_,
                          options_.settle_ratio, current_.cable.periodicity_defect);
    return fail(Termination::not_periodic,
                fmt::format("({}; {} more periods at the same coefficients did not settle the cable's memory)", where,
                            settling_periods_));
  }
  settling_periods_ += options_.periods;
  // Newton's move of the start stalls where the pass's map has a kink (a section
  // whose moment reverses right at the period's start): there the rest of the solve
  // chains periods from the last end state, as without Newton on the state.
  if (periodic_newton_ && current_.cable.periodicity_defect > 0.5 * last_settling_defect_) chain_periods();
  last_settling_defect_ = current_.cable.periodicity_defect;
  return adopt_evaluation(q, false, "while settling");
}

NewtonSolve::StepOutcome NewtonSolve::step(Eigen::VectorXd& q) {
  if (!factors_.ready()) factors_.factor(jacobian_);
  const Eigen::VectorXd direction = factors_.solve(-effective_);
  if (exact_) {
    // Exact: adopted since the last factorisation, so no Broyden change on the factors.
    const double reciprocal_condition = factors_.reciprocal_condition();
    if (numerics::is_singular(reciprocal_condition, direction)) {
      summary_.reciprocal_condition = reciprocal_condition;
      fail(Termination::singular_jacobian);
      return StepOutcome::failed;
    }
  } else {
    // A stored Jacobian's step is tried once and an exact Jacobian decides if it
    // fails, so its conditioning is not estimated (that cost half a factorisation);
    // a singular one gives a non-finite step.
    if (!direction.allFinite()) return StepOutcome::retry_with_exact_jacobian;
  }
  const double norm2 = effective_.norm();
  // With a stored Jacobian only the full step is tried: if it fails, an exact one is cheaper than halving.
  // Under Newton on the periodic state chained periods take over sooner (run()).
  const int halvings = !exact_ ? 1 : periodic_newton_ ? 6 : 30;
  double alpha = 1.0;
  for (int halving = 0; halving < halvings; ++halving, alpha *= 0.5) {
    const Eigen::VectorXd dq = alpha * direction;
    const Eigen::VectorXd q_try = q + dq;
    const cable::CableState trial_start = next_start(current_, &dq);
    HarmonicBalanceEvaluation trial =
        model_.evaluate(excitation_, q_try, &trial_start, passes(), HarmonicBalance::kNone, workspace_, mode());
    ++summary_.evaluations;
    summary_.periods += passes();
    if (!trial.ok()) continue;
    // Accept a decrease, or a step that meets the tolerance.
    Eigen::VectorXd trial_effective = effective_residual(trial);
    if (trial_effective.norm() <= (1.0 - 1e-4 * alpha) * norm2 || norm_of(trial) <= options_.tolerance) {
      q = q_try;
      start_ = next_start(trial, nullptr);
      current_ = std::move(trial);
      effective_ = std::move(trial_effective);
      return StepOutcome::accepted;
    }
  }
  if (!exact_) return StepOutcome::retry_with_exact_jacobian;
  fail(Termination::line_search_failed);
  return StepOutcome::failed;
}

void NewtonSolve::predict_periodic_start(const Eigen::VectorXd& q) {
  if (!periodic_newton_ || !start_ || memory_.periodic_state.empty() || memory_.unknowns.size() != q.size()) return;
  // The stored state is periodic at the stored q. Staying periodic, z_end = z, to first
  // order: G_z dz + G_q dq = dz, so dz = -D^-1 G_q dq (D = G_z - I).
  const Eigen::VectorXd move = -(memory_.periodic_state.start_by_coefficients * (q - memory_.unknowns));
  cable::CableState moved = *start_;
  if (model_.arm().cable().law().shift(model_.arm().cable(), moved, move)) start_ = std::move(moved);
}

bool NewtonSolve::run(Eigen::VectorXd& q) {
  predict_periodic_start(q);
  const bool stored = memory_.force_jacobian.size() > 0 && (!periodic_newton_ || !memory_.periodic_state.empty());
  // Under Newton on the periodic state the stored Jacobian drifts from point to point.
  const bool aged = periodic_newton_ && options_.stored_jacobian_points > 0 &&
                    memory_.jacobian_points >= options_.stored_jacobian_points;
  if (!adopt_evaluation(q, !stored || aged, "at the starting point")) return false;
  while (true) {
    summary_.residual = norm_;
    summary_.periodicity_defect = current_.cable.periodicity_defect;
    if (criteria_met()) {
      const Finish outcome = finish(q);
      if (outcome == Finish::not_yet) continue;
      return outcome == Finish::converged;
    }
    // The equations hold, or the residual is mostly the memory's drift (a step cannot
    // remove it: a stored Jacobian's step was then mostly rejected, and an exact one
    // re-evaluated): let the memory settle at these coefficients first.
    if (norm_ <= options_.tolerance ||
        (!periodic_newton_ && norm_ < options_.settle_ratio * current_.cable.periodicity_defect)) {
      if (!settle(q)) return false;
      continue;
    }
    if (summary_.newton_iterations == options_.max_iterations) return fail(Termination::max_iterations);
    ++summary_.newton_iterations;
    const double previous_norm = norm_;
    step_start_ = q;
    step_start_residual_ = effective_;
    const StepOutcome outcome = step(q);
    if (outcome == StepOutcome::failed) {
      if (!periodic_newton_ || summary_.termination != Termination::line_search_failed) return false;
      // Newton's move of the start can leave the piece on which the pass's map is
      // smooth (a section reversing at the period's start): chain periods instead.
      --summary_.newton_iterations;
      summary_.termination = Termination::not_run;
      summary_.where.clear();
      chain_periods();
      if (!adopt_evaluation(q, true, "chaining periods")) return false;
      continue;
    }
    if (outcome == StepOutcome::retry_with_exact_jacobian) {
      --summary_.newton_iterations;
      if (!adopt_evaluation(q, true, "refreshing the Jacobian")) return false;
      continue;
    }
    norm_ = norm_of(current_);
    // Slow progress means the Jacobian belongs to another piece: refresh it.
    const bool refresh = norm_ > options_.jacobian_refresh_ratio * previous_norm && norm_ > options_.tolerance;
    if (refresh) {
      if (!adopt_evaluation(q, true, "refreshing the Jacobian")) return false;
    } else {
      broyden_update(q);
      model_.assemble_jacobian(excitation_, memory_.force_jacobian, jacobian_);
      exact_ = false;
    }
  }
}

void NewtonSolve::chain_periods() {
  periodic_newton_ = false;
  memory_.periodic_state = {};
  start_ = current_.end_state;
  effective_ = current_.residual;
}

bool NewtonSolve::store_periodic_state_terms(const HarmonicBalanceEvaluation& e) {
  const Eigen::Index n = model_.unknown_count(), m = e.state_gap.size();
  Eigen::MatrixXd d = e.state_jacobian.rightCols(m);
  d.diagonal().array() -= 1.0;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(d);
  if (!(lu.rcond() > 1e-12)) return false;
  PeriodicStateTerms& terms = memory_.periodic_state;
  terms.start_by_gap = lu.inverse();
  if (!terms.start_by_gap.allFinite()) return false;
  terms.start_by_coefficients.noalias() = terms.start_by_gap * e.state_jacobian.leftCols(n);
  terms.residual_by_start = e.force_jacobian.rightCols(m);
  memory_.force_jacobian = e.force_jacobian.leftCols(n);
  memory_.force_jacobian.noalias() -= terms.residual_by_start * terms.start_by_coefficients;
  return true;
}

Eigen::VectorXd NewtonSolve::effective_residual(const HarmonicBalanceEvaluation& e) const {
  if (!periodic_newton_ || memory_.periodic_state.empty()) return e.residual;
  const PeriodicStateTerms& terms = memory_.periodic_state;
  const Eigen::VectorXd start_move = terms.start_by_gap * e.state_gap;
  return e.residual - terms.residual_by_start * start_move;
}

cable::CableState NewtonSolve::next_start(const HarmonicBalanceEvaluation& e, const Eigen::VectorXd* dq) const {
  if (!periodic_newton_ || memory_.periodic_state.empty()) return e.end_state;
  const PeriodicStateTerms& terms = memory_.periodic_state;
  // From the end state (z + G) to z + dz.
  Eigen::VectorXd move = -(terms.start_by_gap * e.state_gap) - e.state_gap;
  if (dq) move.noalias() -= terms.start_by_coefficients * *dq;
  cable::CableState start = e.end_state;
  if (!model_.arm().cable().law().shift(model_.arm().cable(), start, move)) return e.end_state;
  return start;
}

void NewtonSolve::broyden_update(const Eigen::VectorXd& q) {
  if (!options_.broyden) return;
  const Eigen::VectorXd dq = q - step_start_;
  const double dq2 = dq.squaredNorm();
  if (!(dq2 > 0.0)) return;
  // The inertia terms are linear: the whole Newton matrix's secant error is the force Jacobian's.
  const Eigen::VectorXd change = ((effective_ - step_start_residual_) - jacobian_ * dq) / dq2;
  memory_.force_jacobian.noalias() += change * dq.transpose();
  if (factors_.ready()) factors_.update(change, dq);
}

}  // namespace stockbridge::damper
