#pragma once
// The damper schedule of a line (docs/line.md): for each span the undamped figures,
// then the recommended arrangement: the fewest dampers per end (min_per_end to
// max_per_end) of any damper type, at positions searched together
// (span::optimise_positions on the tables alone, then rounded to position_step),
// whose polished balance makes the span safe; among the types that need that many,
// the best by the objective. A span no arrangement makes safe gets the best of
// max_per_end, unsafe, with a warning. A span with masses (warning spheres) also gets,
// in every arrangement, a damper of the type on either side of each mass, at one
// distance chosen for the span (ScheduleRules::sphere_dampers). One span is one task: the CLI deals them to
// threads and MPI ranks; the impedance tables come from a TableCache shared by all.

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/line/line.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/table_cache.hpp"

namespace stockbridge::line {

/// The damper types' impedance tables by type, frequencies and table options: a
/// table depends on the damper and the frequencies alone (not the span), so spans of
/// one conductor and wind share it, whichever thread asks first.
using TableCache = span::TableCache<span::ImpedanceTable>;

/// One span's line of the schedule. Stresses in Pa; NaN where nothing converged.
struct ScheduleRow {
  std::size_t index = 0;  ///< the span's place in the line
  std::string id;
  double length = 0.0;              ///< m
  double tension = 0.0;             ///< N
  double tension_fraction = 0.0;    ///< of the RTS
  double catenary_parameter = 0.0;  ///< H/w, m
  double span_parameter = 0.0;      ///< L D / m, m^3/kg
  std::string conductor;            ///< its name
  int terrain = 0;                  ///< TB 273's category, 0: not given
  int terrain_within = -1;          ///< H/w within its limit: 1, 0; -1: no terrain given
  double endurance_limit = 0.0;     ///< Pa

  double undamped_max_stress = 0.0;  ///< over the undamped balance's points
  double undamped_life_years = 0.0;  ///< NaN: no climate or a point missing; inf: no damage
  span::Verdict undamped_verdict = span::Verdict::unknown;

  std::string damper_type;         ///< empty with no dampers
  int per_end = 0;
  std::vector<double> positions;   ///< m from the clamp, increasing; both ends alike
  /// The dampers of the type beside the span's masses (two a mass position; 0: none)
  /// and their distance from each mass, m (NaN: none).
  int sphere_dampers = 0;
  double sphere_distance = std::numeric_limits<double>::quiet_NaN();
  /// The largest stress the criterion judges over the converged points (fymax, or
  /// Poffenberger-Swart under the microstrain criterion), and the top of a measured
  /// sheet's band there (NaN without one).
  double max_stress = 0.0;
  double max_stress_high = std::numeric_limits<double>::quiet_NaN();
  double max_stress_frequency = 0.0;  ///< Hz
  /// Where that largest stress is: "span clamp 1", "span clamp 2" or a mass's clamp
  /// ("sphere at 120 m"): BalanceSummary::max_judged_stress_place; empty where
  /// nothing converged.
  std::string governing_place;
  double life_years = 0.0;         ///< as undamped_life_years
  span::Verdict verdict = span::Verdict::unknown;
  /// What judged the span without dampers safe where it gets none: "balance" (its
  /// own), "tb273" (UndampedRule::tb273: its H/w within its terrain's limit; the
  /// undamped balance's figures still beside it); empty where it has dampers.
  std::string no_damper_basis;
  int converged = 0, points = 0;   ///< of the recommended arrangement's balance
  int balances = 0;                ///< the search's balances (its cost)
  std::vector<std::string> warnings;

  /// max_stress / endurance_limit.
  double stress_ratio() const { return max_stress / endurance_limit; }
};

/// A span's schedule row, and the analysis of its recommended arrangement (the span
/// without dampers where it needs none).
struct SpanSchedule {
  ScheduleRow row;
  span::SpanAnalysis analysis;
};

/// The impedance table of damper type `type` at `frequencies` with `options`, from
/// the cache (made there once, by whichever thread asks first).
std::shared_ptr<const span::ImpedanceTable> type_table(const Line& line, std::size_t type,
                                                     const std::vector<double>& frequencies,
                                                     const span::ImpedanceTableOptions& options, TableCache& cache);

/// Schedules span `index` of `line`. `stop` (when given) is asked between balances:
/// true throws Interrupted. Non-convergence is in the row (verdict unknown,
/// converged < points, a warning), never an exception.
SpanSchedule schedule_span(const Line& line, std::size_t index, TableCache& cache, const std::function<bool()>& stop = {});

/// The analysis of span `index` with the row's arrangement (what --details writes
/// and `stockbridge span` reproduces): the same balance schedule_span made.
span::SpanAnalysis analyse_arrangement(const Line& line, const ScheduleRow& row, TableCache& cache);

/// The bill of materials: dampers of each type over the line (2 per_end a span, and
/// those beside its masses).
struct BillLine {
  std::string damper_type;
  int dampers = 0;
  int spans = 0;
  std::optional<double> mass;   ///< kg, all of them, where the type's mass is known
  std::optional<double> price;  ///< all of them, where the type's price is known
};
std::vector<BillLine> bill_of_materials(const Line& line, const std::vector<ScheduleRow>& rows);

/// What a schedule comes to: spans by verdict, spans not converged throughout, spans
/// whose dampers raise the stress above the undamped one, spans by dampers per end,
/// and the governing span (the largest stress ratio among those converged throughout
/// and judged by their balance: not a span TB 273's rule spares dampers).
struct ScheduleCounts {
  int safe = 0, unsafe = 0, unknown = 0, uncertain = 0;
  int not_converged = 0;
  int worse_than_undamped = 0;
  std::map<int, int> per_end;  ///< dampers per end -> spans
  const ScheduleRow* governing = nullptr;  ///< into the rows counted; none where no span converged
};
ScheduleCounts schedule_counts(const std::vector<ScheduleRow>& rows);

/// The rows' warnings grouped by kind: warnings that differ only in their numbers
/// (the same message of the same damper type on other spans) become one line, the
/// first span's text with how many spans gave it and their ids ("(3 spans: T01,
/// T04, T07; the figures are T01's)"), in the order of their first span.
std::vector<std::string> grouped_warnings(const std::vector<ScheduleRow>& rows);

}  // namespace stockbridge::line
