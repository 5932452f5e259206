#pragma once
// Shooting for one arm's periodic steady state (MODEL.md section 6, dissertation
// 4.2.5.2), on the same discrete equations as TimeIntegration (the Newmark
// average-acceleration scheme with the exact cable law, NewmarkStepper), so that
// both converge to the same periodic solution of the discrete problem.
//
// Unknowns: the arm's mechanical state at phase W t = 0,
//     z0 = (x, phi, x', phi')(0),   m, rad, m/s, rad/s.
// The cable's hysteretic state is not an unknown: it follows from pre-periods.
// The shooting function S(z0) is defined by
//   1. the cable starts from its memory M (virgin at first; see below); the arm is
//      placed at z0 (the cable moves to (x0, phi0) in one monotone step, the
//      acceleration follows from equilibrium);
//   2. P = pre_periods periods are integrated from there;
//   3. the mechanical state is set back to z0 keeping the cable's hysteretic state
//      (the cable moves from where the pre-periods left it to (x0, phi0) in one
//      monotone step; at a solution that step is small);
//   4. one period is integrated (the "final period"), ending in z(T);
//   5. S(z0) = D (z(T) - z0),  D = diag(1, l, 1/W, l/W) / A,
//      l the cable length, A the amplitude max_j max(|x_j|, l |phi_j|) of the latest
//      accepted final period (held fixed within a Newton iteration).
// Each evaluation of S therefore integrates P + 1 periods. S is continuous and
// piecewise smooth (the cable law is piecewise linear), not differentiable at the
// breakpoints.
//
// Newton's method on S(z0) = 0 with a Jacobian by forward finite differences of S
// (4 extra evaluations, step `finite_difference_step` in the scaled variables
// D z0, i.e. relative to the amplitude; across breakpoints this is a secant slope,
// which is what the nonsmooth map needs) and a backtracking line search on |S|.
// The differences are taken at the first iteration and again whenever a step
// fails; in between the Jacobian gets Broyden's rank-one update from each accepted
// step (a full step, no line search) and is kept when P grows (for large P the
// memory after the pre-periods hardly depends on z0, so the Jacobian tends to the
// monodromy matrix minus the identity). Converged when
//   * the state measure max(|dx|, l |dphi|, |dx'| / W, l |dphi'| / W) / A of
//     z(T) - z0 (A the final period's amplitude) is <= tolerance, and
//   * the loads of the final period differ from those of the last pre-period by at
//     most periodicity_tolerance (max_j max(|dF_j|, |dQ_j| / l) / max_j max(|F_j|, |Q_j| / l)):
//     the cable's memory settles only geometrically over the periods (see
//     periodic_cable.hpp), so when it has not, P is doubled (up to max_pre_periods),
//     M becomes the cable's state at the end of the last accepted shot (so that
//     the memory goes on settling from where it got to: after k doublings it has
//     had about 2^(k+1) P periods, not 2^k P; the Bouc-Wen law's memory, which
//     settles more slowly than the Masing law's, needs that), and Newton
//     continues from the current z0 as soon as the state measure is
//     below max(tolerance, 0.01 x the loads defect) (solving S = 0 more precisely
//     than the memory has settled is wasted) or a line search fails where the
//     state measure is already below the loads defect (S is not defined more
//     precisely than the memory has settled); at max_pre_periods the defect is
//     reported (converged == false).
// Near a linear resonance steady states may be non-unique; shooting returns the one
// Newton reaches from its start.
//
// Cost and limits: the memory needs about as many pre-periods as time integration
// needs periods (30-130 on the verification arm at 0.2 m/s), and each Newton
// iteration shoots from the virgin cable again, so shooting costs several times
// TimeIntegration (on the verification arm at 15 Hz, 0.2 m/s, N = 256: about 300
// periods against 37). When the response barely slips (5 Hz at 0.2 m/s), the free
// vibration set off by starting the cable virgin at z0 is hardly damped and never
// settles: the loads defect stays at a few per cent and non-convergence is
// reported; use TimeIntegration there.

#include <Eigen/Core>

#include "stockbridge/damper/periodic_solution.hpp"
#include "stockbridge/damper/time_integration.hpp"

namespace stockbridge::damper {

struct ShootingOptions : TimeDomainOptions {
  int pre_periods = 2;          ///< P at the start, >= 1
  int max_pre_periods = 256;    ///< P is doubled up to this, >= pre_periods
  /// Newton iterations in all, over the values of P, >= 1 (a few per value of P:
  /// the Bouc-Wen law's memory needs up to 7 values)
  int max_iterations = 60;
  double tolerance = 1e-9;      ///< on the state measure of S (see above)
  double periodicity_tolerance = 1e-7;  ///< on the loads, final period vs last pre-period
  double finite_difference_step = 1e-6;  ///< in the scaled unknowns D z0 (relative to the amplitude)
  int max_halvings = 20;        ///< line search

  /// Throws InvalidParameter naming the bad field ("pre_periods = 0: ...").
  void validate() const;
};

/// Result: ArmSolution::period = the final period of the last accepted shot,
/// sampled at t_j = j T / N (aligned with x_c = X sin(W t_j)), dissipated over it;
/// unknowns = z0; summary.newton_iterations = Newton iterations; summary.residual =
/// the state measure of S; summary.periods = periods integrated in all;
/// summary.periodicity_defect = the loads measure; summary.energy_error from
/// energy_error(). Non-convergence (max_iterations, line_search_failed,
/// singular_jacobian, not_periodic for the pre-periods, a failed time step) is
/// reported in the summary, never thrown.
class Shooting {
 public:
  Shooting(Arm arm, ShootingOptions options);

  const ShootingOptions& options() const { return options_; }

  /// `initial_state`: z0 to start Newton from; default the discrete all-stick
  /// linear steady state (linear_discrete_start). Throws InvalidParameter for a bad
  /// excitation or an initial state of the wrong size.
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd* initial_state = nullptr) const;
  /// The same on `stepper` (made by stepper(), reused from solve to solve).
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd* initial_state, NewmarkStepper& stepper) const;
  /// A run's state and workspace for this model.
  NewmarkStepper stepper() const { return NewmarkStepper(arm_, options_); }

  /// A shot: steps 1-4 above from z0 with P pre-periods.
  struct Shot {
    /// Converged when every step succeeded; else the failed step's report, with
    /// the stage of the shot in `where`.
    SolverSummary summary;
    Eigen::Vector4d end = Eigen::Vector4d::Zero();  // z(T)
    ArmPeriod period;                               // the final period
    Eigen::Matrix2Xd pre_loads;                     // loads of the last pre-period
    cable::CableState memory;                       // the cable's state at the end of the final period
  };
  /// Fires a shot on `stepper` (its excitation set) into `shot`, the cable starting
  /// from `memory` (virgin where null).
  void shoot(NewmarkStepper& stepper, const Eigen::Vector4d& z0, int pre_periods, Shot& shot,
             const cable::CableState* memory = nullptr) const;

 private:
  Arm arm_;
  ShootingOptions options_;
};

}  // namespace stockbridge::damper
