#include "stockbridge/span/undamped.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

/// The root of `f` in [a, b], where f(a) > 0 >= f(b), by TOMS 748 (Alefeld, Potra, Shi)
/// into `root`.
void refine_stable_root(const std::function<double(double)>& f, double a, double b, double fa, double fb,
                        const RootSearchOptions& options, StableRoot& root) {
  SolverSummary& summary = root.summary;
  if (fb == 0.0) {
    root.amplitude = b;
    summary.termination = Termination::converged;
    return;
  }
  const double tolerance = options.relative_tolerance;
  auto close_enough = [tolerance](double lo, double hi) { return std::abs(hi - lo) <= tolerance * std::min(lo, hi); };
  double last = a;
  const auto counted = [&](double y) {
    ++summary.evaluations;
    last = y;
    return f(y);
  };
  std::uintmax_t iterations = static_cast<std::uintmax_t>(options.max_iterations);
  try {
    const auto [lo, hi] = boost::math::tools::toms748_solve(counted, a, b, fa, fb, close_enough, iterations);
    root.amplitude = 0.5 * (lo + hi);
    summary.residual = (hi - lo) / std::min(lo, hi);
    summary.termination = close_enough(lo, hi) ? Termination::converged : Termination::max_iterations;
  } catch (const boost::math::evaluation_error&) {
    summary.termination = Termination::non_finite;
    summary.where = fmt::format("at Y = {:.3g} m", last);
  } catch (const std::domain_error&) {
    summary.termination = Termination::non_finite;
    summary.where = fmt::format("at Y = {:.3g} m", last);
  }
}

}  // namespace

void RootSearchOptions::validate() const {
  require_in_range("points_per_decade", points_per_decade, 1, 100000);
  require_positive("relative_tolerance", relative_tolerance, "");
  require_in_range("max_iterations", max_iterations, 1, 100000);
}

StableRoot smallest_stable_root(const std::function<double(double)>& net_power, double y_min, double y_max,
                                const RootSearchOptions& options) {
  options.validate();
  require_positive("y_min", y_min, "m");
  if (!(y_max > y_min && std::isfinite(y_max))) {
    throw_invalid("y_max", y_max, fmt::format("a finite value > y_min = {}", format_value(y_min)));
  }
  StableRoot root;
  SolverSummary& summary = root.summary;
  const auto sample = [&](double y) {
    ++summary.evaluations;
    const double value = net_power(y);
    if (!std::isfinite(value)) {
      summary.termination = Termination::non_finite;
      summary.where = fmt::format("at Y = {:.3g} m", y);
    }
    return value;
  };
  const int steps = std::max(1, static_cast<int>(std::ceil(options.points_per_decade * std::log10(y_max / y_min))));
  const double ratio = std::pow(y_max / y_min, 1.0 / steps);
  double a = y_min;
  double fa = sample(a);
  if (!std::isfinite(fa)) return root;
  if (fa <= 0.0) {
    summary.termination = Termination::converged;  // nothing builds up
    return root;
  }
  for (int i = 1; i <= steps; ++i) {
    const double b = i == steps ? y_max : y_min * std::pow(ratio, i);
    const double fb = sample(b);
    if (!std::isfinite(fb)) return root;
    if (fb <= 0.0) {
      refine_stable_root(net_power, a, b, fa, fb, options, root);
      return root;
    }
    a = b;
    fa = fb;
  }
  summary.termination = Termination::no_root;
  summary.where = fmt::format("up to Y = {:.3g} m", y_max);
  return root;
}

std::optional<double> undamped_amplitude(const WindModel& wind, const SelfDampingModel& self_damping,
                                         const Conductor& conductor, double tension, double span_length,
                                         double frequency) {
  auto net_power = [&](double y) {
    return wind.power(y, frequency, conductor.diameter, span_length) -
           self_damping.power(y, frequency, conductor, tension, span_length);
  };
  const StableRoot root = smallest_stable_root(net_power, undamped_search_min * conductor.diameter,
                                              undamped_search_max * conductor.diameter);
  if (!root.converged()) return std::nullopt;
  return root.amplitude;
}

}  // namespace stockbridge::span
