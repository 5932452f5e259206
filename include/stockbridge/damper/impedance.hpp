#pragma once
// The damper's nonlinear impedance (MODEL.md section 5): clamp motion
// x_c = X sin(W t), velocity V cos(W t); in the periodic steady state the shaker
// force F_c(t) = m_c x_c'' - sum_k F_k(t) has the first harmonic
//     F1 = (2/T) int_0^T F_c(t) exp(-i W t) dt,   Z = F1 / V,
// so that a pure mass m gives Z = i W m. The mean power is P = V^2 Re(Z) / 2, and
// equals the energy the sliders dissipate per period / T.

#include <complex>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/damper/harmonic_balance.hpp"
#include "stockbridge/damper/periodic_solution.hpp"

namespace stockbridge::damper {

enum class Method { harmonic_balance, collocation, time_integration, shooting };

/// "hb", "collocation", "time" or "shooting"; throws InvalidParameter otherwise.
Method parse_method(std::string_view name);
std::string_view method_name(Method method);

struct SolverOptions {
  Method method = Method::harmonic_balance;
  HarmonicBalanceOptions harmonic_balance;  ///< also for collocation (its `collocation` flag is set)
  int steps_per_period = 256;               ///< time integration and shooting
  /// A point whose energy balance (SolverSummary::energy_error, relative to the
  /// apparent power) is off by more than this is not trusted: converged = false.
  /// Typical errors: 1e-4 (harmonic balance, 128 samples), 1e-3 (time, 64 steps).
  double energy_tolerance = 0.01;
  void validate() const;
};

/// One arm's periodic solver, whichever the method (a small interface the damper sees).
class ArmSolver {
 public:
  virtual ~ArmSolver() = default;
  /// `predictor`: the unknowns of a nearby solution (empty: the solver's own start).
  virtual ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& predictor) = 0;
  /// Follows the branch of the solution `from` (at `from_frequency_hz`) to the target
  /// excitation by arclength continuation, at constant velocity amplitude; the
  /// solutions at every crossing of the target frequency (several where the branch
  /// folds back over it). Empty where the method cannot (only harmonic balance can).
  virtual std::vector<ArmSolution> continue_to(const Excitation& /*target*/, const Eigen::VectorXd& /*from*/,
                                               double /*from_frequency_hz*/) {
    return {};
  }
};

std::unique_ptr<ArmSolver> make_arm_solver(const Arm& arm, const SolverOptions& options);

/// The damper at one excitation.
struct ImpedancePoint {
  double frequency_hz = 0.0;
  double velocity_amplitude = 0.0;      ///< V, m/s
  double displacement_amplitude = 0.0;  ///< X, m
  bool converged = false;
  std::complex<double> impedance;       ///< Z, N s/m (only if converged)
  double power = 0.0;                   ///< V^2 Re(Z) / 2, W
  double dissipated_power = 0.0;        ///< sliders' energy per period / T, W
  double energy_error = 0.0;            ///< largest over the arms (see SolverSummary)
  double residual = 0.0;                ///< largest over the arms
  int iterations = 0;                   ///< largest over the arms
  double seconds = 0.0;
  std::string message;                  ///< why not converged (which arm, where, by how much), or notes
  /// Several steady states near this frequency: set by the sweep (see sweep.hpp).
  bool non_unique = false;
};

/// Combines the arms' periodic solutions with the clamp mass into the impedance; a
/// point is converged only if every arm converged within `energy_tolerance`.
ImpedancePoint combine(const DamperDescription& damper, const Excitation& excitation,
                       const std::vector<const ArmSolution*>& arm_solutions, double energy_tolerance = 0.01);

/// The shaker force over one period at N samples (all arms sampled alike): m_c x_c'' - sum F_k.
Eigen::RowVectorXd shaker_force(const DamperDescription& damper, const Excitation& excitation,
                                const std::vector<const ArmSolution*>& arm_solutions);

/// Groups identical arms: index of the representative arm for each arm.
std::vector<std::size_t> distinct_arms(const DamperDescription& damper);

}  // namespace stockbridge::damper
