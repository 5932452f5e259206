// The typical ranges behind the unit-mistake warnings: the code's table is the one
// docs/file-formats.md shows, and a value warns exactly when it lies outside.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/damper/damper.hpp"

namespace stockbridge {
namespace {

std::vector<std::string> cells(std::string row) {
  std::string unescaped;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      unescaped += '\x01';  // an escaped pipe inside a cell
      ++i;
    } else {
      unescaped += row[i];
    }
  }
  std::vector<std::string> out;
  std::stringstream in(unescaped);
  for (std::string cell; std::getline(in, cell, '|');) {
    const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
    cell = first == std::string::npos ? "" : cell.substr(first, last - first + 1);
    for (char& ch : cell) ch = ch == '\x01' ? '|' : ch;
    out.push_back(cell);
  }
  return out;
}

TEST(TypicalRanges, TheDocsTableIsTheCodes) {
  std::ifstream docs(std::string(STOCKBRIDGE_SOURCE_DIR) + "/docs/file-formats.md");
  std::vector<std::vector<std::string>> rows;
  bool in_table = false;
  for (std::string line; std::getline(docs, line);) {
    if (line.rfind("| quantity | typical | unit |", 0) == 0) {
      in_table = true;
    } else if (in_table && line.rfind("|", 0) == 0) {
      if (line.rfind("|---", 0) != 0) rows.push_back(cells(line));
    } else {
      in_table = false;
    }
  }
  const std::vector<TypicalRange>& ranges = typical::all();
  ASSERT_EQ(rows.size(), ranges.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    SCOPED_TRACE(ranges[i].quantity);
    ASSERT_GE(rows[i].size(), 6u);
    EXPECT_EQ(rows[i][1], ranges[i].quantity);
    EXPECT_EQ(rows[i][5], ranges[i].slip.unit);
    EXPECT_EQ(rows[i][2], fmt::format("{:.6g} to {:.6g}", ranges[i].min, ranges[i].max));
    EXPECT_EQ(rows[i][3], ranges[i].unit);
    EXPECT_LT(ranges[i].min, ranges[i].max);
  }
}

TEST(TypicalRanges, AValueWarnsExactlyOutsideItsRange) {
  EXPECT_FALSE(unusual("m", 0.05, typical::arm_mass));
  EXPECT_FALSE(unusual("m", 20.0, typical::arm_mass));
  EXPECT_TRUE(unusual("m", 0.0499, typical::arm_mass));
  EXPECT_TRUE(unusual("m", 20.01, typical::arm_mass));
  EXPECT_EQ(unusual("arm[0].mass", 863, typical::arm_mass)->message(),
            "arm[0].mass = 863: outside the typical 0.05 to 20 kg of the arm mass (in g? 863 g = 0.863 kg)");
  EXPECT_EQ(unusual("arm[0].mass", 86300, typical::arm_mass)->message(),
            "arm[0].mass = 86300: outside the typical 0.05 to 20 kg of the arm mass (a unit mistake?)");
}

// A reader refuses a value its range's slip explains (SlipPolicy::refuse, the
// default), and warns of it where the study goes there on purpose; a value no slip
// explains is a warning either way.
TEST(TypicalRanges, AReaderRefusesASlipAndWarnsOfTheRest) {
  const UnusualValue kn = *unusual("span.tension", 30.3, typical::span_tension);
  const UnusualValue huge = *unusual("span.tension", 5e7, typical::span_tension);
  EXPECT_TRUE(kn.slip_explained());
  EXPECT_FALSE(huge.slip_explained());
  std::vector<std::string> warnings;
  try {
    judge_unusual(kn, "s.toml:16: ", SlipPolicy::refuse, warnings);
    ADD_FAILURE() << "a slip accepted";
  } catch (const UnusualValueError& e) {
    EXPECT_EQ(std::string(e.what()), "s.toml:16: span.tension = 30.3: outside the typical 1000 to 500000 N of the "
                                     "conductor tension (in kN? 30.3 kN = 30300 N)");
  }
  EXPECT_TRUE(warnings.empty());
  judge_unusual(huge, "s.toml:16: ", SlipPolicy::refuse, warnings);
  judge_unusual(kn, "s.toml:16: ", SlipPolicy::warn, warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[1], "s.toml:16: " + kn.message());
  EXPECT_THROW(judge_implausible("x", SlipPolicy::refuse, warnings), UnusualValueError);
  judge_implausible("x", SlipPolicy::warn, warnings);
  EXPECT_EQ(warnings.back(), "x");
}

TEST(TypicalRanges, AUsualSlipOfUnitsIsNamedWhereItExplainsTheValue) {
  EXPECT_EQ(unusual("conductor.diameter", 28.14, typical::conductor_diameter)->message(),
            "conductor.diameter = 28.14: outside the typical 0.004 to 0.08 m of the conductor diameter (in mm? "
            "28.14 mm = 0.02814 m)");
  EXPECT_EQ(unusual("span.tension_fraction", 0.9, typical::tension_fraction)->message(),
            "span.tension_fraction = 0.9: outside the typical 0.03 to 0.4 of the tension as a fraction of the rated "
            "tensile strength (a unit mistake?)");
  EXPECT_EQ(unusual("fatigue.aeolian_fraction", 30, typical::aeolian_fraction)->message(),
            "fatigue.aeolian_fraction = 30: outside the typical 0.01 to 1 of the share of the year with aeolian "
            "vibration (a percentage? 30 % = 0.3)");
  // A value the slip does not bring into the range is not blamed on it.
  EXPECT_EQ(unusual("span.tension", 5e7, typical::span_tension)->message(),
            "span.tension = 50000000: outside the typical 1000 to 500000 N of the conductor tension (a unit mistake?)");
  EXPECT_EQ(*typical::outer_wire_modulus.slipped(68.9), 68.9e9);
  EXPECT_FALSE(typical::outer_wire_modulus.slipped(68.9e9));
}

TEST(TypicalRanges, TheDissertationsDamperIsTypicalAndEachUnitMistakeIsNamed) {
  damper::ArmDescription arm;
  arm.mass = 0.856;
  arm.inertia = 0.001814;
  arm.offset = 0.0325;
  arm.cable = cable::CableDescription::uniform(0.1875, 40, 2.8, {{20.0, 0.7}});
  damper::DamperDescription d{0.7, {arm, arm}};
  EXPECT_TRUE(d.unusual_values().empty());
  d.arms[1].offset = -32.5;      // mm
  d.arms[1].cable.length = 187.5;  // mm
  d.arms[1].cable.jenkin[0].h = cable::Profile::constant(700);  // N mm
  const std::vector<UnusualValue> found = d.unusual_values();
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].field, "arm[1].offset");
  EXPECT_EQ(found[0].value, -32.5);
  EXPECT_EQ(found[1].field, "arm[1].cable.length");
  EXPECT_EQ(found[2].field, "arm[1].cable.jenkin[0].h");
}

}  // namespace
}  // namespace stockbridge
