#pragma once
// Gauss-Legendre quadrature on an interval.

#include <vector>

namespace stockbridge::numerics {

struct QuadratureRule {
  std::vector<double> nodes;    ///< ascending
  std::vector<double> weights;  ///< positive, summing to the interval's length
};

/// The n-point Gauss-Legendre rule on [a, b]: exact for polynomials of degree
/// 2n - 1; for integrands with kinks (the cable's curvature at stick-slip
/// boundaries) the error falls as n^-2. Nodes by Newton's method on P_n from
/// Chebyshev guesses, accurate to round-off for n up to many thousands.
QuadratureRule gauss_legendre(int n, double a, double b);

}  // namespace stockbridge::numerics
