#pragma once
// Dense linear solves that say when the matrix is numerically singular, so that a
// Newton step is never taken from a matrix that carries no digits.

#include <Eigen/LU>

namespace stockbridge::numerics {

/// Below this estimated reciprocal condition number (1-norm) a matrix counts as
/// singular: a solve with it may lose every digit (the bound is about 450 machine
/// epsilons). The example damper's Jacobians at converged points lie between 1e-6
/// and 2e-3; exactly at an undamped linear resonance, near 1e-19.
inline constexpr double singular_reciprocal_condition = 1e-13;

/// LU with partial pivoting: x = A^-1 b. Returns the estimated reciprocal condition
/// number of A; the solve is untrustworthy (x is then left as computed) when that
/// is below singular_reciprocal_condition or x is not finite (see is_singular).
template <typename Matrix, typename Vector>
double solve_checked(const Matrix& a, const Vector& b, Vector& x) {
  const Eigen::PartialPivLU<Matrix> lu(a);
  x = lu.solve(b);
  return lu.rcond();
}

/// Whether a solve_checked result is to be rejected.
template <typename Vector>
bool is_singular(double reciprocal_condition, const Vector& x) {
  return !(reciprocal_condition >= singular_reciprocal_condition) || !x.allFinite();
}

}  // namespace stockbridge::numerics
