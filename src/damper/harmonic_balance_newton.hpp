#pragma once
// Harmonic balance's Newton solve for one excitation (harmonic_balance_newton.cpp),
// private to the damper module: HarmonicBalance::solve runs it.

#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "../numerics/updated_factors.hpp"
#include "stockbridge/damper/harmonic_balance.hpp"

namespace stockbridge::damper {

/// Newton's method for one excitation, in named steps. The cable's start state,
/// the current evaluation and the Newton matrix are its own; the stored force
/// Jacobian lives in the caller's memory.
class NewtonSolve {
 public:
  NewtonSolve(const HarmonicBalance& model, const Excitation& excitation, HarmonicBalanceMemory& memory,
              HarmonicBalanceWorkspace& workspace, SolverSummary& summary)
      : model_(model),
        options_(model.options()),
        excitation_(excitation),
        scale_(model.force_scale(excitation)),
        memory_(memory),
        workspace_(workspace),
        summary_(summary),
        periodic_newton_(model.uses_periodic_newton()),
        start_(memory.cable_state) {}

  /// Runs Newton from q (updated in place); true when converged. `current()` is the
  /// last successful evaluation.
  bool run(Eigen::VectorXd& q);
  HarmonicBalanceEvaluation& current() { return current_; }
  const std::optional<cable::CableState>& cable_state() const { return start_; }

 private:
  /// Evaluates at q from the chained start state; on success adopts it as the
  /// current evaluation (the next start is its end state) and sets the Newton
  /// matrix, exact when `exact` or else from the stored force Jacobian.
  bool adopt_evaluation(const Eigen::VectorXd& q, bool exact, std::string_view stage);
  bool fail(Termination termination, std::string where = {});
  /// The residual and the periodicity defect of the current evaluation both within tolerance.
  bool criteria_met() const {
    return norm_ <= options_.tolerance && current_.cable.periodicity_defect <= options_.periodicity_tolerance;
  }
  enum class Finish { converged, not_yet, failed };
  /// Both criteria met: records the determinant sign and ends; where the sign
  /// changed since the last solution it is confirmed with an exact evaluation,
  /// whose criteria must hold too (not_yet: Newton goes on).
  Finish finish(const Eigen::VectorXd& q);
  /// The equations hold but the memory has not settled: more periods, no step.
  bool settle(const Eigen::VectorXd& q);
  enum class StepOutcome { accepted, retry_with_exact_jacobian, failed };
  /// One Newton step with a backtracking line search.
  StepOutcome step(Eigen::VectorXd& q);
  /// Broyden's rank-one update of the stored force Jacobian after an accepted step
  /// with a stored one: the secant condition J dq = dr along the step.
  void broyden_update(const Eigen::VectorXd& q);
  double norm_of(const HarmonicBalanceEvaluation& e) const { return e.residual.lpNorm<Eigen::Infinity>() / scale_; }
  /// Newton on the periodic state: from an exact evaluation, the stored terms and
  /// the force Jacobian with the state eliminated (false, nothing stored: G_z - I
  /// singular, its reciprocal condition below 1e-12).
  bool store_periodic_state_terms(const HarmonicBalanceEvaluation& e);
  /// The residual Newton steps on: R, less R_z D^-1 G under Newton on the periodic state.
  Eigen::VectorXd effective_residual(const HarmonicBalanceEvaluation& e) const;
  /// Where the next evaluation after `e` starts for a step dq (empty: none): its end
  /// state, or under Newton on the periodic state that moved to z + dz, dz = -D^-1 (G
  /// + G_q dq) (the end state where the law refuses the move).
  cable::CableState next_start(const HarmonicBalanceEvaluation& e, const Eigen::VectorXd* dq) const;
  /// Under Newton on the periodic state, with the state terms and the q of the last
  /// solution stored: moves the start (the periodic state there) to the state the
  /// terms predict periodic at q, z - D^-1 G_q (q - q_last) in the law's coordinates
  /// (kept where the law refuses the move). Along a sweep the first pass then starts
  /// nearer its periodic state: on slenderpy's damper the first pass's defect falls
  /// from a median of 2.6e-2 to 3.3e-3, and a point takes 4.9 passes instead of 5.4.
  void predict_periodic_start(const Eigen::VectorXd& q);
  /// Sign of det of the Newton matrix, from its factors (factored here where none are ready).
  int newton_matrix_sign() {
    if (!factors_.ready()) factors_.factor(jacobian_);
    return factors_.determinant_sign();
  }

  const HarmonicBalance& model_;
  const HarmonicBalanceOptions& options_;
  const Excitation& excitation_;
  const double scale_;
  HarmonicBalanceMemory& memory_;
  HarmonicBalanceWorkspace& workspace_;
  SolverSummary& summary_;
  /// From here on, chained periods (and the half-wave's centring) instead of Newton
  /// on the periodic state; the stored state terms are dropped with it.
  void chain_periods();

  PeriodicStart mode() const { return periodic_newton_ ? PeriodicStart::newton : PeriodicStart::chained; }
  /// Passes an evaluation drives: one under Newton on the periodic state, else options' periods.
  int passes() const { return periodic_newton_ ? 1 : options_.periods; }

  bool periodic_newton_;
  std::optional<cable::CableState> start_;  // where the cable's next evaluation starts (empty: virgin)
  Eigen::VectorXd effective_;                 // the current evaluation's effective_residual
  HarmonicBalanceEvaluation current_;
  Eigen::MatrixXd jacobian_;
  numerics::UpdatedFactors factors_;  // of jacobian_ where ready (its Broyden updates as rank-one changes)
  bool exact_ = false;  // the Newton matrix is exact at the current point
  double norm_ = 0.0;   // of the current residual, relative to the force scale
  int settling_periods_ = 0;
  double last_settling_defect_ = std::numeric_limits<double>::infinity();  // before the last settling pass
  Eigen::VectorXd step_start_, step_start_residual_;  // where the last step started
};

}  // namespace stockbridge::damper
