#pragma once
// The damper's nonlinear impedance (MODEL.md section 5): clamp motion
// x_c = X sin(W t), velocity V cos(W t); in the periodic steady state the shaker
// force F_c(t) = m_c x_c'' - sum_k F_k(t) has the first harmonic
//     F1 = (2/T) int_0^T F_c(t) exp(-i W t) dt,   Z = F1 / V,
// so that a pure mass m gives Z = i W m. The mean power is P = V^2 Re(Z) / 2, and
// equals the energy the sliders dissipate per period / T.

#include <complex>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/damper/harmonic_balance.hpp"
#include "stockbridge/damper/periodic_solution.hpp"
#include "stockbridge/damper/shooting.hpp"
#include "stockbridge/damper/time_integration.hpp"

namespace stockbridge::damper {

enum class Method { harmonic_balance, collocation, time_integration, shooting };

/// "hb", "collocation", "time" or "shooting"; throws InvalidParameter otherwise.
Method parse_method(std::string_view name);
std::string_view method_name(Method method);

/// Every method's full options; `method` picks the one used. Each method keeps its
/// own defaults (collocation needs more harmonics than harmonic balance, since its
/// 2H + 1 collocation points are also its sampling).
struct SolverOptions {
  Method method = Method::harmonic_balance;
  HarmonicBalanceOptions harmonic_balance;
  HarmonicBalanceOptions collocation = collocation_defaults();
  TimeIntegrationOptions time_integration;
  ShootingOptions shooting;
  /// A point whose energy balance (SolverSummary::energy_error, relative to the
  /// apparent power) is off by more than this is not trusted: converged = false.
  /// Typical errors: 1e-4 (harmonic balance, 144 samples), 1e-3 (time, 64 steps).
  double energy_tolerance = 0.01;

  void validate() const;
  static HarmonicBalanceOptions collocation_defaults();
};

/// Two amplitudes equal but for round-off (a velocity computed back from W X).
bool same_amplitude(double a, double b);

/// Where a solve along a path (a sweep, a continuation) starts: the last converged
/// solution. Empty: a cold start, from the solver's own starting point.
struct Continuation {
  Eigen::VectorXd unknowns;      ///< the solver's unknowns at the solution
  Excitation excitation;         ///< where it was solved
  HarmonicBalanceMemory memory;  ///< harmonic balance and collocation: its cable state and Jacobian
  /// The solution before it (empty: none), for the secant.
  Eigen::VectorXd previous_unknowns;
  Excitation previous_excitation;

  bool empty() const { return unknowns.size() == 0; }
  /// The predictor at `target`: the unknowns scaled to its displacement amplitude
  /// and, where the path came from a lower frequency at the same amplitude and goes
  /// on upwards by a step at most twice the last, the secant through the last two
  /// solutions (so scaled) extrapolated in log frequency.
  Eigen::VectorXd predictor(const Excitation& target) const;
  /// Whether predictor() takes the secant at `target`.
  bool secant_applies(const Excitation& target) const;
  /// Moves on to a converged solution (the current one becomes the previous).
  void advance(const Eigen::VectorXd& solution, const Excitation& at);
};

/// One arm's periodic solver, whichever the method (a small interface the damper
/// sees). It owns its scratch space, so one solver serves one thread.
class ArmSolver {
 public:
  virtual ~ArmSolver() = default;
  /// Solves at `excitation`, starting from `path`. On convergence `path` moves on to
  /// this solution; otherwise its unknowns stay and the solver's memory is cleared.
  virtual ArmSolution solve(const Excitation& excitation, Continuation& path) = 0;
  /// Follows the branch through `path` to the target excitation by arclength
  /// continuation at constant velocity amplitude: the solutions at every crossing
  /// of the target frequency (several where the branch folds back over it), and
  /// `path` moves on to the last. Empty where the method cannot (only harmonic
  /// balance and collocation can) or the branch was lost.
  virtual std::vector<ArmSolution> continue_to(const Excitation& /*target*/, Continuation& /*path*/) { return {}; }
};

std::unique_ptr<ArmSolver> make_arm_solver(const Arm& arm, const SolverOptions& options);

/// The damper at one excitation.
struct ImpedancePoint {
  double frequency_hz = 0.0;
  double velocity_amplitude = 0.0;      ///< V, m/s
  double displacement_amplitude = 0.0;  ///< X, m
  /// converged: every arm converged within the energy tolerance; otherwise the
  /// first failing arm's termination (energy_mismatch for the balance).
  Termination termination = Termination::not_run;
  std::complex<double> impedance;       ///< Z, N s/m (only if converged)
  double power = 0.0;                   ///< V^2 Re(Z) / 2, W
  double dissipated_power = 0.0;        ///< sliders' energy per period / T, W
  double energy_error = std::numeric_limits<double>::quiet_NaN();  ///< largest over the arms (NaN unless converged)
  double residual = std::numeric_limits<double>::quiet_NaN();      ///< largest over the arms (NaN unless converged)
  /// The largest over the arms of the clamp section's curvature amplitude
  /// (ArmFigures), 1/m: the damper cable's own fatigue load (NaN unless converged).
  double messenger_curvature_max = std::numeric_limits<double>::quiet_NaN();
  /// One per arm of the damper, in its order: each arm's power, mass amplitude and
  /// clamp curvature amplitude (all NaN unless the point converged).
  std::vector<ArmFigures> arms;
  int newton_iterations = 0;            ///< largest over the arms
  int periods = 0;                      ///< largest over the arms, periods integrated
  double seconds = 0.0;
  std::string failure;                  ///< why not converged: which arm, where, by how much
  std::string note;                     ///< about a converged point (several steady states, how it was reached)
  /// Several steady states near this frequency: set by the sweep (see sweep.hpp).
  bool non_unique = false;

  bool converged() const { return termination == Termination::converged; }
};

/// Combines the arms' periodic solutions (one per arm of the damper) with the
/// clamp mass into the impedance and the design figures (arm_figures); a point is
/// converged only if every arm converged within `energy_tolerance`.
ImpedancePoint combine(const Damper& damper, const Excitation& excitation,
                       const std::vector<const ArmSolution*>& arm_solutions, double energy_tolerance);

/// The shaker force over one period at N samples: m_c x_c'' - sum F_k (also for the
/// last iterate of a point that did not converge); empty unless every arm has a
/// period of the same N samples.
Eigen::RowVectorXd shaker_force(const Damper& damper, const Excitation& excitation,
                                const std::vector<const ArmSolution*>& arm_solutions);

}  // namespace stockbridge::damper
