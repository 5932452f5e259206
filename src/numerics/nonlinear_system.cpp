#include "nonlinear_system.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/LU>
#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>
#include <unsupported/Eigen/NonLinearOptimization>

namespace stockbridge::numerics {

namespace {

/// hybrj's functor: counts, keeps the best point evaluated, and stops the solver
/// (a negative return) once a residual meets the tolerance or cannot be evaluated.
class SystemFunctor {
 public:
  SystemFunctor(const Residual& residual, const ResidualJacobian& jacobian, double tolerance)
      : residual_(residual), jacobian_(jacobian), tolerance_(tolerance) {}

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    ++evaluations_;
    // A step that is not a number (a singular Jacobian's) is never handed to the residual.
    if (!x.allFinite() || !residual_(x, r) || !r.allFinite()) {
      failed_ = true;
      return -1;
    }
    const double size = r.cwiseAbs().maxCoeff();
    if (!(size >= best_size_)) {
      best_size_ = size;
      best_x_ = x;
      best_r_ = r;
    }
    if (size <= tolerance_) {
      converged_ = true;
      return -1;
    }
    return 0;
  }
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jacobian) {
    ++jacobians_;
    if (!jacobian_(x, jacobian) || !jacobian.allFinite()) {
      failed_ = true;
      return -1;
    }
    return 0;
  }

  int evaluations() const { return evaluations_; }
  int jacobians() const { return jacobians_; }
  bool converged() const { return converged_; }
  bool failed() const { return failed_; }
  double best_size() const { return best_size_; }
  const Eigen::VectorXd& best_x() const { return best_x_; }
  const Eigen::VectorXd& best_r() const { return best_r_; }

 private:
  const Residual& residual_;
  const ResidualJacobian& jacobian_;
  double tolerance_;
  int evaluations_ = 0;
  int jacobians_ = 0;
  bool converged_ = false;
  bool failed_ = false;
  double best_size_ = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_x_, best_r_;
};

Termination termination_of(Eigen::HybridNonLinearSolverSpace::Status status) {
  using namespace Eigen::HybridNonLinearSolverSpace;
  switch (status) {
    case TooManyFunctionEvaluation: return Termination::max_iterations;
    case ImproperInputParameters: return Termination::inner_failure;
    default: return Termination::no_progress;  // converged in x, tolerance too small, no progress
  }
}

}  // namespace

NonlinearSystemResult solve_nonlinear_system(const Residual& residual, const ResidualJacobian& jacobian,
                                             const Eigen::VectorXd& start, const NonlinearSystemOptions& options) {
  SystemFunctor functor(residual, jacobian, options.tolerance);
  Eigen::HybridNonLinearSolver<SystemFunctor> solver(functor);
  // Unit scaling, so that the trust region is a radius in x itself; the first radius
  // is factor * |x|.
  solver.useExternalScaling = true;
  solver.diag = Eigen::VectorXd::Ones(start.size());
  const double size = start.norm();
  solver.parameters.factor = options.initial_step / (size > 0.0 ? size : 1.0);
  solver.parameters.maxfev = options.max_evaluations;
  solver.parameters.xtol = 0.0;  // the residual's tolerance decides, in the functor
  Eigen::VectorXd x = start;
  auto status = solver.solveInit(x);
  while (status == Eigen::HybridNonLinearSolverSpace::Running) status = solver.solveOneStep(x);

  NonlinearSystemResult result;
  result.summary.evaluations = functor.evaluations();
  result.summary.jacobians = functor.jacobians();
  result.summary.residual = functor.best_size();
  result.x = functor.best_x();
  result.residual = functor.best_r();
  if (functor.converged()) {
    result.summary.termination = Termination::converged;
  } else if (functor.failed()) {
    result.summary.termination = Termination::inner_failure;
  } else {
    result.summary.termination = termination_of(status);
  }
  return result;
}

namespace {

/// The residual counted and the best point kept, outside the hybrid method.
struct CountedResidual {
  const Residual& residual;
  const NonlinearSystemOptions& options;
  NonlinearSystemResult& best;
  int evaluations = 0;
  bool failed = false;
  bool within_noise = false;  ///< a bracket closed with |h| within the residual's scatter
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> known{};  ///< every point evaluated, with its r

  /// r at x; false (failed) where it cannot be evaluated. A point evaluated before is
  /// not evaluated again (the hybrid method evaluates its start, the Newton phase's
  /// best point, and its first step may be the Newton step already taken): its r is
  /// known.
  bool operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    for (const auto& [known_x, known_r] : known) {
      if (known_x == x) {
        r = known_r;
        return true;
      }
    }
    ++evaluations;
    if (!x.allFinite() || !residual(x, r) || !r.allFinite()) return !(failed = true);
    known.emplace_back(x, r);
    const double size = r.cwiseAbs().maxCoeff();
    if (!(size >= best.summary.residual)) {
      best.x = x;
      best.residual = r;
      best.summary.residual = size;
    }
    return true;
  }
  bool converged() const { return within_noise || best.summary.residual <= options.tolerance; }
  bool exhausted() const { return evaluations >= options.max_evaluations; }
  /// Whether the search is over (converged, failed or out of evaluations).
  bool over() const { return failed || converged() || exhausted(); }
};

/// Thrown out of the root search along a march when the search is over.
struct SearchOver {};

/// The march of solve_fixed_point from x along the residual r there, then the
/// root along the last step. Returns where to solve the system again, or none:
/// the search is over, or the root closed on a jump (`best.jump_at` says where).
std::optional<Eigen::VectorXd> march_along_residual(CountedResidual& h, Eigen::VectorXd x, const Eigen::VectorXd& r,
                                                    double noise) {
  const Eigen::VectorXd d = r / r.cwiseAbs().maxCoeff();
  double step = std::max(r.cwiseAbs().maxCoeff(), 0.05);
  double phi_a = r.dot(d), phi_b = 0.0;
  Eigen::VectorXd rb;
  for (;; step *= 2.0) {
    if (h.exhausted() || !h(x + step * d, rb) || h.over()) return std::nullopt;
    phi_b = rb.dot(d);
    if (phi_b <= 0.0) break;
    x += step * d;
    phi_a = phi_b;
  }
  // The root of phi(t) = h(x + t d) . d on [0, step], phi(0) > 0 >= phi(step).
  const double tolerance = h.options.tolerance;
  Eigen::VectorXd rt;
  const auto phi = [&](double t) {
    if (!h(x + t * d, rt) || h.over()) throw SearchOver{};
    return rt.dot(d);
  };
  const auto close_enough = [tolerance](double lo, double hi) { return std::abs(hi - lo) <= tolerance; };
  std::uintmax_t iterations = static_cast<std::uintmax_t>(h.options.max_evaluations);
  std::pair<double, double> bracket;
  try {
    bracket = boost::math::tools::toms748_solve(phi, 0.0, step, phi_a, phi_b, close_enough, iterations);
  } catch (const SearchOver&) {
    return std::nullopt;
  }
  const Eigen::VectorXd at = x + 0.5 * (bracket.first + bracket.second) * d;
  if (!h(at, rt) || h.over()) return std::nullopt;
  if (!close_enough(bracket.first, bracket.second)) return at;  // TOMS 748 stopped short: solve from there
  // A bracket narrower than the tolerance: what is left of the residual is its own
  // scatter (a solution), or h . d jumps there (far more than its slope across the
  // bracket could make), or the root along d is not the system's (several
  // unknowns): solve from there.
  if (rt.cwiseAbs().maxCoeff() <= noise) {
    h.best.x = at;
    h.best.residual = rt;
    h.best.summary.residual = rt.cwiseAbs().maxCoeff();
    h.within_noise = true;
    return std::nullopt;
  }
  constexpr double kJump = 100.0;  // tolerances: |h . d| a continuous root leaves within its bracket is about 1
  if (std::abs(rt.dot(d)) <= kJump * std::max(tolerance, noise)) return at;
  if (h.best.jump_at.size() == 0) h.best.jump_at = at;
  h.best.jump_residual = rt;
  return std::nullopt;
}

/// Up to options.newton_steps full Newton steps from x on the caller's Jacobian, while
/// each stays within options.initial_step and at least halves max |r|. True where it
/// converged (h.best holds the solution); false with x the best point reached, where
/// the hybrid method takes over.
bool newton_phase(CountedResidual& h, const ResidualJacobian& jacobian, Eigen::VectorXd& x, int& jacobians) {
  constexpr double kContraction = 0.5;
  Eigen::VectorXd r;
  Eigen::MatrixXd jac;
  double last = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= h.options.newton_steps; ++step) {
    if (h.exhausted() || !h(x, r)) return false;
    if (h.converged()) return true;
    const double size = r.cwiseAbs().maxCoeff();
    if (!(size <= kContraction * last) || step == h.options.newton_steps) break;
    ++jacobians;
    if (!jacobian(x, jac) || !jac.allFinite()) break;
    last = size;
    const Eigen::VectorXd next = x - jac.partialPivLu().solve(r);
    // A step beyond the hybrid method's first trust radius: the linear model is not
    // to be trusted that far (a nearly singular Jacobian); the hybrid method takes over.
    if (!next.allFinite() || (next - x).cwiseAbs().maxCoeff() > h.options.initial_step) break;
    x = next;
  }
  x = h.best.x;
  return false;
}

}  // namespace

NonlinearSystemResult solve_fixed_point(const Residual& residual, const ResidualJacobian& jacobian,
                                        const Eigen::VectorXd& start, const NonlinearSystemOptions& options,
                                        double noise) {
  NonlinearSystemResult best;
  best.summary.residual = std::numeric_limits<double>::infinity();
  CountedResidual h{residual, options, best};
  const Residual counted = [&h](const Eigen::VectorXd& x, Eigen::VectorXd& r) { return h(x, r); };
  int jacobians = 0;
  Eigen::VectorXd x = start;
  const bool newton_converged = options.newton_steps > 0 && newton_phase(h, jacobian, x, jacobians);
  while (!newton_converged && !h.failed) {
    NonlinearSystemOptions system = options;
    system.max_evaluations = options.max_evaluations - h.evaluations;
    const NonlinearSystemResult solved = solve_nonlinear_system(counted, jacobian, x, system);
    jacobians += solved.summary.jacobians;
    if (h.over() || solved.summary.termination != Termination::no_progress) break;
    const std::optional<Eigen::VectorXd> again = march_along_residual(h, solved.x, solved.residual, noise);
    if (!again) break;
    x = *again;
  }
  SolverSummary& summary = best.summary;
  summary.evaluations = h.evaluations;
  summary.jacobians = jacobians;
  if (h.failed) {
    summary.termination = Termination::inner_failure;
  } else if (h.converged()) {
    summary.termination = Termination::converged;
  } else if (best.jump_at.size() > 0) {
    summary.termination = Termination::no_progress;
    summary.where = fmt::format("(the residual jumps by {:.3g} within {:.3g} of the unknowns)",
                                best.jump_residual.cwiseAbs().maxCoeff(), options.tolerance);
  } else {
    summary.termination = h.exhausted() ? Termination::max_iterations : Termination::no_progress;
  }
  return best;
}

}  // namespace stockbridge::numerics
