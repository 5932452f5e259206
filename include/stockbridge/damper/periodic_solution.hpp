#pragma once
// What every periodic-steady-state solver returns for one arm, and how it ended.

#include <complex>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/numerics/solver_summary.hpp"

namespace stockbridge::damper {

/// One arm's steady periodic motion, sampled at t_j = j T / N, j = 0..N-1.
struct ArmPeriod {
  Eigen::Matrix2Xd kinematics;        ///< (x, phi), m and rad
  Eigen::Matrix2Xd loads;             ///< (F, Q), N and N m
  std::vector<double> clamp_moment;   ///< T, N m
  std::vector<double> clamp_curvature;  ///< curvature at the integration point nearest the clamp, 1/m
  std::vector<double> clamp_section_moment;  ///< bending moment there, T - F s_0, N m
  double dissipated = 0.0;            ///< by the sliders over one period, J

  /// Sizes every per-sample field for `samples` samples.
  void resize(int samples);
  /// The period recorder shared by every periodic solver (the observer of Boost.Odeint):
  /// stores at sample j the cable's tip loads (F, Q), the clamp moment T and the clamp
  /// section's curvature and moment T - F s_0 of `state`.
  void record_loads(int j, const cable::CableState& state, const cable::Cable& cable);
  /// Under half-wave symmetry the first half of the samples was recorded: the second
  /// half's loads, moments and curvatures are their negatives.
  void complete_half_wave();
};

/// How an arm's periodic solve ended: termination, newton_iterations (harmonic
/// balance, collocation, shooting), periods (integrated in all), residual (each
/// solver's header says relative to what), periodicity_defect, energy_error
/// (see energy_error()), seconds. `where` says where a failure happened.
struct ArmSolution {
  ArmPeriod period;
  SolverSummary summary;
  /// Sign of the Jacobian's determinant at the solution (harmonic balance,
  /// collocation; 0 if unknown). A change of sign between neighbouring frequencies
  /// marks a fold of the response curve: several steady states there.
  int jacobian_sign = 0;
  /// Steady states found at this excitation (more than 1: the response curve folds
  /// back over this frequency; the solution is the one the continuation goes on with).
  int branches = 1;
  /// How the solution was reached, where that is worth saying ("by arclength continuation").
  std::string note;
  /// The solver's own unknowns at the solution (Fourier coefficients for harmonic
  /// balance and collocation, the initial mechanical state for shooting and time
  /// integration), used as the predictor at the next frequency.
  Eigen::VectorXd unknowns;
};

/// The sample times t_j = j T / N, j = 0..N-1, of one period, s.
std::vector<double> time_grid(const Excitation& excitation, int samples);

/// The first harmonic (2/N) sum_j y_j exp(-i W t_j) of samples y_j at t_j = j T / N.
std::complex<double> first_harmonic(const Eigen::Ref<const Eigen::RowVectorXd>& samples);

/// The arm's contribution -F(t) to the shaker force: its first harmonic, and the
/// energy error of the solution (see SolverSummary::energy_error).
std::complex<double> arm_force_first_harmonic(const ArmPeriod& period);
double energy_error(const ArmPeriod& period, const Excitation& excitation);

/// One arm's design figures over its steady period (MODEL.md sections 4 and 5).
/// Amplitudes are half the range of the period's samples (zero to peak about the
/// centre): a static offset that friction can lock into the cable is left out, since
/// it depends on how the steady state was reached (the sweep's path, the solver's
/// start), not on the excitation; where there is none they are the largest |value|.
struct ArmFigures {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  /// Z_k = F1_k / V, the arm's part of the damper's impedance (F1_k the first
  /// harmonic of -F_k): Z = i W m_c + sum_k Z_k. N s/m.
  std::complex<double> impedance{kNaN, kNaN};
  /// V^2 Re(Z_k) / 2: the mean power the arm takes from the clamp, W. The arms'
  /// powers add up to the damper's (Re Z does not depend on the clamp mass).
  double power = kNaN;
  /// The amplitude of x - b phi: how far the mass's centre of gravity G moves
  /// relative to the clamp (y_G - x_c), m; what the mass needs as clearance.
  double mass_amplitude = kNaN;
  /// The amplitude of the clamp section's curvature (ArmPeriod::clamp_curvature), 1/m.
  double clamp_curvature_amplitude = kNaN;
};

/// The design figures of `arm`'s period at `excitation`.
ArmFigures arm_figures(const ArmPeriod& period, const Arm& arm, const Excitation& excitation);

}  // namespace stockbridge::damper
