#include "stockbridge/span/position_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

PositionSearch optimise_position(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                                 double position_min, double position_max, int scan_points) {
  require_positive("position_min", position_min, "m");
  if (!(position_max > position_min)) throw_invalid("position_max", position_max, "a value > position_min (m)");
  require_in_range("scan_points", scan_points, 3, 10000);
  if (span.dampers().empty()) throw InvalidParameter("damper", ": a position search needs at least one [[damper]]");
  PositionSearch best;
  BalanceOptions scan = options;
  scan.polish = false;
  const auto largest_stress = [&](double a) {
    ++best.balances;
    const SpanBalance b = run_balance(span.with_dampers_at(a), tables, scan);
    // A point that did not converge counts as the worst: never chosen for it.
    return b.summary.all_converged() ? b.summary.max_stress_fymax : std::numeric_limits<double>::infinity();
  };
  // The scan finds the best basin (the stress over position has a local minimum near
  // every node of the shortest waves); golden sections then refine within it.
  const double step = (position_max - position_min) / (scan_points - 1);
  std::vector<double> stress(static_cast<std::size_t>(scan_points));
  std::size_t k_best = 0;
  for (std::size_t k = 0; k < stress.size(); ++k) {
    stress[k] = largest_stress(position_min + static_cast<double>(k) * step);
    if (stress[k] < stress[k_best]) k_best = k;
  }
  double lo = std::max(position_min, position_min + (static_cast<double>(k_best) - 1.0) * step);
  double hi = std::min(position_max, position_min + (static_cast<double>(k_best) + 1.0) * step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = largest_stress(x1), f2 = largest_stress(x2);
  while (hi - lo > 1e-3 * step) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = largest_stress(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = largest_stress(x2);
    }
  }
  best.position = f1 <= f2 ? x1 : x2;
  best.max_stress_fymax = std::min(f1, f2);
  if (stress[k_best] < best.max_stress_fymax) {
    best.position = position_min + static_cast<double>(k_best) * step;
    best.max_stress_fymax = stress[k_best];
  }
  return best;
}

}  // namespace stockbridge::span
