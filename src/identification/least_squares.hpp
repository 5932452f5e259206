#pragma once
// Nonlinear least squares for the identification from impedance (private to the
// library): Levenberg-Marquardt (Eigen's port of MINPACK's lmder) on residuals and
// a Jacobian the caller provides, and what the Jacobian at the optimum says about
// the estimates.

#include <vector>

#include <Eigen/Core>

#include "stockbridge/numerics/solver_summary.hpp"

namespace stockbridge::identification::least_squares {

/// Residuals r(x) (m of them) of n <= m variables, and their Jacobian dr/dx.
class Problem {
 public:
  virtual ~Problem() = default;
  virtual int variables() const = 0;
  virtual int residual_count() const = 0;
  virtual Eigen::VectorXd residuals(const Eigen::VectorXd& x) = 0;
  virtual Eigen::MatrixXd jacobian(const Eigen::VectorXd& x) = 0;
};

struct Run {
  Eigen::VectorXd x;          ///< the best point reached
  double sum_of_squares = 0;  ///< |r(x)|^2
  int jacobians = 0;          ///< iterations
  /// converged (a step changed |r| or x by less than the tolerance, or r is
  /// orthogonal to J's columns); max_iterations (max_jacobians used up); no_progress
  /// (the tolerances cannot be met in floating point); inner_failure (bad input).
  /// residual: |r|, jacobians, evaluations.
  SolverSummary summary;
};

/// Levenberg-Marquardt from x for at most `max_jacobians` iterations; stops earlier
/// where a step changes |r| or x by a relative 1e-10. The trust region is a ball in
/// the variables (which should be of order one), of radius `first_step` at first.
Run levenberg_marquardt(Problem& problem, Eigen::VectorXd x, int max_jacobians, double first_step = 1.0);

/// The estimates' statistics from the Jacobian J at the optimum (m x n, rank k) and
/// the sum of squares S there. With C = (J^T J)^+:
///   standard error of x_i:  sigma sqrt(C_ii), sigma = max(sqrt(S / (m - k)),
///                           `error_floor`): the residuals' own scatter, or the
///                           floor where that is larger (m > k; else infinity)
///   resolution of x_i:      scatter sqrt(C_ii): the standard error the residuals
///                           would give at a scatter of `scatter` each
///   sensitivity of x_i:     |J_i| / sqrt(m), the column's RMS
/// A variable with a component in J's null space (a singular value below 1e-9 of
/// the largest) has infinite standard error and resolution.
struct Statistics {
  Eigen::VectorXd standard_error;
  Eigen::VectorXd resolution;
  Eigen::VectorXd sensitivity;
  Eigen::MatrixXd correlation;   ///< C_ij / sqrt(C_ii C_jj); NaN in rows and columns of null-space variables
  Eigen::MatrixXd covariance;    ///< C = (J^T J)^+, per unit scatter
  std::vector<bool> in_null_space;
  /// The resolution of a linear combination g . x of the variables (infinity where
  /// it has a component in the null space).
  double resolution_of(const Eigen::VectorXd& g) const;
  /// Its standard error (infinity likewise).
  double standard_error_of(const Eigen::VectorXd& g) const;
  double scatter = 0.0;           ///< the one asked for the resolutions
  double residual_scatter = 0.0;  ///< sqrt(S / (m - k)): the residuals' own (infinity for m = k)
  double error_scatter = 0.0;     ///< max(residual_scatter, error_floor): the standard errors'
  int rank = 0;                   ///< k: n less the null space's dimension
  Eigen::MatrixXd null_space;     ///< its basis vectors as columns
};
Statistics statistics(const Eigen::MatrixXd& jacobian, double sum_of_squares, double scatter, double error_floor = 0.0);

/// The chi-square test of a sum of squares against a stated scatter: with residuals
/// of independent errors of standard deviation sigma, S / sigma^2 follows the
/// chi-square distribution with `degrees_of_freedom` (m - k) degrees of freedom.
struct ChiSquareTest {
  double statistic = 0.0;       ///< S / sigma^2
  int degrees_of_freedom = 0;
  double p_value = 1.0;         ///< P(chi2 >= statistic); NaN without degrees of freedom
  double critical = 0.0;        ///< the chi2 quantile at 1 - level (NaN likewise)
  double level = 0.0;
  bool significant = false;     ///< p_value < level: the residuals exceed the scatter
};
/// Boost.Math's chi-square distribution; `degrees_of_freedom` <= 0 gives no test
/// (p_value and critical NaN, not significant).
ChiSquareTest chi_square_test(double statistic, int degrees_of_freedom, double level);

/// What one more variable, whose Jacobian column is `column`, would do at the
/// optimum x of residuals r and Jacobian J (the Gauss-Newton step of the
/// augmented problem [J, column]): with c' the part of `column` outside J's range,
///   reduction = (c' . r)^2 / |c'|^2   (of |r|^2; 0 where |c'| <= 1e-9 |column|)
///   step      = -(c' . r) / |c'|^2    (the new variable's)
///   shift     = -J^+ column step      (the fitted variables' change with it)
struct ExtraVariable {
  double reduction = 0.0;
  double step = 0.0;
  Eigen::VectorXd shift;
};
ExtraVariable extra_variable(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals,
                             const Eigen::VectorXd& column);

}  // namespace stockbridge::identification::least_squares
