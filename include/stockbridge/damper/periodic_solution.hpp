#pragma once
// What every periodic-steady-state solver returns for one arm, and how it ended.

#include <complex>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/damper/damper.hpp"

namespace stockbridge::damper {

/// How a solver ended. A solution is used only if `converged`.
struct SolverSummary {
  bool converged = false;
  int iterations = 0;     ///< Newton (or period) iterations
  int evaluations = 0;    ///< periodic evaluations of the cable (harmonic balance, collocation)
  int jacobians = 0;      ///< of which with exact sensitivities
  double residual = std::numeric_limits<double>::quiet_NaN();      ///< final residual, relative (see each solver)
  /// |P - D/T| relative to the apparent power V |F1| / 2: P the mean input power
  /// from the first harmonic, D the sliders' dissipation per period.
  double energy_error = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;   ///< wall time
  int periods = 0;        ///< periods of the cable run to make its state periodic (harmonic balance, collocation)
  double periodicity_defect = 0.0;  ///< relative change of the loads over the last period
  /// Sign of the Jacobian's determinant at the solution (harmonic balance,
  /// collocation; 0 if unknown). A change of sign between neighbouring frequencies
  /// marks a fold of the response curve: several steady states there.
  int jacobian_sign = 0;
  /// Steady states found at this excitation (more than 1: the response curve folds
  /// back over this frequency; the solution is the one the continuation goes on with).
  int branches = 1;
  std::string message;    ///< why it did not converge (where and by how much), or notes
};

/// One arm's steady periodic motion, sampled at t_j = j T / N, j = 0..N-1.
struct ArmPeriod {
  Eigen::Matrix2Xd kinematics;        ///< (x, phi), m and rad
  Eigen::Matrix2Xd loads;             ///< (F, Q), N and N m
  std::vector<double> clamp_moment;   ///< T, N m
  std::vector<double> clamp_curvature;  ///< curvature at the integration point nearest the clamp, 1/m
  std::vector<double> clamp_section_moment;  ///< bending moment there, T - F s_0, N m
  double dissipated = 0.0;            ///< by the sliders over one period, J
};

struct ArmSolution {
  ArmPeriod period;
  SolverSummary summary;
  /// The solver's own unknowns at the solution (Fourier coefficients for harmonic
  /// balance and collocation, the initial mechanical state for shooting and time
  /// integration), used as the predictor at the next frequency.
  Eigen::VectorXd unknowns;
};

/// The first harmonic (2/N) sum_j y_j exp(-i W t_j) of samples y_j at t_j = j T / N.
std::complex<double> first_harmonic(const Eigen::Ref<const Eigen::RowVectorXd>& samples);

/// The arm's contribution -F(t) to the shaker force: its first harmonic, and the
/// energy error of the solution (see SolverSummary::energy_error).
std::complex<double> arm_force_first_harmonic(const ArmPeriod& period);
double energy_error(const ArmPeriod& period, const Excitation& excitation);

}  // namespace stockbridge::damper
