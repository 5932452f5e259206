#include "stockbridge/damper/arclength.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <Eigen/LU>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/linear_solve.hpp"

namespace stockbridge::damper {

namespace {

/// The branch in scaled unknowns y = (q / scale_q, W / scale_w), so that a unit
/// step changes the response and the frequency by comparable amounts.
class Branch {
 public:
  Branch(const HarmonicBalance& model, double velocity, HarmonicBalanceWorkspace& workspace, Eigen::VectorXd scale,
         std::optional<cable::CableState> cable_state)
      : model_(model),
        velocity_(velocity),
        workspace_(workspace),
        scale_(std::move(scale)),
        p_count_(model.unknown_count()),
        cable_state_(std::move(cable_state)) {}

  Eigen::VectorXd unknowns_of(const Eigen::VectorXd& y) const {
    return y.head(p_count_).cwiseProduct(scale_.head(p_count_));
  }
  double angular_frequency_of(const Eigen::VectorXd& y) const { return y(p_count_) * scale_(p_count_); }

  /// Evaluates R, J and dR/dW at y from the branch's cable state, which then moves
  /// on to the evaluation's end state. Converged; no_progress where the branch has
  /// turned back to W <= 0; inner_failure where the cable failed.
  SolverSummary evaluate(const Eigen::VectorXd& y, HarmonicBalanceEvaluation& out) {
    const double w = angular_frequency_of(y);
    if (!(w > 0.0)) return summary_of(Termination::no_progress, "the branch turned back to W <= 0");
    out = model_.evaluate(excitation_at(w), unknowns_of(y), cable_state_ ? &*cable_state_ : nullptr,
                          model_.options().periods, HarmonicBalance::kJacobian | HarmonicBalance::kFrequency,
                          workspace_);
    if (!out.ok()) return summary_of(Termination::inner_failure, "the cable along the branch: " + brief_report(out.cable));
    cable_state_ = out.end_state;
    force_jacobian_ = out.force_jacobian;
    return summary_of(Termination::converged);
  }

  /// The unit tangent [J, R_W] t = 0 with t_W = +1 before normalisation, in scaled unknowns.
  Eigen::VectorXd tangent(const HarmonicBalanceEvaluation& e, double w) const {
    const Eigen::MatrixXd j = model_.jacobian(excitation_at(w), e.force_jacobian);
    Eigen::VectorXd t(p_count_ + 1);
    t.head(p_count_) = -(j * scale_.head(p_count_).asDiagonal()).partialPivLu().solve(e.d_frequency * scale_(p_count_));
    t(p_count_) = 1.0;
    return t.normalized();
  }

  /// One corrector: Newton on [R(q, W); t . (y - y_pred)] = 0 (scaled), letting the
  /// cable's memory settle at the point. Converged (then `last` is the evaluation
  /// there), or why not: the evaluation's failure, singular_jacobian,
  /// not_periodic (the memory did not settle), max_iterations.
  SolverSummary correct(Eigen::VectorXd& y, const Eigen::VectorXd& tangent, const Eigen::VectorXd& y_pred,
                        HarmonicBalanceEvaluation& last) {
    const HarmonicBalanceOptions& options = model_.options();
    Eigen::MatrixXd bordered(p_count_ + 1, p_count_ + 1);
    Eigen::VectorXd g(p_count_ + 1);
    int settling_periods = 0;
    const int max_iterations = std::min(options.max_iterations, 25);  // a failed corrector halves the step instead
    for (int iteration = 0; iteration <= max_iterations; ++iteration) {
      if (SolverSummary evaluated = evaluate(y, last); !evaluated.converged()) return evaluated;
      const double w = angular_frequency_of(y);
      const double force = model_.force_scale(excitation_at(w));
      const double constraint = tangent.dot(y - y_pred);
      const double norm = last.residual.lpNorm<Eigen::Infinity>() / force;
      if (norm <= options.tolerance && std::abs(constraint) <= 1e-10) {
        if (last.cable.periodicity_defect <= options.periodicity_tolerance) return summary_of(Termination::converged);
        if (settling_periods >= options.max_settling_periods) {
          return summary_of(Termination::not_periodic, "the cable's memory did not settle at the corrected point");
        }
        settling_periods += options.periods;  // let the cable's memory settle at this point
        continue;
      }
      bordered.topLeftCorner(p_count_, p_count_) =
          model_.jacobian(excitation_at(w), last.force_jacobian) * scale_.head(p_count_).asDiagonal() / force;
      bordered.topRightCorner(p_count_, 1) = last.d_frequency * (scale_(p_count_) / force);
      bordered.bottomRows(1) = tangent.transpose();
      g.head(p_count_) = last.residual / force;
      g(p_count_) = constraint;
      Eigen::VectorXd step;
      if (numerics::is_singular(numerics::solve_checked(bordered, Eigen::VectorXd(-g), step), step)) {
        return summary_of(Termination::singular_jacobian, "the bordered corrector matrix");
      }
      y += step;
    }
    return summary_of(Termination::max_iterations, "the corrector");
  }

  /// The solver's memory at the current point of the branch.
  HarmonicBalanceMemory memory() const { return {cable_state_, force_jacobian_, {}, 0, {}}; }
  const std::optional<cable::CableState>& cable_state() const { return cable_state_; }
  void set_cable_state(std::optional<cable::CableState> state) { cable_state_ = std::move(state); }

 private:
  Excitation excitation_at(double w) const { return Excitation::from_velocity(w / (2.0 * std::numbers::pi), velocity_); }

  const HarmonicBalance& model_;
  const double velocity_;
  HarmonicBalanceWorkspace& workspace_;
  const Eigen::VectorXd scale_;
  const Eigen::Index p_count_;
  std::optional<cable::CableState> cable_state_;  // where the branch's next evaluation starts
  Eigen::MatrixXd force_jacobian_;                // of the latest evaluation
};

}  // namespace

BranchCrossings continue_along_branch(const HarmonicBalance& model, double velocity, const BranchPoint& from,
                                      double target_hz, HarmonicBalanceWorkspace& workspace, int max_steps) {
  require_positive("velocity", velocity, "m/s");
  const Eigen::Index p_count = model.unknown_count();
  const double w0 = 2.0 * std::numbers::pi * from.frequency_hz, w_target = 2.0 * std::numbers::pi * target_hz;
  const double direction = w_target > w0 ? 1.0 : -1.0;
  Eigen::VectorXd scale(p_count + 1);
  scale.head(p_count).setConstant(std::max(from.unknowns.lpNorm<Eigen::Infinity>(), 1e-12));
  scale(p_count) = std::abs(w_target - w0) > 0.0 ? std::abs(w_target - w0) : w0;
  Branch branch(model, velocity, workspace, scale, from.memory.cable_state);
  Eigen::VectorXd y(p_count + 1);
  y.head(p_count) = from.unknowns.cwiseQuotient(scale.head(p_count));
  y(p_count) = w0 / scale(p_count);

  BranchCrossings crossings;
  HarmonicBalanceEvaluation at;
  if (!branch.evaluate(y, at).converged()) return crossings;
  Eigen::VectorXd tangent = branch.tangent(at, w0);
  if (!tangent.allFinite()) return crossings;
  if (tangent(p_count) * direction < 0.0) tangent = -tangent;
  double ds = 0.25;
  for (int step = 0; step < max_steps && ds > 1e-6; ++step) {
    const Eigen::VectorXd y_pred = y + ds * tangent;
    Eigen::VectorXd y_new = y_pred;
    const std::optional<cable::CableState> before = branch.cable_state();
    if (!branch.correct(y_new, tangent, y_pred, at).converged()) {
      branch.set_cable_state(before);
      ds *= 0.5;
      continue;
    }
    const double wa = branch.angular_frequency_of(y), wb = branch.angular_frequency_of(y_new);
    if ((wa - w_target) * (wb - w_target) <= 0.0 && wa != w_target) {
      // Polish at exactly the target from the interpolated point, continuing the branch's memory.
      const double t = (w_target - wa) / (wb - wa);
      const Eigen::VectorXd q_guess = branch.unknowns_of((1.0 - t) * y + t * y_new);
      HarmonicBalanceMemory memory = branch.memory();
      ArmSolution polished =
          model.solve(Excitation::from_velocity(target_hz, velocity), q_guess, memory, workspace);
      if (polished.summary.converged()) {
        polished.note = "reached by arclength continuation";
        crossings.solutions.push_back(std::move(polished));
        crossings.memory = std::move(memory);
      }
    }
    Eigen::VectorXd new_tangent = branch.tangent(at, wb);
    if (!new_tangent.allFinite()) break;
    if (new_tangent.dot(tangent) < 0.0) new_tangent = -new_tangent;
    tangent = new_tangent;
    y = y_new;
    ds = std::min(2.0 * ds, 1.0);
    // Done once the branch has passed the target for good (moving on, beyond it).
    if (!crossings.solutions.empty() && direction * (wb - w_target) > 0.0 && direction * tangent(p_count) > 0.0 &&
        direction * (wb - w_target) > 0.5 * std::abs(w_target - w0)) {
      break;
    }
  }
  for (ArmSolution& s : crossings.solutions) s.branches = static_cast<int>(crossings.solutions.size());
  return crossings;
}

}  // namespace stockbridge::damper
