#pragma once
// The dampers' best positions on a span (docs/span.md, `--optimize-position`;
// docs/line.md): each damper's own distance from the span end's clamp, within
// [position_min, position_max] and at least spacing_min from its neighbours, that
// minimises an objective over the band: the largest fymax stress relative to the
// endurance limit, or the damage per year (the life's inverse). One damper: a scan
// and golden sections; several: NLopt's COBYLA from the best of the usual starting
// arrangements (MODEL.md section 12: the first damper at a fraction of the shortest
// loop, the others at growing spacings).

#include <functional>
#include <string_view>
#include <vector>

#include "stockbridge/span/balance.hpp"

namespace stockbridge::span {

/// What the search minimises: max_stress, the largest fymax stress over the
/// endurance limit; life, log10 of Miner's damage per year (the span file must give
/// the climate).
enum class PositionObjective { max_stress, life };
/// Its name in outputs ("max_stress", "life"; a user's name is parsed by io::parse_position_objective).
std::string_view position_objective_name(PositionObjective objective);

struct PositionRules {
  double position_min = 0.5;  ///< m from the span end's clamp
  double position_max = 8.0;  ///< m
  double spacing_min = 0.5;   ///< m between two dampers (at one end)
  PositionObjective objective = PositionObjective::max_stress;
  int scan_points = 41;       ///< one damper: the scan before the golden sections (>= 3)
  int max_evaluations = 60;   ///< several dampers: each local search's balances at most (>= 4)
  int local_searches = 2;     ///< several dampers: local searches, from the best starts (>= 1)

  /// Throws InvalidParameter naming "position_min", "position_max", "spacing_min",
  /// "scan_points", "max_evaluations" or "local_searches".
  void validate() const;
};

struct PositionSearch {
  std::vector<double> positions;  ///< m, each damper's, in the span's order
  PositionObjective criterion = PositionObjective::max_stress;  ///< what was minimised
  double objective = 0.0;         ///< at `positions`, on the tables alone
  double max_stress_fymax = 0.0;  ///< Pa, the same
  int balances = 0;               ///< balance runs made
  /// Frequencies balanced over all of them: an arrangement shown unable to win stops
  /// at the point that shows it (max_stress), so this is less than balances times
  /// the tables' frequencies.
  int points = 0;
  /// Several dampers: the best arrangement of each other local search (every
  /// damper's positions, span order), best first. On the tables alone two basins'
  /// objectives can rank otherwise than their polished balances do: a caller may
  /// balance these too.
  std::vector<std::vector<double>> runners_up;
};

/// The objective of a balance: +inf where a point did not converge (or, for the
/// life, where the span gives no climate).
double position_objective(const SpanBalance& balance, PositionObjective objective);

/// The span's shortest loop c / (2 f_max), m: c = sqrt(T / m), f_max the top of its
/// wind band (St speed_max / D). Practice places the first damper at a fraction of it.
double shortest_loop(const Span& span);

/// The usual first arrangement of `count` dampers (m from the clamp, increasing):
/// the first at `fraction` of the shortest loop c / (2 f_max) (c = sqrt(T / m),
/// f_max the band's top frequency), each further one 1.3 times the previous
/// spacing beyond it (at least spacing_min), all within the rules' range.
std::vector<double> usual_positions(const Span& span, double f_max, int count, double fraction, const PositionRules& rules);

/// The search over the span's dampers (every one its own position; dampers of one
/// end keep their order). The balances use the tables without the polish (a polished
/// balance at each of some 60 arrangements would cost a minute): balance the answer
/// with the caller's options (the analysis does). An arrangement where a point does
/// not converge is never chosen. `stop` (when given) is asked before every balance;
/// true makes the search throw Interrupted. InvalidParameter naming a rule, "damper"
/// for a span without dampers, "spacing_min" where the dampers cannot fit, or
/// "objective" for the life without a climate.
PositionSearch optimise_positions(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                                  const PositionRules& rules, const std::function<bool()>& stop = {});

}  // namespace stockbridge::span
