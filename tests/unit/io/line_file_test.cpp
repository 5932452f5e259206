// A line file's masses along its spans (warning spheres, markers): [[span.mass]]
// tables and the spans CSV's masses column read into each span, a bad cell or value
// named by file, line and column or key; the rules for the dampers beside the masses
// read and checked against each span's masses; a --details span file writes the
// masses and the dampers beside them so that the span file reads them back.

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

const std::string kSauter = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml";

/// A line of ASTER570 with one damper type, the rules `rules` of [dampers], and `spans`.
std::string mass_line(const std::string& rules, const std::string& spans) {
  return "[conductor]\ntype = \"AAAC ASTER570\"\n[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n"
         "[fatigue]\ncycles = 5e8\n[dampers]\ntypes = [ { name = \"sb1\", file = \"" +
         kSauter + "\" } ]\nposition_max = 5.0\n" + rules + spans;
}

std::string mass_line_error(const std::string& text) {
  try {
    load_line_text(text, "line(text=...)");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

/// A folder of the running test's own: ctest runs the tests of this file side by
/// side, and one folder for all of them let one test read another's spans.csv.
std::filesystem::path csv_folder() {
  return std::filesystem::temp_directory_path() /
         (std::string("stockbridge-line-masses-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

/// The line with its spans in `csv` (written as spans.csv beside it).
LineFile csv_line(const std::string& csv, SlipPolicy policy = SlipPolicy::refuse) {
  testing::write_temp_file(csv_folder(), "spans.csv", csv);
  return load_line_text("spans = \"spans.csv\"\n" + mass_line("", ""), "line(text=...)", csv_folder(), policy);
}

std::string csv_line_error(const std::string& csv) {
  try {
    csv_line(csv);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string kSpanWithSpheres = R"([[span]]
id = "A"
length = 400
tension_fraction = 0.15
[[span.mass]]
name = "sphere"
mass = 12.5
positions = [100, 200, 300]
[[span.mass]]
mass = 8
positions = [250]
stress_factor = 1.2
)";

TEST(LineFileMasses, AreReadFromTheSpansMassTables) {
  const LineFile f = load_line_text(mass_line("sphere_dampers = \"none\"\n", kSpanWithSpheres), "line(text=...)");
  const std::vector<span::SpanMass>& m = f.line.spans().at(0).span.masses();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].name, "sphere");
  EXPECT_EQ(m[0].mass, 12.5);
  EXPECT_EQ(m[0].positions, (std::vector<double>{100, 200, 300}));
  EXPECT_EQ(m[0].stress_factor, 1.0);
  EXPECT_EQ(m[1].name, "mass 2");  // a span file's [[mass]] name where none is given
  EXPECT_EQ(m[1].stress_factor, 1.2);
}

TEST(LineFileMasses, AreReadFromTheCsvColumnGroupedByTheirMass) {
  const LineFile f = csv_line("id,length_m,tension_fraction,masses\n"
                              "A,400,0.15,12.5@100;8@200; 12.5 @ 300\n"
                              "B,300,0.15,\n");
  const std::vector<span::SpanMass>& a = f.line.spans().at(0).span.masses();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].name, "mass 1");
  EXPECT_EQ(a[0].mass, 12.5);
  EXPECT_EQ(a[0].positions, (std::vector<double>{100, 300}));
  EXPECT_EQ(a[1].name, "mass 2");
  EXPECT_EQ(a[1].mass, 8.0);
  EXPECT_EQ(a[1].positions, (std::vector<double>{200}));
  EXPECT_TRUE(f.line.spans().at(1).span.masses().empty());  // an empty cell: none
}

TEST(LineFileMasses, ABadCellIsNamedByItsFileLineAndColumn) {
  const std::string file = (csv_folder() / "spans.csv").string();
  const std::string expected = "<kg>@<m from end 1> entries, ';'-separated (e.g. 12.5@30;12.5@90), or an empty cell for none";
  EXPECT_EQ(csv_line_error("id,length_m,tension_fraction,masses\nA,400,0.15,12.5@100;12.5@\n"),
            file + ":2: column 'masses' = '12.5@100;12.5@': '12.5@' is not a mass at a position: expected " + expected);
  EXPECT_EQ(csv_line_error("id,length_m,tension_fraction,masses\nA,400,0.15,12.5 100\n"),
            file + ":2: column 'masses' = '12.5 100': '12.5 100' is not a mass at a position: expected " + expected);
  EXPECT_EQ(csv_line_error("id,length_m,tension_fraction,masses\nA,400,0.15,12.5@100;\n"),
            file + ":2: column 'masses' = '12.5@100;': '' is not a mass at a position: expected " + expected);
  EXPECT_EQ(csv_line_error("id,length_m,tension_fraction,masses\nA,400,0.15,12.5@450\n"),
            file + ":2: span \"A\": column 'masses' = '12.5@450': a position = 450: expected a distance from end 1 > 0 "
                   "and < the span's length, 400 m");
  // A mass in grams is a unit slip: refused, or taken with a warning.
  EXPECT_EQ(csv_line_error("id,length_m,tension_fraction,masses\nA,400,0.15,12500@100\n"),
            file + ":2: span \"A\": masses = 12500: outside the typical 0.5 to 50 kg of the mass along the span (warning "
                   "sphere, marker) (in g? 12500 g = 12.5 kg)");
  const LineFile taken = csv_line("id,length_m,tension_fraction,masses\nA,400,0.15,12500@100\n", SlipPolicy::warn);
  ASSERT_EQ(taken.warnings.size(), 1u);
  EXPECT_NE(taken.warnings[0].find("span \"A\": masses = 12500: outside the typical"), std::string::npos);
}

TEST(LineFileMasses, ABadTableValueIsNamedByItsKey) {
  std::string beyond = kSpanWithSpheres;
  beyond.replace(beyond.find("[100, 200, 300]"), 15, "[100, 200, 420]");
  EXPECT_EQ(mass_line_error(mass_line("sphere_dampers = \"none\"\n", beyond)),
            "line(text=...): span \"A\": mass[0].positions[2] = 420: expected a distance from end 1 > 0 and < the "
            "span's length, 400 m");
  std::string misspelt = kSpanWithSpheres;
  misspelt.replace(misspelt.find("stress_factor"), 13, "stress_facter");
  EXPECT_NE(mass_line_error(mass_line("", misspelt)).find("stress_facter"), std::string::npos);
}

TEST(LineFileMasses, TheRulesForTheDampersBesideThemAreReadAndChecked) {
  const LineFile f = load_line_text(mass_line("", kSpanWithSpheres), "line(text=...)");
  EXPECT_EQ(f.line.rules().sphere_dampers, line::SphereDampers::both_sides);
  EXPECT_EQ(f.line.rules().sphere_distance_min, 1.0);
  EXPECT_EQ(f.line.rules().sphere_distance_max, 3.0);
  EXPECT_EQ(line::parse_sphere_dampers(line::sphere_dampers_name(line::SphereDampers::none)), line::SphereDampers::none);
  EXPECT_NE(mass_line_error(mass_line("sphere_dampers = \"both\"\n", kSpanWithSpheres))
                .find("dampers.sphere_dampers = 'both': expected \"both sides\" (a damper on either side of each mass "
                      "along a span) or \"none\""),
            std::string::npos);
  EXPECT_NE(mass_line_error(mass_line("sphere_distance_min = 0\n", kSpanWithSpheres)).find("dampers.sphere_distance_min = 0"),
            std::string::npos);
  EXPECT_NE(mass_line_error(mass_line("sphere_distance_min = 2\nsphere_distance_max = 1.5\n", kSpanWithSpheres))
                .find("dampers.sphere_distance_max = 1.5: expected a distance >= sphere_distance_min = 2 m"),
            std::string::npos);
  // The masses at 200 and 250 m: dampers 24 m from each would meet; from the mass at
  // 100 m, 92 m would reach into the end dampers' range (up to 5 m, 0.5 m apart).
  EXPECT_EQ(mass_line_error(mass_line("sphere_distance_max = 24.9\n", kSpanWithSpheres)),
            "line(text=...): dampers.sphere_distance_max = 24.9: on span \"A\", the dampers beside the masses at 200 "
            "and 250 m would come within spacing_min of each other (spacing_min = 0.5 m): expected a smaller "
            "sphere_distance_max, or sphere_dampers = \"none\"");
  EXPECT_NE(mass_line_error(mass_line("sphere_distance_min = 20\nsphere_distance_max = 94.6\n",
                                      "[[span]]\nid = \"A\"\nlength = 400\ntension_fraction = 0.15\n"
                                      "[[span.mass]]\nmass = 12.5\npositions = [100]\n"))
                .find("the dampers beside the mass at 100 m would come within spacing_min of the end dampers' range "
                      "(position_max = 5 m)"),
            std::string::npos);
  // No dampers beside the masses: nothing to fit.
  EXPECT_EQ(mass_line_error(mass_line("sphere_dampers = \"none\"\nsphere_distance_max = 24.9\n", kSpanWithSpheres)),
            "(accepted)");
}

TEST(LineFileMasses, ADetailsSpanFileWritesTheMassesAndTheDampersBesideThem) {
  const LineFile f = load_line_text(mass_line("", kSpanWithSpheres), "line(text=...)");
  line::ScheduleRow row;
  row.index = 0;
  row.damper_type = "sb1";
  row.per_end = 1;
  row.positions = {1.23};
  row.sphere_dampers = 8;
  row.sphere_distance = 1.5;
  const SpanFile again = load_span_text(span_file_text(f, row), "details");
  const span::Span& s = again.span;
  ASSERT_EQ(s.masses().size(), 2u);
  EXPECT_EQ(s.masses()[0].positions, (std::vector<double>{100, 200, 300}));
  EXPECT_EQ(s.masses()[1].mass, 8.0);
  EXPECT_EQ(s.masses()[1].stress_factor, 1.2);
  EXPECT_EQ(s.masses()[1].name, "mass 2");
  ASSERT_EQ(s.dampers().size(), 2u);
  EXPECT_EQ(s.dampers()[0].position, 1.23);
  EXPECT_TRUE(s.dampers()[0].both_ends);
  EXPECT_EQ(s.dampers()[1].along, (std::vector<double>{98.5, 101.5, 198.5, 201.5, 248.5, 251.5, 298.5, 301.5}));
  EXPECT_EQ(s.dampers()[1].along, line::sphere_damper_positions(f.line.spans()[0].span, 1.5));
}

}  // namespace
}  // namespace stockbridge::io
