// A line's pieces: schedule records give their rows back bit for bit (what ranks send
// and --resume reads) and refuse a record cut short; the rules and the line file are
// checked where the user wrote them.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/requests/line_request.hpp"

namespace stockbridge::line {
namespace {

ScheduleRow a_row() {
  ScheduleRow r;
  r.index = 17;
  r.id = "T12\tT13 \\ river";
  r.conductor = "ACSR Drake";
  r.length = 420.0;
  r.tension = 27795.000000000004;
  r.tension_fraction = 0.15000000000000002;
  r.catenary_parameter = 1804.1382647817643;
  r.span_parameter = 7.905792488860598;
  r.terrain = 2;
  r.terrain_within = 0;
  r.endurance_limit = 8.73234423885417e6;
  r.undamped_max_stress = 4.959895173457283e7;
  r.undamped_life_years = 0.001538996328427709;
  r.undamped_verdict = span::Verdict::unsafe;
  r.damper_type = "sb1";
  r.per_end = 2;
  r.positions = {1.33, 4.1};
  r.sphere_dampers = 6;
  r.sphere_distance = 1.25;
  r.governing_place = "sphere\tat 150 m";
  r.max_stress = 7.130785512570936e6;
  r.max_stress_frequency = 6.076401576332188;
  r.life_years = std::numeric_limits<double>::infinity();
  r.verdict = span::Verdict::safe;
  r.converged = 99;
  r.points = 100;
  r.balances = 125;
  r.warnings = {"first\nsecond line", "", "a | b"};
  return r;
}

TEST(ScheduleRecord, GivesItsRowBackBitForBit) {
  const ScheduleRow r = a_row();
  const std::string record = requests::schedule_record(r);
  EXPECT_EQ(record.find('\n'), std::string::npos);
  const ScheduleRow back = requests::parse_schedule_record(record);
  EXPECT_EQ(requests::schedule_record(back), record);
  EXPECT_EQ(back.id, r.id);
  EXPECT_EQ(back.warnings, r.warnings);
  EXPECT_EQ(back.positions, r.positions);
  EXPECT_EQ(back.tension, r.tension);
  EXPECT_EQ(back.catenary_parameter, r.catenary_parameter);
  EXPECT_TRUE(std::isinf(back.life_years));
  EXPECT_EQ(back.verdict, span::Verdict::safe);
  EXPECT_EQ(back.sphere_dampers, 6);
  EXPECT_EQ(back.sphere_distance, 1.25);
  EXPECT_EQ(back.governing_place, r.governing_place);
  // The CSV row of the record's row is the row's.
  EXPECT_EQ(requests::schedule_table().values(back).csv(), requests::schedule_table().values(r).csv());
  ScheduleRow missing = r;
  missing.max_stress = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(requests::parse_schedule_record(requests::schedule_record(missing)).max_stress));
  ScheduleRow no_spheres = r;
  no_spheres.sphere_dampers = 0;
  no_spheres.sphere_distance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(requests::parse_schedule_record(requests::schedule_record(no_spheres)).sphere_distance));
}

// A record of the program before the dampers beside the masses (span-v2) is not a
// schedule record: --resume computes its span again rather than write a row without
// its governing place.
TEST(ScheduleRecord, ARecordOfTheEarlierFormIsRefused) {
  std::string record = requests::schedule_record(a_row());
  record.replace(0, 7, "span-v2");
  EXPECT_THROW(requests::parse_schedule_record(record), InvalidParameter);
}

TEST(ScheduleRecord, ARecordCutShortIsRefused) {
  const std::string record = requests::schedule_record(a_row());
  for (const std::size_t keep : {std::size_t{0}, std::size_t{10}, record.size() / 2, record.size() - 4}) {
    EXPECT_THROW(requests::parse_schedule_record(record.substr(0, keep)), InvalidParameter) << keep;
  }
}

TEST(ScheduleCsv, StressesOfABalanceNotConvergedThroughoutAreLeftEmpty) {
  ScheduleRow r = a_row();
  const std::string csv = requests::schedule_table().values(r).csv();
  // converged 99 of 100: max_stress_mpa, life and the ratio empty; the undamped figures kept
  EXPECT_NE(csv.find(",49.59895173457283,0.001538996328427709,2,6,1.25,,,,,,,0,99,100,125"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("sphere\tat"), std::string::npos) << "the governing place of a balance not converged throughout";
  r.converged = 100;
  const std::string converged = requests::schedule_table().values(r).csv();
  EXPECT_NE(converged.find(",2,6,1.25,7.130785512570936,"), std::string::npos) << converged;
  EXPECT_NE(converged.find("a | b\",sphere\tat 150 m,420,"), std::string::npos) << converged;
}

TEST(ScheduleRules, AreCheckedAsTheLineFileSpellsThem) {
  const auto field_of = [](ScheduleRules r) {
    try {
      r.validate();
    } catch (const InvalidParameter& e) {
      return e.field();
    }
    return std::string("(accepted)");
  };
  ScheduleRules r;
  EXPECT_EQ(field_of(r), "(accepted)");
  r.max_per_end = 0;
  EXPECT_EQ(field_of(r), "dampers.max_per_end");
  r = ScheduleRules{};
  r.min_per_end = 3, r.max_per_end = 2;
  EXPECT_EQ(field_of(r), "dampers.max_per_end");
  r = ScheduleRules{};
  r.positions.position_max = 0.2;
  EXPECT_EQ(field_of(r), "dampers.position_max");
  r = ScheduleRules{};
  r.positions.spacing_min = 4.0;  // three dampers 4 m apart do not fit in 0.5 .. 8 m
  EXPECT_EQ(field_of(r), "dampers.spacing_min");
  r = ScheduleRules{};
  r.position_step = 0.0;
  EXPECT_EQ(field_of(r), "dampers.position_step");
  r = ScheduleRules{};
  r.life_target = -1.0;
  EXPECT_EQ(field_of(r), "dampers.life_target");
  r = ScheduleRules{};
  r.sphere_distance_min = 0.0;
  EXPECT_EQ(field_of(r), "dampers.sphere_distance_min");
  r = ScheduleRules{};
  r.sphere_distance_max = 0.9;  // below the default minimum of 1 m
  EXPECT_EQ(field_of(r), "dampers.sphere_distance_max");
  r.sphere_distance_min = r.sphere_distance_max;  // one distance
  EXPECT_EQ(field_of(r), "(accepted)");
}

std::string line_text(const std::string& extra_dampers, const std::string& spans) {
  return std::string(R"([conductor]
type = "AAAC ASTER570"
[wind]
law = "cigre"
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 5e8
[dampers]
types = [ { name = "sb1", file = ")") + STOCKBRIDGE_SOURCE_DIR + "/examples/sauter2003.toml\" } ]\n" + extra_dampers +
         spans;
}

std::string error_of(const std::string& text) {
  try {
    io::load_line_text(text, "line(text=...)");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(LineFile, SpansAreReadWithTheirTensionInAnyForm) {
  const io::LineFile f = io::load_line_text(
      line_text("", "[[span]]\nid = \"A\"\nlength = 300\ntension_fraction = 0.15\n"
                    "[[span]]\nid = \"B\"\nlength = 400\ncatenary_parameter = 1500\nconductor = \"ACSR Drake\"\n"
                    "wind = { speed_max = 6 }\n"
                    "[[span]]\nid = \"C\"\nlength = 200\ntension = 30000\nterrain = 3\n"),
      "line(text=...)");
  ASSERT_EQ(f.line.spans().size(), 3u);
  const auto& a = f.line.spans()[0].span;
  EXPECT_DOUBLE_EQ(a.tension(), 0.15 * a.conductor().rated_tensile_strength);
  const auto& b = f.line.spans()[1].span;
  EXPECT_EQ(b.conductor().name, "ACSR Drake");
  EXPECT_NEAR(b.tension(), 1500.0 * b.conductor().mass_per_length * 9.80665, 1e-9 * b.tension());
  EXPECT_EQ(b.wind().speed_max, 6.0);
  EXPECT_EQ(f.line.spans()[2].span.terrain(), 3);
  EXPECT_EQ(f.line.spans()[2].tension_form, "tension");
  ASSERT_EQ(f.line.types().size(), 1u);
  EXPECT_NEAR(*f.line.types()[0].mass, 2.412, 1e-9);  // its clamp (0.7 kg) and two masses of 0.856 kg
}

TEST(LineFile, MistakesAreNamedWhereTheyAre) {
  EXPECT_NE(error_of(line_text("", "[[span]]\nid = \"A\"\nlength = 300\n")).find("missing key 'tension' in [span[0]]"),
            std::string::npos);
  EXPECT_NE(error_of(line_text("", "[[span]]\nid = \"A\"\nlength = 300\ntension = 1\ntension_fraction = 0.1\n"))
                .find("span[0].tension_fraction: given beside tension"),
            std::string::npos);
  EXPECT_NE(error_of(line_text("objective = \"lifetime\"\n", "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e4\n"))
                .find("dampers.objective = \"lifetime\""),
            std::string::npos);
  EXPECT_NE(error_of(line_text("objective = \"life\"\n", "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e4\n"))
                .find("the line gives no climate"),
            std::string::npos);
  EXPECT_NE(error_of(line_text("", "")).find("the line has no span"), std::string::npos);
  EXPECT_NE(error_of(line_text("", "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e5\n")).find("span \"A\": tension"),
            std::string::npos);
  EXPECT_NE(error_of(line_text("max_per_end = 0\n", "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e4\n"))
                .find("max_per_end"),
            std::string::npos);
}

/// A row of span `id` with `warnings`.
ScheduleRow row_warning(const std::string& id, std::vector<std::string> warnings) {
  ScheduleRow r;
  r.id = id;
  r.warnings = std::move(warnings);
  return r;
}

// Warnings that differ only in their numbers are one line: the first span's text,
// how many spans and which; the others each on their own line, led by their span.
TEST(GroupedWarnings, WarningsDifferingOnlyInTheirNumbersAreOneLineWithTheirSpans) {
  const std::string raise = "the dampers raise the largest stress above the undamped span's ";
  const std::string below = "at 3 of the frequencies a measured damper's clamp velocity lay below its sheet's lowest curve";
  const std::vector<ScheduleRow> rows{
      row_warning("T01", {raise + "(9.12 MPa against 8.2 MPa)", below}),
      row_warning("T02", {raise + "(12.5 MPa against 10 MPa)"}),
      row_warning("T03", {"a warning of its own"}),
      row_warning("T04", {}),
      row_warning("T05", {raise + "(7 MPa against 6.55 MPa)"}),
  };
  EXPECT_EQ(grouped_warnings(rows),
            (std::vector<std::string>{
                raise + "(9.12 MPa against 8.2 MPa) (3 spans: T01, T02, T05; the figures are T01's, each span's are in "
                        "its row)",
                "T01: " + below,
                "T03: a warning of its own",
            }));
  EXPECT_TRUE(grouped_warnings({row_warning("T01", {}), row_warning("T02", {})}).empty());
}

// Other words are another kind, however alike: kept apart.
TEST(GroupedWarnings, WarningsOfOtherWordsAreKeptApart) {
  const std::vector<ScheduleRow> rows{
      row_warning("A", {"the measured sheet of vendor is too coarse for this span: 12 %"}),
      row_warning("B", {"the measured sheet of other is too coarse for this span: 12 %"}),
      row_warning("C", {"the measured sheet of vendor is too coarse for this span: 15 %"}),
  };
  EXPECT_EQ(grouped_warnings(rows),
            (std::vector<std::string>{
                "the measured sheet of vendor is too coarse for this span: 12 % (2 spans: A, C; the figures are A's, "
                "each span's are in its row)",
                "B: the measured sheet of other is too coarse for this span: 12 %",
            }));
}

// A number is a number however it is written: with a decimal point, a sign, or an
// exponent as fmt writes it (1.23e+03, 4.5e-05).
TEST(GroupedWarnings, NumbersInExponentFormAreNumbersToo) {
  const std::vector<ScheduleRow> rows{
      row_warning("A", {"life 1.23e+03 years at 8 Hz"}),
      row_warning("B", {"life 950 years at 8 Hz"}),
      row_warning("C", {"life 4.5e-05 years at 12.5 Hz"}),
  };
  EXPECT_EQ(grouped_warnings(rows),
            (std::vector<std::string>{
                "life 1.23e+03 years at 8 Hz (3 spans: A, B, C; the figures are A's, each span's are in its row)"}));
}

TEST(GroupedWarnings, AGroupOfManySpansListsTwelveAndCountsTheRest) {
  std::vector<ScheduleRow> rows;
  for (int i = 1; i <= 15; ++i) {
    std::string id = "S", warning = "stress ";
    id += std::to_string(i);
    warning += std::to_string(i);
    warning += " MPa";
    rows.push_back(row_warning(id, {warning}));
  }
  EXPECT_EQ(grouped_warnings(rows),
            (std::vector<std::string>{"stress 1 MPa (15 spans: S1, S2, S3, S4, S5, S6, S7, S8, S9, S10, S11, S12 and 3 "
                                      "more; the figures are S1's, each span's are in its row)"}));
}

TEST(ScheduleRules, TheTypeChoiceAndTheUndampedRuleAreNamed) {
  for (const TypeChoice c : {TypeChoice::fewest_then_lightest, TypeChoice::fewest_then_cheapest, TypeChoice::lowest_stress}) {
    EXPECT_EQ(parse_type_choice(type_choice_name(c)), c);
  }
  EXPECT_EQ(type_choice_name(TypeChoice::fewest_then_cheapest), "fewest-then-cheapest");
  EXPECT_EQ(parse_undamped_rule("tb273"), UndampedRule::tb273);
  EXPECT_EQ(parse_undamped_rule("balance"), UndampedRule::balance);
  EXPECT_EQ(undamped_rule_name(UndampedRule::tb273), "tb273");
  EXPECT_EQ(ScheduleRules{}.choose, TypeChoice::fewest_then_lightest);
  EXPECT_EQ(ScheduleRules{}.undamped_rule, UndampedRule::balance);
  EXPECT_FALSE(ScheduleRules{}.accept_uncertain);
  EXPECT_NE(error_of(line_text("choose = \"cheapest\"\n", "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e4\n"))
                .find("dampers.choose = 'cheapest': expected fewest-then-lightest, fewest-then-cheapest or lowest-stress"),
            std::string::npos);
  EXPECT_NE(error_of(line_text("undamped_rule = \"tb-273\"\n", "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e4\n"))
                .find("dampers.undamped_rule = 'tb-273': expected balance or tb273"),
            std::string::npos);
  const io::LineFile f = io::load_line_text(
      line_text("choose = \"lowest-stress\"\naccept_uncertain = true\nundamped_rule = \"tb273\"\n",
                "[[span]]\nid = \"A\"\nlength = 300\ntension = 3e4\n"),
      "line(text=...)");
  EXPECT_EQ(f.line.rules().choose, TypeChoice::lowest_stress);
  EXPECT_TRUE(f.line.rules().accept_uncertain);
  EXPECT_EQ(f.line.rules().undamped_rule, UndampedRule::tb273);
}

}  // namespace
}  // namespace stockbridge::line
