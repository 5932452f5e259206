// The schedule's recommendation rule, checked from outside the search: a span
// recommended with n dampers per end is unsafe with n - 1 at their best positions
// (one damper: the best of a 5 cm grid over the whole range, polished; none: the
// undamped balance), and every row is the balance of its span file (the text
// --details writes), read and balanced as `stockbridge span` does, to 1e-9: a span
// with warning spheres and the dampers beside them too. The schedule against a
// stored one: the same counts, no largest stress 0.5 % higher.

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/io/line_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/line/schedule.hpp"

namespace stockbridge::line {
namespace {

const std::string kSauterDamper = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml";

std::string verification_line() {
  return R"([line]
points = 30
search_points = 20
[conductor]
type = "AAAC ASTER570"
[wind]
law = "cigre"
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 5e8
[dampers]
types = [ { name = "sb1", file = ")" + kSauterDamper + R"(" } ]
max_per_end = 2
position_max = 5.0
[[span]]
id = "low"
length = 300
tension_fraction = 0.11
[[span]]
id = "high"
length = 420
tension_fraction = 0.19
[[span]]
id = "drake"
length = 350
tension = 30000
conductor = "ACSR Drake"
)";
}

/// The largest fymax stress of one damper per end at the best few of a 5 cm grid
/// (on the search's tables), each polished: the least of them.
double best_one_damper_stress(const Line& line, std::size_t index, TableCache& cache) {
  const LineSpan& s = line.spans()[index];
  const std::vector<double> f = span::band_frequencies(s.span, line.rules().search_points);
  const auto table = type_table(line, 0, f, s.balance.table.for_position_search(), cache);
  const span::SpanTables tables(f, {*table});
  span::BalanceOptions on_tables = s.balance;
  on_tables.polish = false;
  std::vector<std::pair<double, double>> grid;  // (stress, position)
  const span::PositionRules& rules = line.rules().positions;
  for (double x = rules.position_min; x <= rules.position_max + 1e-9; x += 0.05) {
    const span::SpanBalance b =
        span::run_balance(with_arrangement(s.span, line.types()[0], Arrangement{{x}, std::nullopt}), tables, on_tables);
    if (b.summary.all_converged()) grid.emplace_back(b.summary.max_stress_fymax, x);
  }
  std::sort(grid.begin(), grid.end());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 3 && k < grid.size(); ++k) {
    ScheduleRow row;
    row.index = index;
    row.damper_type = line.types()[0].name;
    row.positions = {grid[k].second};
    const span::SpanAnalysis a = analyse_arrangement(line, row, cache);
    if (a.balance.summary.all_converged()) best = std::min(best, a.balance.summary.max_stress_fymax);
  }
  return best;
}

/// The schedule of verification_line() as stored on 2026-11-29 (the same as before
/// the search's balances were made faster): a change of the search may move the
/// positions, never to more dampers or to a largest stress 0.5 % higher.
struct StoredRow {
  int per_end;
  double max_stress_mpa;
};
constexpr StoredRow kStoredSchedule[] = {{1, 8.3713}, {2, 6.6569}, {2, 6.1284}};

TEST(LineSchedule, ARecommendationOfNPerEndIsUnsafeWithOneFewer) {
  const io::LineFile file = io::load_line_text(verification_line(), "line(text=...)");
  TableCache cache;
  int checked_two = 0;
  for (std::size_t i = 0; i < file.line.spans().size(); ++i) {
    const SpanSchedule s = schedule_span(file.line, i, cache);
    const ScheduleRow& row = s.row;
    SCOPED_TRACE(row.id);
    EXPECT_EQ(row.per_end, kStoredSchedule[i].per_end);
    EXPECT_LE(row.max_stress / 1e6, 1.005 * kStoredSchedule[i].max_stress_mpa);
    ASSERT_EQ(row.converged, row.points);
    EXPECT_EQ(row.verdict, span::Verdict::safe);
    EXPECT_LE(row.max_stress, row.endurance_limit);
    ASSERT_GE(row.per_end, 1) << "every span of this line needs dampers";
    EXPECT_EQ(row.undamped_verdict, span::Verdict::unsafe);
    // Positions installable: on the 1 cm step, in the range, spaced.
    for (std::size_t k = 0; k < row.positions.size(); ++k) {
      EXPECT_NEAR(row.positions[k] * 100.0, std::round(row.positions[k] * 100.0), 1e-6);
      EXPECT_GE(row.positions[k], file.line.rules().positions.position_min);
      EXPECT_LE(row.positions[k], file.line.rules().positions.position_max);
      if (k > 0) {
        EXPECT_GE(row.positions[k] - row.positions[k - 1], file.line.rules().positions.spacing_min - 1e-9);
      }
    }
    if (row.per_end == 2) {
      ++checked_two;
      EXPECT_GT(best_one_damper_stress(file.line, i, cache), row.endurance_limit);
    }
    // The row is its span file's balance.
    const io::SpanFile again = io::load_span_text(io::span_file_text(file, row), "details");
    span::AnalysisOptions options;
    options.balance = again.balance;
    const span::SpanAnalysis a =
        span::analyse_span(again.span, span::band_frequencies(again.span, file.line.rules().points), options);
    EXPECT_NEAR(a.balance.summary.max_stress_fymax, row.max_stress, 1e-9 * row.max_stress);
    EXPECT_EQ(a.balance.summary.undamped_max_stress_fymax, row.undamped_max_stress);
  }
  EXPECT_GE(checked_two, 1) << "no span of the line needed two dampers per end: the rule's check did not run";
}

// A span with two warning spheres: its row (the dampers at the ends and those
// beside the spheres) is its span file's balance, the masses and every damper
// written there; its largest judged stress and its place, and the undamped one, to 1e-9.
TEST(LineSchedule, TheRowOfASpanWithSpheresIsItsSpanFilesBalance) {
  std::string text = verification_line();
  text = text.substr(0, text.find("[[span]]"));
  const std::string points = "points = 30\nsearch_points = 20";
  text.replace(text.find(points), points.size(), "points = 16\nsearch_points = 10");
  text += "sphere_distance_min = 1.5\nsphere_distance_max = 1.5\n"  // one distance: the scan is the unit tests'
          "[[span]]\nid = \"spheres\"\nlength = 400\ntension_fraction = 0.15\n"
          "[[span.mass]]\nname = \"sphere\"\nmass = 12.5\npositions = [150, 250]\n";
  const io::LineFile file = io::load_line_text(text, "line(text=...)");
  TableCache cache;
  const ScheduleRow row = schedule_span(file.line, 0, cache).row;
  ASSERT_EQ(row.converged, row.points);
  ASSERT_GE(row.per_end, 1);
  EXPECT_EQ(row.sphere_dampers, 4);
  EXPECT_EQ(row.sphere_distance, 1.5);
  const io::SpanFile again = io::load_span_text(io::span_file_text(file, row), "details");
  ASSERT_EQ(again.span.masses().size(), 1u);
  ASSERT_EQ(again.span.dampers().size(), static_cast<std::size_t>(row.per_end) + 1);
  span::AnalysisOptions options;
  options.balance = again.balance;
  const span::SpanAnalysis a =
      span::analyse_span(again.span, span::band_frequencies(again.span, file.line.rules().points), options);
  EXPECT_NEAR(a.balance.summary.max_judged_stress, row.max_stress, 1e-9 * row.max_stress);
  EXPECT_EQ(a.balance.summary.max_judged_stress_place, row.governing_place);
  EXPECT_EQ(a.balance.summary.undamped_max_judged_stress, row.undamped_max_stress);
}

}  // namespace
}  // namespace stockbridge::line
