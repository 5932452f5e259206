#pragma once
// The energy balance of a span without dampers (MODEL.md section 9), and the root
// search every balance uses.
//
// At each frequency the span vibrates at the amplitude Y where the power the wind
// feeds in equals the power dissipated. Vibration builds up from rest, so the
// amplitude is the smallest Y > 0 where the net power P_w - P_s (- P_d with
// dampers) changes from positive to negative: a stable balance (a small step up
// makes the net power negative, one down makes it positive). Where the net power
// is not positive at the smallest amplitude searched, nothing builds up: Y = 0.

#include <functional>
#include <optional>

#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/span/conductor.hpp"
#include "stockbridge/span/self_damping.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

/// How smallest_stable_root looks for the sign change.
struct RootSearchOptions {
  int points_per_decade = 40;         ///< the log grid the sign is sampled on (>= 1)
  double relative_tolerance = 1e-12;  ///< the bracket's width at the end, relative to the root
  int max_iterations = 200;           ///< refinement steps at most (TOMS 748)

  /// Throws InvalidParameter naming the field.
  void validate() const;
};

/// What smallest_stable_root found.
struct StableRoot {
  double amplitude = 0.0;  ///< the root (0: nothing builds up); meaningful only where converged
  /// converged; no_root (the net power stays positive up to y_max: no balance in the
  /// range); non_finite (the net power is not finite where it was evaluated before
  /// the root was found: `where` says at which amplitude); max_iterations (the
  /// refinement's iterations ran out: residual is the bracket's relative width).
  /// evaluations: of the net power.
  SolverSummary summary;

  bool converged() const { return summary.converged(); }
};

/// The smallest amplitude in [y_min, y_max] (0 < y_min < y_max) where `net_power`
/// changes from positive to negative:
///   * 0 when net_power(y_min) <= 0 (nothing builds up from rest);
///   * the root, refined to options.relative_tolerance, of the first grid interval
///     whose left end is > 0 and right end <= 0 (grid: options.points_per_decade
///     log-spaced amplitudes per decade, from y_min to y_max), by TOMS 748;
///   * none (no_root, non_finite: StableRoot) when the net power stays positive up
///     to y_max, or is not finite where it is evaluated before the root is found.
/// A dip of the net power below zero narrower than one grid step can be missed.
/// Throws InvalidParameter naming "y_min", "y_max" or an option for a bad range.
StableRoot smallest_stable_root(const std::function<double(double)>& net_power, double y_min, double y_max,
                                const RootSearchOptions& options = {});

/// The amplitudes the undamped balance searches, in conductor diameters: from
/// 1e-6 D to 10 D (CIGRE's reduced power is negative beyond 1.022 D).
inline constexpr double undamped_search_min = 1e-6;
inline constexpr double undamped_search_max = 10.0;

/// The antinode amplitude Y (m) of the undamped span at `frequency` (Hz):
/// smallest_stable_root of P_w(Y) - P_s(Y) over [1e-6 D, 10 D]. Inputs valid
/// (validated descriptions, check_tension); none when the net power stays positive
/// up to 10 D.
std::optional<double> undamped_amplitude(const WindModel& wind, const SelfDampingModel& self_damping,
                                         const Conductor& conductor, double tension, double span_length,
                                         double frequency);

}  // namespace stockbridge::span
