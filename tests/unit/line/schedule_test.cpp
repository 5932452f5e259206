// A line's schedule rules at work on small lines of short spans, their damper types
// known by the example vendor's measured sheet (nothing solved: each span takes a
// fraction of a second): CIGRE TB 273's rule for the spans needing no damper, the
// type chosen by mass or price among those equally good, the bill's price, and an
// uncertain verdict accepted or not; the dampers beside a span's warning spheres.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"

namespace stockbridge::line {
namespace {

const std::string kExamplesFolder = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples";

/// A line of ASTER570 (Drake where `conductor` says so) with few frequencies, the
/// damper types `types` and the rules `rules` of [dampers], and `spans`.
std::string sheet_line(const std::string& types, const std::string& rules, const std::string& spans,
                       const std::string& conductor = "AAAC ASTER570", const std::string& points = "points = 20\nsearch_points = 12\n") {
  return "[line]\n" + points + "[conductor]\ntype = \"" + conductor +
         "\"\n[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n"
         "[dampers]\ntypes = [ " + types + " ]\n" + rules + spans;
}

io::LineFile load_sheet_line(const std::string& text) {
  return io::load_line_text(text, "line(text=...)", kExamplesFolder);
}

std::string line_error_of(const std::string& text) {
  try {
    load_sheet_line(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string kVendor = "{ name = \"vendor\", impedance = \"vendor_sheet.csv\", mass = 2.4 }";

/// Two short spans at H/w = 1300 m: "A" in terrain category 4 (TB 273's limit 1425 m),
/// "B" of no terrain. Both unsafe without dampers (35 MPa against 8.73 MPa).
const std::string kTwoShortSpans =
    "[[span]]\nid = \"A\"\nlength = 150\ncatenary_parameter = 1300\nterrain = 4\n"
    "[[span]]\nid = \"B\"\nlength = 150\ncatenary_parameter = 1300\n";

// undamped_rule = "tb273": a span whose H/w is within its terrain's limit gets no
// damper, safe by that rule, its undamped balance (unsafe) still in the row; a span
// of no terrain is judged by its balance and gets dampers.
TEST(LineSchedule, TheTb273RuleLeavesASpanWithinItsTerrainsLimitUndamped) {
  const io::LineFile f =
      load_sheet_line(sheet_line(kVendor, "max_per_end = 2\nposition_max = 4.0\nundamped_rule = \"tb273\"\n", kTwoShortSpans));
  TableCache cache;
  const SpanSchedule a = schedule_span(f.line, 0, cache);
  EXPECT_EQ(a.row.per_end, 0);
  EXPECT_EQ(a.row.damper_type, "");
  EXPECT_EQ(a.row.no_damper_basis, "tb273");
  EXPECT_EQ(a.row.verdict, span::Verdict::safe);
  EXPECT_EQ(a.row.terrain, 4);
  EXPECT_EQ(a.row.terrain_within, 1);
  EXPECT_EQ(a.row.undamped_verdict, span::Verdict::unsafe);
  EXPECT_EQ(a.row.undamped_max_stress, a.analysis.balance.summary.undamped_max_judged_stress);
  EXPECT_NEAR(a.row.undamped_max_stress, 35.07e6, 0.01e6);
  EXPECT_GT(a.row.undamped_max_stress, a.row.endurance_limit);
  EXPECT_EQ(a.row.converged, 20);
  ASSERT_FALSE(a.row.warnings.empty());
  EXPECT_EQ(a.row.warnings.front(), "no dampers by CIGRE TB 273: H/w 1300 m is within the 1425 m of terrain category 4; "
                                    "the energy balance without dampers judges it unsafe (largest stress 35.1 MPa)");
  EXPECT_TRUE(a.analysis.span.dampers().empty());

  const SpanSchedule b = schedule_span(f.line, 1, cache);
  EXPECT_EQ(b.row.terrain_within, -1);
  EXPECT_EQ(b.row.damper_type, "vendor");
  EXPECT_EQ(b.row.per_end, 1);
  EXPECT_EQ(b.row.no_damper_basis, "");
  EXPECT_EQ(b.row.verdict, span::Verdict::safe);
  EXPECT_LT(b.row.max_stress, b.row.endurance_limit);
  // Span A's undamped stress, beside it, does not govern the schedule: B does.
  const std::vector<ScheduleRow> rows{a.row, b.row};
  ASSERT_NE(schedule_counts(rows).governing, nullptr);
  EXPECT_EQ(schedule_counts(rows).governing->id, b.row.id);

  // By the default rule, its balance: span A gets the dampers B gets.
  const io::LineFile by_balance = load_sheet_line(sheet_line(kVendor, "max_per_end = 2\nposition_max = 4.0\n", kTwoShortSpans));
  const SpanSchedule balanced = schedule_span(by_balance.line, 0, cache);
  EXPECT_EQ(balanced.row.per_end, 1);
  EXPECT_EQ(balanced.row.no_damper_basis, "");
  EXPECT_EQ(balanced.row.positions, b.row.positions);
}

/// The same sheet as two types, one heavier but cheaper, the heavier listed first or not.
std::string two_types(bool heavy_first) {
  const std::string heavy = "{ name = \"heavy-cheap\", impedance = \"vendor_sheet.csv\", mass = 3.0, price = 40 }";
  const std::string light = "{ name = \"light-dear\", impedance = \"vendor_sheet.csv\", mass = 2.0, price = 60 }";
  return heavy_first ? heavy + ", " + light : light + ", " + heavy;
}

const std::string kOneShortSpan = "[[span]]\nid = \"B\"\nlength = 150\ncatenary_parameter = 1300\n";

// Both types make the span safe with one damper per end, at the same positions:
// the lighter is chosen by default, the cheaper under fewest-then-cheapest, each
// listed second (not the first type by a tie).
TEST(LineSchedule, AmongTypesEquallyGoodTheLighterOrTheCheaperIsChosen) {
  const std::string rules = "max_per_end = 1\nposition_max = 4.0\n";
  TableCache cache;
  const io::LineFile lightest = load_sheet_line(sheet_line(two_types(true), rules, kOneShortSpan));
  EXPECT_EQ(lightest.line.rules().choose, TypeChoice::fewest_then_lightest);
  const SpanSchedule light = schedule_span(lightest.line, 0, cache);
  EXPECT_EQ(light.row.damper_type, "light-dear");
  EXPECT_EQ(light.row.per_end, 1);
  EXPECT_EQ(light.row.verdict, span::Verdict::safe);
  const std::vector<BillLine> bill = bill_of_materials(lightest.line, {light.row});
  ASSERT_EQ(bill.size(), 2u);
  EXPECT_EQ(bill[0].damper_type, "heavy-cheap");
  EXPECT_EQ(bill[0].dampers, 0);
  EXPECT_EQ(bill[0].price, 0.0);
  EXPECT_EQ(bill[1].damper_type, "light-dear");
  EXPECT_EQ(bill[1].dampers, 2);
  EXPECT_EQ(bill[1].spans, 1);
  EXPECT_EQ(bill[1].mass, 4.0);
  EXPECT_EQ(bill[1].price, 120.0);

  const io::LineFile cheapest =
      load_sheet_line(sheet_line(two_types(false), rules + "choose = \"fewest-then-cheapest\"\n", kOneShortSpan));
  const SpanSchedule cheap = schedule_span(cheapest.line, 0, cache);
  EXPECT_EQ(cheap.row.damper_type, "heavy-cheap");
  EXPECT_EQ(cheap.row.per_end, 1);
  EXPECT_EQ(cheap.row.positions, light.row.positions);
  const std::vector<BillLine> priced = bill_of_materials(cheapest.line, {cheap.row});
  EXPECT_EQ(priced[1].damper_type, "heavy-cheap");
  EXPECT_EQ(priced[1].price, 80.0);
  EXPECT_EQ(priced[1].mass, 6.0);
}

// The choice compares every type's price or mass: one missing is refused naming it.
TEST(LineSchedule, ATypeWithoutThePriceOrMassTheChoiceComparesIsRefused) {
  const std::string heavy = "{ name = \"heavy-cheap\", impedance = \"vendor_sheet.csv\", mass = 3.0, price = 40 }";
  const std::string unpriced = "{ name = \"light-dear\", impedance = \"vendor_sheet.csv\", mass = 2.0 }";
  const std::string error = line_error_of(
      sheet_line(heavy + ", " + unpriced, "choose = \"fewest-then-cheapest\"\n", kOneShortSpan));
  EXPECT_NE(error.find("dampers.types[1].price: missing: choose = \"fewest-then-cheapest\" compares every type's price"),
            std::string::npos)
      << error;
  // A sheet's type has no mass of its own: by default it must be given.
  const std::string massless = "{ name = \"light-dear\", impedance = \"vendor_sheet.csv\", price = 60 }";
  EXPECT_NE(line_error_of(sheet_line(heavy + ", " + massless, "", kOneShortSpan))
                .find("dampers.types[1].mass: missing: choose = \"fewest-then-lightest\" compares every type's mass"),
            std::string::npos);
  // One type alone has nothing to compare; a negative price is refused.
  EXPECT_EQ(line_error_of(sheet_line(unpriced, "choose = \"fewest-then-cheapest\"\n", kOneShortSpan)), "(accepted)");
  EXPECT_EQ(line_error_of(sheet_line(two_types(true), "choose = \"fewest-then-cheapest\"\n", kOneShortSpan)), "(accepted)");
  const std::string negative = "{ name = \"x\", impedance = \"vendor_sheet.csv\", mass = 2.0, price = -1 }";
  EXPECT_NE(line_error_of(sheet_line(negative, "", kOneShortSpan)).find("dampers.types[0].price = -1"),
            std::string::npos)
      << line_error_of(sheet_line(negative, "", kOneShortSpan));
}

// A Drake span with the dampers kept within 1.3 to 1.6 m of the clamp: one per end
// leaves it uncertain (its stress within the limit, the sheet's band above); by
// default the schedule goes on to two, which make it safe; accept_uncertain stops at one.
TEST(LineSchedule, AnUncertainArrangementIsSafeOnlyWhereTheRulesAcceptIt) {
  const std::string span = "[[span]]\nid = \"D\"\nlength = 300\ntension_fraction = 0.2\n";
  const std::string rules = "max_per_end = 2\nposition_min = 1.3\nposition_max = 1.6\nspacing_min = 0.05\n";
  const std::string points = "points = 12\nsearch_points = 8\n";
  TableCache cache;
  const SpanSchedule strict =
      schedule_span(load_sheet_line(sheet_line(kVendor, rules, span, "ACSR Drake", points)).line, 0, cache);
  EXPECT_EQ(strict.row.per_end, 2);
  EXPECT_EQ(strict.row.verdict, span::Verdict::safe);
  const SpanSchedule accepting = schedule_span(
      load_sheet_line(sheet_line(kVendor, rules + "accept_uncertain = true\n", span, "ACSR Drake", points)).line, 0, cache);
  EXPECT_EQ(accepting.row.per_end, 1);
  EXPECT_EQ(accepting.row.verdict, span::Verdict::uncertain);
  EXPECT_LT(accepting.row.max_stress, accepting.row.endurance_limit);
  EXPECT_GT(accepting.row.max_stress_high, accepting.row.endurance_limit);
  EXPECT_EQ(schedule_counts({strict.row, accepting.row}).uncertain, 1);
  EXPECT_EQ(schedule_counts({strict.row, accepting.row}).safe, 1);
}

/// A 400 m ASTER570 span at H/w 1300 m with three 12.5 kg warning spheres.
const std::string kSphereSpan =
    "[[span]]\nid = \"S\"\nlength = 400\ncatenary_parameter = 1300\n"
    "[[span.mass]]\nname = \"sphere\"\nmass = 12.5\npositions = [100, 200, 300]\n";

/// The largest stress at the masses' clamps over an analysis's points, Pa.
double largest_sphere_stress(const span::SpanAnalysis& a) {
  double largest = 0.0;
  for (const span::BalancePoint& p : a.balance.points) {
    for (const span::MassAtBalance& m : p.masses) largest = std::max(largest, m.clamp_stress);
  }
  return largest;
}

// By default every arrangement of a span with masses has a damper of its type on
// either side of each mass, at one of the distances tried (1, 2 and 3 m): the row
// counts them, names the governing place, and the bill counts them with the ends';
// sphere_dampers = "none" leaves the masses alone, and their clamps then take more.
TEST(LineSchedule, ASpanWithSpheresGetsADamperOnEitherSideOfEach) {
  const std::string rules = "max_per_end = 1\nposition_max = 4.0\n";
  const std::string points = "points = 12\nsearch_points = 8\n";
  TableCache cache;
  const io::LineFile beside = load_sheet_line(sheet_line(kVendor, rules, kSphereSpan, "AAAC ASTER570", points));
  const SpanSchedule s = schedule_span(beside.line, 0, cache);
  const ScheduleRow& row = s.row;
  ASSERT_GE(row.per_end, 1);
  ASSERT_EQ(row.converged, row.points);
  EXPECT_EQ(row.sphere_dampers, 6);
  const double d = row.sphere_distance;
  EXPECT_TRUE(d == 1.0 || d == 2.0 || d == 3.0) << d;
  const std::vector<span::SpanDamper>& dampers = s.analysis.span.dampers();
  ASSERT_EQ(dampers.size(), static_cast<std::size_t>(row.per_end) + 1);
  EXPECT_EQ(dampers.back().along, (std::vector<double>{100 - d, 100 + d, 200 - d, 200 + d, 300 - d, 300 + d}));
  EXPECT_EQ(dampers.back().name, "vendor");
  EXPECT_FALSE(row.governing_place.empty());
  EXPECT_EQ(row.governing_place, s.analysis.balance.summary.max_judged_stress_place);
  EXPECT_EQ(row.max_stress, s.analysis.balance.summary.max_judged_stress);
  // The row is its arrangement's balance (what --details writes).
  EXPECT_EQ(analyse_arrangement(beside.line, row, cache).balance.summary.max_judged_stress, row.max_stress);
  const std::vector<BillLine> bill = bill_of_materials(beside.line, {row});
  ASSERT_EQ(bill.size(), 1u);
  EXPECT_EQ(bill[0].dampers, 2 * row.per_end + 6);
  EXPECT_NEAR(*bill[0].mass, 2.4 * (2 * row.per_end + 6), 1e-12);

  const io::LineFile none =
      load_sheet_line(sheet_line(kVendor, rules + "sphere_dampers = \"none\"\n", kSphereSpan, "AAAC ASTER570", points));
  const SpanSchedule n = schedule_span(none.line, 0, cache);
  EXPECT_EQ(n.row.sphere_dampers, 0);
  EXPECT_TRUE(std::isnan(n.row.sphere_distance));
  for (const span::SpanDamper& damper : n.analysis.span.dampers()) EXPECT_FALSE(damper.in_span());
  EXPECT_EQ(bill_of_materials(none.line, {n.row})[0].dampers, 2 * n.row.per_end);
  EXPECT_EQ(n.row.undamped_max_stress, row.undamped_max_stress);  // the same span without dampers
  ASSERT_EQ(n.row.converged, n.row.points);
  EXPECT_LT(largest_sphere_stress(s.analysis), largest_sphere_stress(n.analysis));
}

}  // namespace
}  // namespace stockbridge::line
