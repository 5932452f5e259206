// `stockbridge strand` from the command line: the bounds of the shipped example,
// and one line naming file, line, key and value for every bad strand file.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <ostream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"

namespace stockbridge::testing {
namespace {

const std::string kStrandExample = std::string("'") + STOCKBRIDGE_SOURCE_DIR + "/examples/strand_19wire.toml'";

// The example's bounds from MODEL.md section 7, with its numbers (E = 210 GPa, every
// wire of radius r = 1 mm; 6 wires on R = 2 mm, lay 60 mm; 12 on R = 4 mm, lay 100 mm):
// EI_min = E 19 pi r^4 / 4 (3.134 N m^2);
// EI_max = E (pi r^4/4 + sum_j N_j/2 pi r^2 (r^2/2 + R_j^2) cos^3 alpha_j), with
// cos alpha = 1 / sqrt(1 + tan^2 alpha), tan alpha = 2 pi R / lambda (68.10 N m^2).
constexpr double kYoung = 210e9;
constexpr double kWire = 0.001;
const double kEiMin = kYoung * 19.0 * std::numbers::pi * std::pow(kWire, 4) / 4.0;

double helical_layer(int count, double pitch_radius, double lay_length) {
  const double tan_alpha = 2.0 * std::numbers::pi * pitch_radius / lay_length;
  return kYoung * count / 2.0 * std::numbers::pi * kWire * kWire *
         (kWire * kWire / 2.0 + pitch_radius * pitch_radius) * std::pow(1.0 + tan_alpha * tan_alpha, -1.5);
}

const double kEiMax = kYoung * std::numbers::pi * std::pow(kWire, 4) / 4.0 + helical_layer(6, 0.002, 0.060) +
                      helical_layer(12, 0.004, 0.100);

/// The number after `prefix` (a regular expression) in `text`.
double number_after(const std::string& text, const std::string& prefix) {
  const std::regex pattern(prefix + "([-+0-9.eE]+)");
  std::smatch match;
  if (!std::regex_search(text, match, pattern)) {
    ADD_FAILURE() << "no number after " << prefix << " in " << text;
    return std::nan("");
  }
  return std::strtod(match[1].str().c_str(), nullptr);
}

TEST(StrandCli, PrintsTheBoundsOfTheExampleAsJson) {
  const auto dir = scratch_directory("strand-json");
  const CliResult r = run_cli("strand " + kStrandExample + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(std::regex_match(r.out, std::regex(R"(\{"ei_min_n_m2": [-+0-9.eE]+, "ei_max_n_m2": [-+0-9.eE]+\}\n)")))
      << r.out;
  EXPECT_NEAR(json_number(r.out, "ei_min_n_m2"), kEiMin, 1e-9 * kEiMin);
  EXPECT_NEAR(json_number(r.out, "ei_max_n_m2"), kEiMax, 1e-9 * kEiMax);
}

TEST(StrandCli, PrintsTheBoundsOfTheExampleAsText) {
  const auto dir = scratch_directory("strand-text");
  const CliResult r = run_cli("strand " + kStrandExample, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("19 wires (core + 2 layers)"), std::string::npos) << r.out;
  EXPECT_NEAR(number_after(r.out, "ei_min = "), kEiMin, 1e-9 * kEiMin);
  EXPECT_NEAR(number_after(r.out, "ei_max = "), kEiMax, 1e-9 * kEiMax);
}

TEST(StrandCli, YoungsModulusIsOptional) {
  const auto dir = scratch_directory("strand-default-e");
  std::ofstream(dir / "wire.toml") << "[strand]\ncore_radius = 0.001\n";
  const CliResult r = run_cli("strand wire.toml --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // One steel wire: E pi r^4 / 4 = 0.16493 N m^2 for both bounds.
  EXPECT_NEAR(json_number(r.out, "ei_min_n_m2"), kEiMin / 19.0, 1e-12);
  EXPECT_NEAR(json_number(r.out, "ei_max_n_m2"), kEiMin / 19.0, 1e-12);
}

constexpr const char* kGood =
    "[strand]\n"                  // 1
    "youngs_modulus = 210e9\n"    // 2
    "core_radius = 0.001\n"       // 3
    "\n"                          // 4
    "[[strand.layer]]\n"          // 5
    "count = 6\n"                 // 6
    "wire_radius = 0.001\n"       // 7
    "pitch_radius = 0.002\n"      // 8
    "lay_length = 0.06\n";        // 9

struct BadFile {
  const char* name;
  const char* contents;     // nullptr: no file at all
  const char* stderr_line;  // the whole line after "stockbridge: "; "..." at the end: a prefix
};

void PrintTo(const BadFile& bad, std::ostream* os) { *os << bad.name; }

class StrandCliRejects : public ::testing::TestWithParam<BadFile> {};

TEST_P(StrandCliRejects, WithOneLineNamingFileAndKeyAndExitTwo) {
  const auto dir = scratch_directory(std::string("strand-bad-") + GetParam().name);
  if (GetParam().contents) std::ofstream(dir / "bad.toml") << GetParam().contents;
  const CliResult r = run_cli("strand bad.toml --json", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  std::string expected = std::string("stockbridge: ") + GetParam().stderr_line + "\n";
  if (expected.ends_with("...\n")) {
    expected.resize(expected.size() - 4);  // toml++ words its syntax errors itself
    EXPECT_EQ(r.err.substr(0, expected.size()), expected);
  } else {
    EXPECT_EQ(r.err, expected);
  }
  EXPECT_EQ(r.out, "");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) std::abort();
  return text.replace(at, from.size(), to);
}

// The contents must outlive the test run: keep them in static strings.
const std::string kMissingCore = replaced(kGood, "core_radius = 0.001\n", "");
const std::string kMissingLay = replaced(kGood, "lay_length = 0.06\n", "");
const std::string kUnknownKey = replaced(kGood, "core_radius", "core_radus");
const std::string kUnknownLayerKey = std::string(kGood) + "lay_direction = \"left\"\n";
const std::string kUnknownTable = std::string(kGood) + "[cable]\nlength = 0.1\n";
const std::string kNegativeRadius = replaced(kGood, "wire_radius = 0.001", "wire_radius = -0.001");
const std::string kZeroLay = replaced(kGood, "lay_length = 0.06", "lay_length = 0");
const std::string kBadModulus = replaced(kGood, "youngs_modulus = 210e9", "youngs_modulus = -210e9");
const std::string kStringRadius = replaced(kGood, "core_radius = 0.001", "core_radius = \"1 mm\"");
const std::string kFractionalCount = replaced(kGood, "count = 6", "count = 6.5");
const std::string kZeroCount = replaced(kGood, "count = 6", "count = 0");
const std::string kLayerNotArray = replaced(kGood, "[[strand.layer]]", "[strand.layer]");
const std::string kSyntax = replaced(kGood, "core_radius = 0.001", "core_radius = ");

INSTANTIATE_TEST_SUITE_P(
    BadFiles, StrandCliRejects,
    ::testing::Values(
        BadFile{"missing-file", nullptr, "bad.toml: no such file"},
        BadFile{"misspelt-strand", "[strnd]\ncore_radius = 0.001\n",
                "bad.toml:1: unknown key 'strnd': expected one of strand"},
        BadFile{"empty", "# nothing\n", "bad.toml:1: missing key 'strand' in the top level: expected a table"},
        BadFile{"missing-core", kMissingCore.c_str(),
                "bad.toml:1: missing key 'core_radius' in [strand]: expected a number"},
        BadFile{"missing-lay", kMissingLay.c_str(),
                "bad.toml:5: missing key 'lay_length' in [strand.layer[0]]: expected a number"},
        BadFile{"unknown-key", kUnknownKey.c_str(),
                "bad.toml:3: unknown key 'strand.core_radus': expected one of core_radius, core_youngs_modulus, layer, "
                "youngs_modulus"},
        BadFile{"unknown-layer-key", kUnknownLayerKey.c_str(),
                "bad.toml:10: unknown key 'strand.layer[0].lay_direction': expected one of count, lay_length, "
                "pitch_radius, wire_radius, youngs_modulus"},
        BadFile{"unknown-table", kUnknownTable.c_str(), "bad.toml:10: unknown key 'cable': expected one of strand"},
        BadFile{"negative-radius", kNegativeRadius.c_str(),
                "bad.toml:7: strand.layer[0].wire_radius = -0.001: expected a finite value > 0 (m)"},
        BadFile{"zero-lay", kZeroLay.c_str(),
                "bad.toml:9: strand.layer[0].lay_length = 0: expected a finite value > 0 (m)"},
        BadFile{"bad-modulus", kBadModulus.c_str(),
                "bad.toml:2: strand.youngs_modulus = -210000000000: expected a finite value > 0 (Pa)"},
        BadFile{"string-radius", kStringRadius.c_str(),
                "bad.toml:3: strand.core_radius: the string \"1 mm\": expected a number"},
        BadFile{"fractional-count", kFractionalCount.c_str(),
                "bad.toml:6: strand.layer[0].count: the number 6.5: expected an integer from 1 to 1000"},
        BadFile{"zero-count", kZeroCount.c_str(),
                "bad.toml:6: strand.layer[0].count: 0: expected an integer from 1 to 1000"},
        BadFile{"layer-not-array", kLayerNotArray.c_str(),
                "bad.toml:5: strand.layer: a table: expected an array of tables"},
        BadFile{"syntax", kSyntax.c_str(), "bad.toml:3:15: TOML syntax error: ..."}),
    [](const ::testing::TestParamInfo<BadFile>& info) {
      std::string name = info.param.name;
      for (char& ch : name) {
        if (ch == '-') ch = '_';
      }
      return name;
    });

}  // namespace
}  // namespace stockbridge::testing
