#include "stockbridge/span/end_fixed_point.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

void FixedPointOptions::validate() const {
  require_positive("tolerance", tolerance, "");
  require_in_range("max_sweeps", max_sweeps, 1, 100000);
  require_positive("velocity_floor", velocity_floor, "m/s");
}

namespace {

/// The end at the given velocities: the impedances there and the response; none if
/// an impedance is not known.
struct EndState {
  std::vector<std::complex<double>> z;
  EndResponse response;
};

std::optional<EndState> end_at(const StringWave& wave, const std::vector<double>& positions, const ClampImpedance& impedance,
                               double antinode, const std::vector<double>& v) {
  EndState s;
  for (std::size_t j = 0; j < v.size(); ++j) {
    const auto z = impedance(j, v[j]);
    if (!z) return std::nullopt;
    s.z.push_back(*z);
  }
  s.response = end_response(wave, positions, s.z, antinode);
  return s;
}

/// Damper j's velocity consistent with the others' (the scalar root in log v); none
/// if an impedance is not known on the way.
std::optional<double> consistent_velocity(const StringWave& wave, const std::vector<double>& positions,
                                          const ClampImpedance& impedance, double antinode, std::vector<double> v,
                                          std::size_t j, double floor) {
  const auto g = [&](double u) -> std::optional<double> {
    v[j] = std::exp(u);
    const auto s = end_at(wave, positions, impedance, antinode, v);
    if (!s) return std::nullopt;
    return std::log(std::max(wave.angular_frequency * std::abs(s->response.damper_displacement[j]), floor)) - u;
  };
  double a = std::log(std::max(v[j], floor));
  auto ga = g(a);
  if (!ga) return std::nullopt;
  if (*ga == 0.0) return std::exp(a);
  // Bracket outward by doubling steps in log v (g falls through zero as v grows).
  double step = *ga > 0.0 ? 0.1 : -0.1, b = a;
  std::optional<double> gb;
  for (int k = 0; k < 80; ++k, step *= 2.0) {
    b = a + step;
    gb = g(b);
    if (!gb) return std::nullopt;
    if ((*gb > 0.0) != (*ga > 0.0)) break;
    a = b;
    ga = gb;
  }
  if ((*gb > 0.0) == (*ga > 0.0)) return std::nullopt;
  // Regula falsi, Illinois variant: halve the weight of an end kept twice.
  int kept = 0;
  for (int k = 0; k < 200 && std::abs(b - a) > 1e-14; ++k) {
    const double c = b - *gb * (b - a) / (*gb - *ga);
    const auto gc = g(c);
    if (!gc) return std::nullopt;
    if (*gc == 0.0) return std::exp(c);
    if ((*gc > 0.0) == (*gb > 0.0)) {
      if (kept == 1) *ga *= 0.5;
      kept = 1;
    } else {
      a = b;
      ga = gb;
      kept = 0;
    }
    b = c;
    gb = gc;
  }
  return std::exp(b);
}

}  // namespace

EndSolution solve_end(const StringWave& wave, const std::vector<double>& positions, const ClampImpedance& impedance,
                      double antinode, const FixedPointOptions& options, std::vector<double> start) {
  EndSolution out;
  std::vector<double>& v = out.velocities;
  v = std::move(start);
  if (v.size() != positions.size()) {
    v.clear();
    for (const double a : positions) {
      v.push_back(std::max(wave.angular_frequency * antinode * std::abs(std::sin(wave.wavenumber * a)), options.velocity_floor));
    }
  }
  double change = 0.0;
  for (out.sweeps = 1; out.sweeps <= options.max_sweeps; ++out.sweeps) {
    change = 0.0;
    for (std::size_t j = 0; j < v.size(); ++j) {
      const auto vj = consistent_velocity(wave, positions, impedance, antinode, v, j, options.velocity_floor);
      if (!vj) {
        out.failure = fmt::format("damper {}: its impedance is not known near {:.3g} m/s", j + 1, v[j]);
        return out;
      }
      change = std::max(change, std::abs(*vj - v[j]) / std::max(*vj, options.velocity_floor));
      v[j] = *vj;
    }
    if (change <= options.tolerance || v.size() <= 1) break;
  }
  const auto state = end_at(wave, positions, impedance, antinode, v);
  if (!state) {
    out.failure = "an impedance is not known at the fixed point";
    return out;
  }
  out.response = state->response;
  out.impedances = state->z;
  out.converged = change <= options.tolerance || v.size() <= 1;
  if (!out.converged) {
    out.failure = fmt::format("the dampers' velocities still changed by {:.3g} (relative) after {} sweeps", change,
                              options.max_sweeps);
  }
  return out;
}

}  // namespace stockbridge::span
