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

/// The estimates' statistics from the Jacobian J at the optimum (m x n) and the
/// sum of squares S there. With C = (J^T J)^+:
///   standard error of x_i:  sqrt(S / (m - n) C_ii)   (m > n; else infinity)
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
  double residual_scatter = 0.0;  ///< sqrt(S / (m - n)): the residuals' own (infinity for m = n)
  Eigen::MatrixXd null_space;     ///< its basis vectors as columns
};
Statistics statistics(const Eigen::MatrixXd& jacobian, double sum_of_squares, double scatter);

}  // namespace stockbridge::identification::least_squares
