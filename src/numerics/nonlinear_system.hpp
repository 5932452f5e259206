#pragma once
// A small system of nonlinear equations r(x) = 0 (n equations in n unknowns) by
// Powell's hybrid method: a dogleg between the Newton and the steepest-descent
// step within a trust region, with Broyden's rank-one updates of the Jacobian
// between the caller's Jacobians (MINPACK's hybrj, as Eigen's unsupported
// NonLinearOptimization module ports it). The span balance solves its dampers'
// clamp velocities with it. Converged means max |r_i| <= tolerance at a point the
// residual was evaluated at; that point is returned, never a step beyond it.

#include <functional>

#include <Eigen/Core>

#include "stockbridge/numerics/solver_summary.hpp"

namespace stockbridge::numerics {

struct NonlinearSystemOptions {
  double tolerance = 1e-10;   ///< on max |r_i|
  int max_evaluations = 100;  ///< of the residual
  /// The trust region's first radius in x (max-norm steps are at most about this).
  double initial_step = 1.0;
  /// solve_fixed_point: full Newton steps on the caller's Jacobian (taken afresh at
  /// every point) first, at most this many, while each step is within initial_step
  /// (max norm) and at least halves max |r|;
  /// then the hybrid method from the best point, within the evaluations left. Where
  /// the caller's Jacobian is exact or nearly so (the span polish's), Newton needs
  /// fewer residuals than the hybrid method's Broyden updates. 0: the hybrid method alone.
  int newton_steps = 0;
};

/// The residual at x into r; false where it cannot be evaluated (the solve stops
/// with inner_failure, the caller keeps its own reason). An x with an entry that is
/// not a number (a step off a singular Jacobian) is never passed: the solve stops so.
using Residual = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& r)>;
/// The Jacobian dr/dx at x (a point the residual was evaluated at); false: as above.
using ResidualJacobian = std::function<bool(const Eigen::VectorXd& x, Eigen::MatrixXd& jacobian)>;

struct NonlinearSystemResult {
  Eigen::VectorXd x;         ///< the best point evaluated (the solution where converged)
  Eigen::VectorXd residual;  ///< r there
  /// converged; max_iterations (evaluations exhausted); no_progress (the trust region
  /// shrank to nothing or the residual stopped falling); inner_failure (the residual
  /// or Jacobian could not be evaluated). residual = max |r_i|, evaluations, jacobians.
  SolverSummary summary;
  /// solve_fixed_point: where the residual jumps (empty: no jump found), and the
  /// residual there.
  Eigen::VectorXd jump_at;
  Eigen::VectorXd jump_residual;
};

NonlinearSystemResult solve_nonlinear_system(const Residual& residual, const ResidualJacobian& jacobian,
                                             const Eigen::VectorXd& start, const NonlinearSystemOptions& options);

/// A fixed point u = F(u) of a bounded map, as the root of h(u) = F(u) - u (the
/// residual): far from the fixed points h points toward them. The system by
/// solve_nonlinear_system; where that stalls at a minimum of |h| off the root
/// (no_progress), a march from there along d = h / max|h| in doubling steps until h
/// turns against it (h . d <= 0), the root of h(u + t d) . d on the last step (TOMS
/// 748: in one dimension the fixed point itself), and the system again from there,
/// all within options.max_evaluations (options.newton_steps: Newton's method first).
/// Where that root closes on a jump of h (a bracket narrower than the tolerance with
/// |h| above `noise`): no_progress, `where` says where and by how much. `noise`: the
/// residual's own scatter, accepted as converged where such a bracket closes.
NonlinearSystemResult solve_fixed_point(const Residual& residual, const ResidualJacobian& jacobian,
                                        const Eigen::VectorXd& start, const NonlinearSystemOptions& options,
                                        double noise = 0.0);

}  // namespace stockbridge::numerics
