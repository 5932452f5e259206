#pragma once
// Harmonic balance (Galerkin) and trigonometric collocation for one arm's
// periodic steady state (MODEL.md section 6, dissertation 4.2.5.3-4).
//
// The arm's tip kinematics are a Fourier series of H harmonics,
//     u(t) = u_0 + sum_k a_k cos(k W t) + b_k sin(k W t),  unknowns q = [u_0, a_1, b_1, ...],
// two numbers (x, phi) each. Under half-wave symmetry (the default for harmonic
// balance) only the odd harmonics are kept, q = [a_1, b_1, a_3, b_3, ...]: the
// cable law is odd and the drive a sine, so the steady state repeats with the
// opposite sign after half a period, u(t + T/2) = -u(t), and the cable is driven
// over half a period only (PathSymmetry::half_wave). The cable loads f(t) = (F, Q) follow by alternating
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
  int harmonics = 17;         ///< H, >= 1 (17: Z within 0.07 % of a converged reference on the example sweep, see docs/damper.md)
  int samples = 0;            ///< AFT samples per period (harmonic balance); 0: 8 H rounded up to a multiple of 16, >= 64
  bool collocation = false;   ///< trigonometric collocation at 2H + 1 points instead
  /// Odd harmonics only, the cable driven over half periods (harmonic balance with
  /// an even number of samples; collocation and odd sample counts use whole periods).
  /// False: every harmonic and the mean, whole periods (a check, or the path of a
  /// steady state that breaks the symmetry).
  bool half_wave = true;
  int max_iterations = 100;   ///< Newton iterations
  /// Residual relative to the excitation force amplitude m W^2 X (1e-7: Z within 1e-6 of
  /// its value at 1e-8 on the example sweep, far inside the discretisation's 1e-3).
  double tolerance = 1e-7;
  /// Every evaluation drives the cable through `periods` periods (half periods, each
  /// followed by the mirror, under half-wave symmetry) and uses the last;
  /// the solution is accepted when, in the same evaluation, the cable's state over the
  /// last period changed by at most `periodicity_tolerance` (see PeriodicCableResult).
  int periods = 2;
  double periodicity_tolerance = 1e-6;
  /// Once the equations hold, further periods at the same coefficients let the
  /// cable's memory settle; at most this many (near-stick states settle slowly).
  int max_settling_periods = 2000;
  /// Settling also comes before a Newton step while the residual is below this many
  /// times the periodicity defect: such a residual is mostly the drift of a memory
  /// that has not settled, which no step removes (0: settle only once the equations
  /// hold). 0.3: on slenderpy's Bouc-Wen damper 400 points in 38 % less time (the
  /// Jacobians re-evaluated after rejected steps saved), |Z| within 1e-6 of 0's.
  double settle_ratio = 0.3;
  /// The stored Jacobian is replaced by an exact one when a Newton step reduces the
  /// residual by less than this factor (an exact one costs about 12 residuals).
  double jacobian_refresh_ratio = 0.25;
  /// Between exact Jacobians, Broyden's rank-one update after each step.
  bool broyden = true;
  /// Under Newton on the periodic state, the most points one exact Jacobian serves
  /// (the point it was evaluated at included): the next starts with an exact one
  /// (0: no limit, an exact one only where the steps call for it). Its periodic-state
  /// terms drift along a sweep: on slenderpy's damper near 20 Hz the last point's
  /// exact Jacobian contracts the next point's Newton error by about 0.03, one two
  /// points back by 0.06, and the stored one Broyden's updates carried further by
  /// about 0.1. 3: that damper's 400-point sweep 6 % faster than 0.
  int stored_jacobian_points = 3;
  /// Where the cable's law offers periodic coordinates (CableLaw::periodic_coordinates:
  /// Bouc-Wen), Newton solves for the periodic start state together with q: each
  /// evaluation drives one pass (no centring), the exact Jacobian carries the start's
  /// coordinates as parameters too, and the next start is the Newton estimate of the
  /// periodic state instead of the last end state (HarmonicBalance::solve). False:
  /// chained periods for every law.
  bool periodic_newton = true;
  cable::CantileverOptions cantilever;

  void validate() const;
  /// The number of time samples per period actually used.
  int sample_count() const;
  /// Whether half-wave symmetry is used (asked for, harmonic balance, samples even).
  bool uses_half_wave() const;
};

/// Newton on the periodic state: with z the start state's coordinates, G = z_end - z
/// the pass's gap, R_z and G_z, G_q their derivatives, and D = G_z - I, the state's
/// Newton step is dz = -D^-1 (G + G_q dq), and q's is Newton's on the residual with the
/// state eliminated, R - R_z D^-1 G, whose Jacobian is J - R_z D^-1 G_q (J with
/// the start fixed). Kept from the last exact evaluation, as the force Jacobian is.
struct PeriodicStateTerms {
  Eigen::MatrixXd start_by_gap;            ///< D^-1 (m x m)
  Eigen::MatrixXd residual_by_start;       ///< R_z (N x m)
  Eigen::MatrixXd start_by_coefficients;   ///< D^-1 G_q (m x N)

  bool empty() const { return start_by_gap.size() == 0; }
};

/// What a solve leaves for the next one along a path (as in a stepped-sine test):
/// the cable's periodic state at the last solution, where the next evaluation
/// starts, and the Jacobian of the force residual there, exact as long as the path
/// stays on the same piece of the piecewise-linear cable map and so reused across
/// Newton iterations and neighbouring frequencies. Empty: a cold start (virgin
/// cable, no stored Jacobian).
struct HarmonicBalanceMemory {
  std::optional<cable::CableState> cable_state;
  /// d(force residual)/dq (empty: none stored); with periodic-state terms, that of
  /// the residual with the state eliminated.
  Eigen::MatrixXd force_jacobian;
  PeriodicStateTerms periodic_state;  ///< empty: the next start is the last end state
  int jacobian_sign = 0;              ///< sign of det(J) at the last solution (0: unknown)
  /// q at the last solution, where cable_state is periodic (empty: none): with the
  /// periodic-state terms, the next solve moves its start by -D^-1 G_q (q - this).
  Eigen::VectorXd unknowns;
  /// The points solved since the stored Jacobian was last exact, that one included
  /// (HarmonicBalanceOptions::stored_jacobian_points).
  int jacobian_points = 0;

  void clear() { *this = HarmonicBalanceMemory{}; }
};

/// Scratch space of the evaluations: the cable driven through the periods and its
/// sensitivities. One per thread; it carries no result from one call to the next.
struct HarmonicBalanceWorkspace {
  PeriodicCable cable;
  Eigen::MatrixXd sensitivity;
};

/// One evaluation of the harmonic-balance equations at unknowns q.
struct HarmonicBalanceEvaluation {
  /// The periodic cable's report: the residual exists only if it converged
  /// (else inner_failure or non_finite, with `where`).
  SolverSummary cable;
  Eigen::VectorXd residual;        ///< N: Galerkin coefficients (or collocation values) of M u'' + f - L x_c''
  ArmPeriod period;                ///< the kinematics and loads of the final period
  cable::CableState end_state;     ///< the cable's state after it: where a chained evaluation goes on
  Eigen::MatrixXd force_jacobian;  ///< d(force residual)/dq, if asked for
  Eigen::VectorXd d_frequency;     ///< dR/dW at constant velocity amplitude, if asked for
  /// Under PeriodicStart::newton: G = z(end) - z(start) in the law's periodic
  /// coordinates; with the Jacobian, R_z (force_jacobian's further columns, N x m)
  /// and d z_end / d(q, z0) (m x (N + m)).
  Eigen::VectorXd state_gap;
  Eigen::MatrixXd state_jacobian;

  bool ok() const { return cable.converged(); }
};

/// The harmonic-balance (or collocation) model of one arm: basis, projection and
/// the arm, constant once built, so one model serves any number of solves and
/// threads; what changes lives in the memory and workspace the caller passes.
class HarmonicBalance {
 public:
  HarmonicBalance(Arm arm, HarmonicBalanceOptions options);

  const Arm& arm() const { return arm_; }
  const HarmonicBalanceOptions& options() const { return options_; }
  int unknown_count() const { return 2 * static_cast<int>(harmonic_.size()); }
  /// The harmonic number of each coefficient column (0 for the mean).
  const std::vector<int>& harmonics() const { return harmonic_; }
  HarmonicBalanceWorkspace make_workspace() const;

  /// The all-stick linear steady state (a starting point where no predictor exists).
  Eigen::VectorXd linear_guess(const Excitation& excitation) const;
  /// The excitation force scale m W^2 X used for the tolerance, N.
  double force_scale(const Excitation& excitation) const;

  /// Which derivatives an evaluation computes (bit flags).
  enum Derivatives : unsigned { kNone = 0, kJacobian = 1, kFrequency = 2 };
  /// Drives the cable through `periods` periods of the tip motion q from `start`
  /// (nullptr: the virgin state) and evaluates the equations on the last one, with
  /// the exact force Jacobian (forward sensitivities, the start state held fixed)
  /// and dR/dW if asked for. Under PeriodicStart::newton (and a law with periodic
  /// coordinates) also the pass's gap G and, with the Jacobian, the start's
  /// coordinates as further columns of force_jacobian and state_jacobian. Check
  /// ok() before using any number.
  [[nodiscard]] HarmonicBalanceEvaluation evaluate(const Excitation& excitation, const Eigen::VectorXd& q,
                                                   const cable::CableState* start, int periods, unsigned derivatives,
                                                   HarmonicBalanceWorkspace& workspace,
                                                   PeriodicStart mode = PeriodicStart::chained) const;
  /// Whether solve() runs Newton on the periodic state (options' periodic_newton
  /// and a law that offers coordinates).
  bool uses_periodic_newton() const { return periodic_newton_; }
  /// Coefficients q of this model in the layout of the same model over whole periods
  /// (half_wave = false): the odd harmonics in their places, the mean and the even
  /// harmonics zero. q itself where this model uses whole periods already.
  Eigen::VectorXd whole_period_unknowns(const Eigen::VectorXd& q) const;
  /// R(q) at `to` minus R(q) at `from`: what the inertia and the excitation change
  /// (the cable's loads depend on the coefficients q alone).
  Eigen::VectorXd residual_change(const Excitation& from, const Excitation& to, const Eigen::VectorXd& q) const;
  /// J = the force Jacobian + the inertia terms at this frequency.
  Eigen::MatrixXd jacobian(const Excitation& excitation, const Eigen::MatrixXd& force_jacobian) const;
  /// The same into `jacobian`, reusing its storage (Newton's inner loop).
  void assemble_jacobian(const Excitation& excitation, const Eigen::MatrixXd& force_jacobian,
                         Eigen::MatrixXd& jacobian) const;

  /// Newton from `initial` (unknown_count() coefficients, m and rad), starting the
  /// cable from memory.cable_state and reusing memory.force_jacobian where stored.
  ///
  /// Each evaluation starts from the state the last accepted one ended in: the
  /// cable's memory under two prescribed tip coordinates settles over several
  /// periods, and chaining lets those periods accumulate over the Newton
  /// iterations instead of being repeated in each. Convergence requires the
  /// residual (relative to force_scale) and the periodicity defect of the same
  /// evaluation; once the equations hold, further periods at the same coefficients
  /// let the memory settle. Where the solve uses Newton on the periodic state
  /// (uses_periodic_newton), each evaluation is one pass from the Newton estimate of
  /// the periodic start state instead (PeriodicStateTerms), the first from
  /// memory.cable_state moved to where the stored terms predict it periodic at
  /// `initial`, and chained periods take over where that stalls. On convergence
  /// `memory` holds this solution's state, q and Jacobian; otherwise it is cleared.
  /// summary: newton_iterations, periods (in all), evaluations, jacobians, residual,
  /// periodicity_defect, energy_error.
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& initial, HarmonicBalanceMemory& memory,
                    HarmonicBalanceWorkspace& workspace) const;
  /// A cold solve (virgin cable, no stored Jacobian).
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& initial) const;

 private:
  Arm arm_;
  HarmonicBalanceOptions options_;
  int samples_;                 // per period
  PathSymmetry symmetry_;
  int driven_samples_;          // per pass of the cable: N, or N / 2 under half-wave symmetry
  std::vector<int> harmonic_;   // per coefficient column C: 0, 1, 1, 2, 2, ... (odd only: 1, 1, 3, 3, ...)
  int excitation_column_;       // the column of sin(W t)
  bool periodic_newton_ = false;
  Eigen::MatrixXd basis_;       // driven samples x C: 1, cos(k W t_j), sin(k W t_j)
  Eigen::MatrixXd projection_;  // C x driven samples: Fourier coefficients from samples (harmonic balance)
};

}  // namespace stockbridge::damper
