#include "stockbridge/numerics/gauss_legendre.hpp"

#include <cmath>
#include <numbers>

#include "stockbridge/core/error.hpp"

namespace stockbridge::numerics {

QuadratureRule gauss_legendre(int n, double a, double b) {
  require_in_range("quadrature points", n, 1, 1000000);
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  const double half = 0.5 * (b - a);
  const double mid = 0.5 * (a + b);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0;
      double p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    rule.nodes[i] = mid - half * x;
    rule.nodes[n - 1 - i] = mid + half * x;
    rule.weights[i] = rule.weights[n - 1 - i] = half * weight;
  }
  return rule;
}

}  // namespace stockbridge::numerics
