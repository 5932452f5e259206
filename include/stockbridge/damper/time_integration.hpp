#pragma once
// Time integration of one arm until its motion is periodic (MODEL.md section 6,
// dissertation 4.2.5.1), and the Newmark stepper it shares with shooting.
//
// Equation of motion per arm, u = (x, phi) the tip deflection and rotation:
//     M u'' + f(u, history) = L x_c''(t),   x_c = X sin(W t),
// M = Arm::mass_matrix(), L = Arm::load_vector(), f = (F, Q) the quasi-static
// cable's tip loads (cable::Cantilever, exact nonsmooth law, trial/commit).
//
// Scheme: Newmark's average acceleration (trapezoidal rule, beta = 1/4,
// gamma = 1/2): second order, unconditionally stable for the linear system, no
// numerical damping (a linear free vibration keeps its amplitude; its period is
// lengthened by (W h)^2 / 12 relative). With h = T / N,
//     u_{n+1} = u_n + h v_n + h^2/4 (a_n + a_{n+1}),   v_{n+1} = v_n + h/2 (a_n + a_{n+1}),
//     M a_{n+1} + f(u_{n+1}) = L x_c''(t_{n+1}).
// Each step is Newton's method on u_{n+1} with the effective tangent
// K_t + (4/h^2) M (K_t = the trial tip stiffness d(F, Q)/d(x, phi)), carried out in
// terms of a_{n+1} (same iterates, the tangent scaled by h^2/4, which avoids the
// cancellation in u_{n+1} - u_n - h v_n); the cable is set to trial states until
// the residual is below `newton_tolerance` times the largest term of the
// equation (moments divided by the cable length l so that both rows are forces),
// then committed. The cable thus moves monotonically within each step.
//
// Start: with only dry friction, a response in which nothing slips is linear and
// undamped, and its free vibration never decays. The default start is therefore
// the all-stick linear steady state of the *discrete* scheme, so that in the
// stick regime it is periodic from the first step: the trapezoidal rule maps
// sin(W t) to the frequency W_h = (2/h) tan(W h / 2) (W_h -> W as h -> 0), so
//     u_n = U sin(W t_n),  (K_stick - W_h^2 M) U = -W^2 X L,
//     z_0 = (u, u')(0) = (0, 0, W_h U),  the cable virgin, a_0 = 0.
// (The continuous steady state, with W in place of W_h, would leave a free
// vibration of relative size O(h^2) that the scheme never damps.)
//
// Periodicity: after every period k >= 2 two measures are computed,
//     state: max(|dx|, l |dphi|, |dx'| / W, l |dphi'| / W) / A, d = the change of the
//            state at the period start from the previous period start, A = the
//            amplitude max_j max(|x_j|, l |phi_j|) of the period just integrated;
//     loads: max_j max(|dF_j|, |dQ_j| / l) / max_j max(|F_j|, |Q_j| / l), d = the change
//            of the loads at sample j from the previous period's.
// Both <= periodicity_tolerance: converged. Near a linear resonance steady states
// may be non-unique; this solver returns the one its start leads to.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/damper/periodic_solution.hpp"

namespace stockbridge::damper {

/// What every time-domain solver (time integration, shooting) shares: the Newmark
/// scheme's step and the Newton iteration of each step.
struct TimeDomainOptions {
  int steps_per_period = 256;       ///< N, time steps per excitation period, >= 8
  int max_newton = 30;              ///< Newton iterations per time step
  double newton_tolerance = 1e-12;  ///< step residual relative to the equation's largest term
  cable::CantileverOptions cantilever;

  /// Throws InvalidParameter naming the bad field ("steps_per_period = 3: ...").
  void validate() const;
};

/// The all-stick linear steady state of the discrete Newmark scheme with N steps
/// per period at phase W t = 0: z = (x, phi, x', phi') = (0, 0, W_h U) (see above), m, rad, m/s, rad/s.
Eigen::Vector4d linear_discrete_start(const Arm& arm, const Excitation& excitation, int steps_per_period);

/// Newmark average-acceleration stepping of one arm under harmonic clamp motion,
/// a whole period at a time (phase 0 to 2 pi), with the exact cable law: one run's
/// state (the cable's hysteretic state in its cable::Cantilever, the mechanical state
/// u, u', u'') and workspace (the forcing samples). The solvers (TimeIntegration,
/// Shooting) are const models; each solve runs on a stepper passed in (one per
/// thread, reused from point to point) or made for it.
class NewmarkStepper {
 public:
  NewmarkStepper(const Arm& arm, const TimeDomainOptions& options);

  /// Sets h = T / N and the load samples L x_c''(t_j); the state is unchanged.
  void set_excitation(const Excitation& excitation);
  /// The cable back to its virgin state (the mechanical state is unchanged).
  void reset_cable();
  /// The cable to a committed state it had (the mechanical state is unchanged).
  void restore_cable(const cable::CableState& memory) { cantilever_.restore(memory); }
  /// Puts the arm at phase W t = 0 in the mechanical state z = (x, phi, x', phi'):
  /// the cable moves from its committed state to (x, phi) in one monotone step and
  /// is committed; a = M^-1 (L x_c''(0) - f). Converged, or inner_failure where the
  /// cable's state determination failed (`where` says how).
  SolverSummary place(const Eigen::Vector4d& z);
  /// Integrates one period (N steps) from phase 0, committing every step. With
  /// `record`, fills it (the shared recorder, ArmPeriod::record_loads) with the state
  /// at t_j = j T / N, j = 0..N-1 (before step j) and the dissipation over the
  /// period. Converged, or how a step failed: max_iterations or non_finite for the
  /// step's Newton iteration (with its iterations and residual), inner_failure for
  /// the cable's state determination; `where` names the time and step. After a
  /// failure the state is that of the last committed step.
  SolverSummary advance_period(ArmPeriod* record = nullptr);

  /// (x, phi, x', phi') now.
  Eigen::Vector4d state() const;
  const Eigen::Vector2d& displacement() const { return u_; }
  const cable::Cantilever& cantilever() const { return cantilever_; }
  int steps_per_period() const { return steps_; }
  /// Time since the last place(), s.
  double time() const { return static_cast<double>(periods_since_place_) * period_; }

 private:
  /// From t_j to t_{j+1} of the current period; false with `failure` filled if it failed.
  bool step(int j, SolverSummary& failure);

  // The model: fixed for the stepper's life.
  Eigen::Matrix2d mass_;
  Eigen::Vector2d load_;
  int steps_;
  int max_newton_;
  double newton_tolerance_;
  double length_;
  Eigen::Matrix2d mass_inverse_;
  // The run: the excitation's samples and the state.
  cable::Cantilever cantilever_;
  double period_ = 0.0, h_ = 0.0;
  std::vector<Eigen::Vector2d> forcing_;  // L x_c''(t_j), j = 0..N-1
  Eigen::Vector2d u_ = Eigen::Vector2d::Zero(), v_ = Eigen::Vector2d::Zero(), a_ = Eigen::Vector2d::Zero();
  long long periods_since_place_ = 0;
};

struct TimeIntegrationOptions : TimeDomainOptions {
  int max_periods = 3000;              ///< periods integrated at most, >= 2
  double periodicity_tolerance = 1e-8; ///< on both periodicity measures (see above)

  /// Throws InvalidParameter naming the bad field.
  void validate() const;
};

/// Integrates the initial value problem until the motion is periodic.
///
/// Result: ArmSolution::period sampled at t_j = j T / N of the final period
/// (aligned with the excitation phase, x_c = X sin(W t_j)); dissipated = the
/// cable's dissipation over the final period. summary.periods = periods
/// integrated (no Newton iterations at this level); summary.residual = the final
/// periodicity measure (the larger of the two); summary.periodicity_defect = the
/// loads measure; summary.energy_error from energy_error(). ArmSolution::unknowns =
/// (x, phi, x', phi') at the start of the final period. Not reaching periodicity in
/// max_periods (not_periodic), or a failed step (the stepper's termination), is
/// reported in the summary, never thrown.
class TimeIntegration {
 public:
  TimeIntegration(Arm arm, TimeIntegrationOptions options);

  const TimeIntegrationOptions& options() const { return options_; }

  /// `initial_state`: (x, phi, x', phi') at t = 0 (the cable starts virgin and moves
  /// to (x, phi) in one step); default the discrete all-stick steady state.
  /// Throws InvalidParameter for a bad excitation or an initial state of the wrong size.
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd* initial_state = nullptr) const;
  /// The same on `stepper` (made by stepper(), reused from solve to solve).
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd* initial_state, NewmarkStepper& stepper) const;
  /// A run's state and workspace for this model.
  NewmarkStepper stepper() const { return NewmarkStepper(arm_, options_); }

 private:
  Arm arm_;
  TimeIntegrationOptions options_;
};

/// Checks a time-domain solve's arguments: a valid excitation, and an initial state
/// (if given) of four finite values (x, phi, x', phi'); InvalidParameter otherwise.
void require_time_domain_start(const Excitation& excitation, const Eigen::VectorXd* initial_state);

/// The largest tip excursion of a period, max_j max(|x_j|, l |phi_j|), m.
double amplitude_of(const ArmPeriod& period, double length);
/// The periodicity measures used by TimeIntegration and Shooting (see above).
/// State: change `delta` of (x, phi, x', phi') relative to the period's amplitude.
double state_change_measure(const Eigen::Vector4d& delta, const ArmPeriod& period, double angular_frequency,
                            double length);
/// Loads: largest change per sample relative to the largest load.
double loads_change_measure(const Eigen::Matrix2Xd& loads, const Eigen::Matrix2Xd& previous, double length);

}  // namespace stockbridge::damper
