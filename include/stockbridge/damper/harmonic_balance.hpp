#pragma once
// Harmonic balance (Galerkin) and trigonometric collocation for one arm's
// periodic steady state (MODEL.md section 6, dissertation 4.2.5.3-4).
//
// The arm's tip kinematics are a Fourier series of H harmonics,
//     u(t) = u_0 + sum_k a_k cos(k W t) + b_k sin(k W t),  unknowns q = [u_0, a_1, b_1, ...],
// two numbers (x, phi) each. The cable loads f(t) = (F, Q) follow by alternating
// frequency-time: u is sampled at N points per period, the cable is driven
// through a pre-period and the period with the exact law, and f is projected
// back. Harmonic balance sets the Galerkin projection of the equation of motion
// M u'' + f = L x_c'' to zero; collocation sets the equation itself to zero at
// N = 2H + 1 points. Newton's method uses the exact Jacobian (forward
// sensitivities of the piecewise-linear cable map) and a backtracking line search.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/damper/periodic_cable.hpp"
#include "stockbridge/damper/periodic_solution.hpp"

namespace stockbridge::damper {

struct HarmonicBalanceOptions {
  int harmonics = 9;          ///< H, >= 1
  int samples = 0;            ///< AFT samples per period (harmonic balance); 0: 8 H rounded up to a power of 2, >= 64
  bool collocation = false;   ///< trigonometric collocation at 2H + 1 points instead
  int max_iterations = 100;   ///< Newton iterations
  double tolerance = 1e-8;    ///< residual relative to the excitation force amplitude m W^2 X
  /// Every evaluation drives the cable through `periods` periods and uses the last;
  /// the solution is accepted when, in the same evaluation, the cable's state over the
  /// last period changed by at most `periodicity_tolerance` (see PeriodicCableResult).
  int periods = 2;
  double periodicity_tolerance = 1e-8;
  /// Once the equations hold, further periods at the same coefficients let the
  /// cable's memory settle; at most this many (near-stick states settle slowly).
  int max_settling_periods = 2000;
  /// The stored Jacobian is replaced by an exact one when a Newton step reduces the
  /// residual by less than this factor (an exact one costs about 12 residuals).
  double jacobian_refresh_ratio = 0.25;
  cable::CantileverOptions cantilever;

  void validate() const;
  /// The number of time samples per period actually used.
  int sample_count() const;
};

class HarmonicBalance {
 public:
  HarmonicBalance(const Arm& arm, HarmonicBalanceOptions options);

  const HarmonicBalanceOptions& options() const { return options_; }
  int unknown_count() const { return 2 * (2 * options_.harmonics + 1); }

  /// The all-stick linear steady state (a starting point where no predictor exists).
  Eigen::VectorXd linear_guess(const Excitation& excitation) const;

  /// Newton from `initial` (unknown_count() coefficients, m and rad).
  ///
  /// The cable's hysteretic state is carried along: each evaluation starts from the
  /// state the last accepted evaluation ended in (the first from the virgin state, or,
  /// with `continue_from_last`, from the periodic state of the last converged solve,
  /// as in a stepped-sine test). The cable's memory under two prescribed tip
  /// coordinates settles over several periods, and chaining lets those periods
  /// accumulate over the Newton iterations instead of being repeated in each; the
  /// Jacobian is exact for the map with the start state held fixed. Convergence
  /// requires the residual and the periodicity defect of the same evaluation.
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& initial, bool continue_from_last = false);

  /// Pseudo-arclength continuation in (q, W) at constant velocity amplitude V, from
  /// the solution `q0` at `f0_hz` (the last converged solve, whose cable state it
  /// continues) until the frequency has passed `target_hz`, turning through folds.
  /// Returns the solutions at every crossing of `target_hz` (polished at exactly that
  /// frequency): one on a single-valued branch, several where the branch folds back
  /// over it; empty if the branch could not be followed there in `max_steps` steps.
  std::vector<ArmSolution> continue_along_branch(double velocity, const Eigen::VectorXd& q0, double f0_hz,
                                                 double target_hz, int max_steps = 60);

  /// The residual (N) at q, and optionally its exact Jacobian
  /// and its derivative with respect to the angular frequency at constant velocity
  /// amplitude (for arclength continuation). Returns false if the cable failed.
  bool residual(const Excitation& excitation, const Eigen::VectorXd& q, int periods, Eigen::VectorXd& r,
                Eigen::MatrixXd* jacobian, Eigen::VectorXd* d_frequency, PeriodicCableResult* loads);

  /// The excitation force scale m W^2 X used for the tolerance, N.
  double force_scale(const Excitation& excitation) const;

 private:
  ArmPeriod period_of(const Eigen::VectorXd& q, const PeriodicCableResult& loads) const;
  /// J = the stored force Jacobian + the inertia terms at this frequency.
  void assemble_jacobian(const Excitation& excitation, Eigen::MatrixXd& jacobian) const;
  /// One arclength corrector: Newton on [R(q, W); t . (y - y_pred)] = 0, scaled.
  bool correct_on_branch(double velocity, Eigen::VectorXd& y, const Eigen::VectorXd& tangent, const Eigen::VectorXd& y_pred,
                         const Eigen::VectorXd& scale, Eigen::MatrixXd& jacobian, Eigen::VectorXd& d_frequency);
  /// Newton's iterations; updates q and loads.
  bool newton(const Excitation& excitation, Eigen::VectorXd& q, PeriodicCableResult& loads, SolverSummary& summary);

  const Arm& arm_;
  HarmonicBalanceOptions options_;
  int samples_;
  Eigen::MatrixXd basis_;       // N x (2H+1): 1, cos(k W t_j), sin(k W t_j)
  Eigen::MatrixXd projection_;  // (2H+1) x N: Fourier coefficients from samples (harmonic balance)
  PeriodicCable cable_;
  Eigen::MatrixXd sensitivity_;
  // d(force residual)/dq of the last exact evaluation: exact as long as the path stays
  // on the same piece of the piecewise-linear cable map, so it is reused across Newton
  // iterations and neighbouring frequencies and refreshed when convergence slows.
  Eigen::MatrixXd force_jacobian_;
  bool force_jacobian_stored_ = false;
  int last_sign_ = 0;  // determinant sign at the last solution
  SolverSummary* counting_ = nullptr;  // where residual() counts its evaluations
  std::optional<cable::CableState> last_state_;  // periodic state of the last converged solve
  std::optional<cable::CableState> start_;       // where the cable's next evaluation starts (empty: virgin)
};

}  // namespace stockbridge::damper
