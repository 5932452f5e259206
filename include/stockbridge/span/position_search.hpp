#pragma once
// The dampers' best position on a span (docs/span.md, `--optimize-position`): the
// position (m from the span end's clamp), every damper moved together, that
// minimises the largest fymax stress over the band.

#include "stockbridge/span/balance.hpp"

namespace stockbridge::span {

struct PositionSearch {
  double position = 0.0;
  double max_stress_fymax = 0.0;  ///< Pa, at the position found (on the tables alone)
  int balances = 0;               ///< balance runs made
};

/// A scan of `scan_points` positions in [position_min, position_max], then a
/// golden-section refinement around the best. The balances of the search use the
/// tables without the polish (a polished balance at each of some 60 positions would
/// cost a minute), so balance the position found with the caller's options (the
/// analysis does). A position where a point does not converge is never chosen.
/// InvalidParameter naming "position_min", "position_max", "scan_points", or
/// "damper" for a span without dampers.
PositionSearch optimise_position(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                                 double position_min, double position_max, int scan_points = 41);

}  // namespace stockbridge::span
