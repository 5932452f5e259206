// `stockbridge modes` as users run it: the example's frequencies as JSON, the CSV's
// header and rows, the table, and bad input (exit 2, one line, no file written).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

/// The numbers of the JSON array after "key": in `text` from position `from`.
std::vector<double> json_array(const std::string& text, const std::string& key, std::size_t from = 0) {
  const std::size_t at = text.find("\"" + key + "\": [", from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no array " << key << " in " << text;
    return {};
  }
  const std::size_t open = text.find('[', at), close = text.find(']', open);
  std::vector<double> values;
  std::istringstream in(text.substr(open + 1, close - open - 1));
  for (std::string cell; std::getline(in, cell, ',');) values.push_back(std::strtod(cell.c_str(), nullptr));
  return values;
}

// MODEL.md section 4: each arm of the example 21.2 / 68.2 Hz sticking, 7.4 / 23.9 Hz
// slipping. The two arms are identical, so the clamp-free damper has these too
// (antisymmetric modes, clamp still) and two symmetric modes between and above.
TEST(ModesCli, PrintsTheExamplesFrequenciesAsJson) {
  const auto dir = scratch_directory("modes-json");
  const CliResult r = run_cli("modes '" + kDamperExample + "' --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out.rfind("{\"arms\": [{\"name\": \"left\", \"stick_hz\": [", 0), 0u) << r.out;
  const std::size_t right = r.out.find("\"name\": \"right\"");
  ASSERT_NE(right, std::string::npos) << r.out;
  for (const std::size_t from : {std::size_t{0}, right}) {
    const std::vector<double> stick = json_array(r.out, "stick_hz", from), slip = json_array(r.out, "slip_hz", from);
    ASSERT_EQ(stick.size(), 2u);
    ASSERT_EQ(slip.size(), 2u);
    EXPECT_NEAR(stick[0], 21.2, 0.05);
    EXPECT_NEAR(stick[1], 68.2, 0.05);
    EXPECT_NEAR(slip[0], 7.4, 0.05);
    EXPECT_NEAR(slip[1], 23.9, 0.05);
  }
  const std::size_t whole = r.out.find("\"damper\": {\"clamp_mass_kg\": 0.7, ");
  ASSERT_NE(whole, std::string::npos) << r.out;
  const std::vector<double> stick = json_array(r.out, "stick_hz", whole), slip = json_array(r.out, "slip_hz", whole);
  ASSERT_EQ(stick.size(), 4u);  // 2 arms x 2; the rigid-body mode is not listed
  ASSERT_EQ(slip.size(), 4u);
  // Interlacing with the held 21.2, 21.2, 68.2, 68.2: the antisymmetric modes come first
  // and third, the symmetric ones (31.8, 84.2 Hz) second and fourth.
  EXPECT_NEAR(stick[0], 21.2, 0.05);
  EXPECT_NEAR(stick[1], 31.8, 0.05);
  EXPECT_NEAR(stick[2], 68.2, 0.05);
  EXPECT_NEAR(stick[3], 84.2, 0.05);
  EXPECT_NEAR(slip[0], 7.4, 0.05);
  EXPECT_NEAR(slip[1], 11.2, 0.05);
  EXPECT_NEAR(slip[2], 23.9, 0.05);
  EXPECT_NEAR(slip[3], 29.5, 0.05);
  EXPECT_NE(r.out.find("\"stick_modes\": [{\"frequency_hz\": "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"dominant_arm\": \"left\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"energy_share\": "), std::string::npos) << r.out;
}

TEST(ModesCli, WritesTheCsvAndPrintsATable) {
  const auto dir = scratch_directory("modes-csv");
  const CliResult r = run_cli("modes '" + kDamperExample + "' -o modes.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto lines = lines_of(read_text(dir / "modes.csv"));
  ASSERT_EQ(lines.size(), 1u + 8u + 8u);  // 2 arms x 2 states x 2 modes; the damper 2 states x 4 modes
  EXPECT_EQ(lines[0], "arm,state,mode,frequency_hz");
  EXPECT_TRUE(std::regex_match(lines[1], std::regex(R"(left,stick,1,21\.1[0-9]*)"))) << lines[1];
  EXPECT_TRUE(std::regex_match(lines[2], std::regex(R"(left,stick,2,68\.2[0-9]*)"))) << lines[2];
  EXPECT_TRUE(std::regex_match(lines[3], std::regex(R"(left,slip,1,7\.4[0-9]*)"))) << lines[3];
  EXPECT_TRUE(std::regex_match(lines[4], std::regex(R"(left,slip,2,23\.9[0-9]*)"))) << lines[4];
  EXPECT_EQ(lines[5].rfind("right,stick,1,21.1", 0), 0u) << lines[5];
  EXPECT_EQ(lines[9].rfind("damper,stick,1,", 0), 0u) << lines[9];
  EXPECT_EQ(lines[16].rfind("damper,slip,4,29.5", 0), 0u) << lines[16];
  // The table: the arms' frequencies to 0.01 Hz, the damper's modes with energy shares.
  EXPECT_NE(r.out.find("left        21.17      68.21       7.42      23.90  Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rigid-body mode at 0 Hz is not listed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("50%"), std::string::npos) << r.out;
}

constexpr const char* kNamedDamper =
    "[clamp]\nmass = 0.5\n"
    "[[arm]]\nname = \"damper\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
    "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n";

// The whole damper's rows are "damper": an arm of that name makes the arms arm1, ...
TEST(ModesCli, AnArmNamedDamperIsRenamedInTheCsv) {
  const auto dir = scratch_directory("modes-named");
  std::ofstream(dir / "d.toml") << kNamedDamper;
  const CliResult r = run_cli("modes d.toml -o m.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = lines_of(read_text(dir / "m.csv"));
  ASSERT_EQ(lines.size(), 1u + 4u + 4u);
  EXPECT_EQ(lines[1].rfind("arm1,stick,1,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[5].rfind("damper,stick,1,", 0), 0u) << lines[5];
}

struct BadModesRun {
  const char* name;
  const char* damper;  // file contents, or nullptr: no file
  const char* arguments;
  const char* must_mention;
};

void PrintTo(const BadModesRun& bad, std::ostream* os) { *os << bad.name; }

class ModesCliRejects : public ::testing::TestWithParam<BadModesRun> {};

TEST_P(ModesCliRejects, WithOneLineExitTwoAndNoFile) {
  const auto dir = scratch_directory(std::string("modes-bad-") + GetParam().name);
  if (GetParam().damper) std::ofstream(dir / "d.toml") << GetParam().damper;
  const CliResult r = run_cli(GetParam().arguments, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().must_mention), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, ModesCliRejects,
    ::testing::Values(
        BadModesRun{"missing_file", nullptr, "modes d.toml --json -o out.csv", "d.toml: no such file"},
        BadModesRun{"negative_mass",
                    "[clamp]\nmass = 0.7\n[[arm]]\nmass = -0.856\ninertia = 0.001814\noffset = 0.0325\n"
                    "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\n",
                    "modes d.toml -o out.csv", "d.toml:4: arm[0].mass = -0.856"},
        BadModesRun{"offset_beyond_cable",
                    "[clamp]\nmass = 0.7\n[[arm]]\nmass = 0.856\ninertia = 0.001814\noffset = 0.5\n"
                    "[arm.cable]\nlength = 0.1875\nsections = 8\nei = 2.8\n",
                    "modes d.toml --json -o out.csv", "arm[0].offset = 0.5"},
        BadModesRun{"no_arm", "[clamp]\nmass = 0.7\n", "modes d.toml -o out.csv", "'arm'"},
        BadModesRun{"output_is_input", "[clamp]\nmass = 0.7\n", "modes d.toml -o d.toml", "is the damper file"},
        BadModesRun{"unknown_flag", "[clamp]\nmass = 0.7\n", "modes d.toml --jsn -o out.csv", "did you mean '--json'?"}),
    [](const ::testing::TestParamInfo<BadModesRun>& info) { return info.param.name; });

}  // namespace
}  // namespace stockbridge::testing
