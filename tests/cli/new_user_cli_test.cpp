// What a new user hit (issue 13): an output that is one of the inputs, misspelt
// words, empty lists, number noise in the CSV, --version.

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

std::vector<std::vector<std::string>> csv_cells(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(NewUserCli, AnOutputThatIsAnInputIsRefusedAndTheInputKept) {
  const auto dir = scratch_directory("output-is-input");
  std::filesystem::copy_file(kDamperExample, dir / "my_damper.toml");
  std::filesystem::create_symlink(dir / "my_damper.toml", dir / "link.toml");
  const std::string original = read_text(dir / "my_damper.toml");
  for (const std::string output : {"my_damper.toml", "./my_damper.toml", "link.toml"}) {
    SCOPED_TRACE(output);
    const CliResult r = run_cli("impedance my_damper.toml --velocity 0.1 --frequencies 20 -o " + output, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.stderr_lines(), 1);
    EXPECT_NE(r.err.find("is the damper file"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(dir / "my_damper.toml"), original);
  }
  std::filesystem::copy_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/cycle_measured_a.csv", dir / "cm.csv");
  const std::string measured = read_text(dir / "cm.csv");
  const CliResult fitted =
      run_cli("identify global --experiment a --length 0.3 --input cm.csv --method four-step --fitted cm.csv", dir);
  EXPECT_EQ(fitted.exit_code, 2);
  EXPECT_NE(fitted.err.find("--fitted cm.csv: is the --input record"), std::string::npos) << fitted.err;
  EXPECT_EQ(read_text(dir / "cm.csv"), measured);
  const CliResult twice =
      run_cli("identify global --experiment a --length 0.3 --input cm.csv --method four-step -o x.csv --fitted x.csv", dir);
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("the same file as -o"), std::string::npos) << twice.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.csv"));
}

TEST(NewUserCli, ListsMayHaveSpacesButNotBeEmpty) {
  const auto dir = scratch_directory("lists");
  const CliResult spaced = run_cli("impedance '" + kDamperExample + "' --velocity '0.1, 0.05' --frequencies '10, 20' -o z.csv", dir);
  ASSERT_EQ(spaced.exit_code, 0) << spaced.err;
  EXPECT_EQ(csv_cells(read_text(dir / "z.csv")).size(), 1u + 4u);
  const CliResult empty = run_cli("impedance '" + kDamperExample + "' --velocity 0.1 --frequencies '' -o e.csv", dir);
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("--frequencies = '': expected a comma-separated list"), std::string::npos) << empty.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "e.csv"));
}

// The grid's ends and the amplitudes are printed as typed; Re Z and P that are
// round-off of zero (nothing slips at 1 Hz) are printed as 0.
TEST(NewUserCli, NumbersTheUserGaveArePrintedAsGiven) {
  const auto dir = scratch_directory("number-noise");
  const CliResult r = run_cli("impedance '" + kDamperExample + "' --velocity 0.2 --fmin 5 --fmax 100 --points 7 -o z.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_cells(read_text(dir / "z.csv"));
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows[1][0], "5");
  EXPECT_EQ(rows[7][0], "100");
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i][1], "0.2");
  const CliResult stick = run_cli("impedance '" + kDamperExample + "' --velocity 0.2 --frequencies 1 -o s.csv", dir);
  ASSERT_EQ(stick.exit_code, 0) << stick.err;
  const auto stuck = csv_cells(read_text(dir / "s.csv"));
  EXPECT_EQ(stuck[0][2], "re_z_n_s_m");
  EXPECT_EQ(stuck[1][2], "0");  // round-off of zero: the arms do not slip at 1 Hz
  EXPECT_EQ(stuck[0][6], "power_w");
  EXPECT_EQ(stuck[1][6], "0");
}

TEST(NewUserCli, MisspeltWordsAreNamedWithTheClosestValidOne) {
  const auto dir = scratch_directory("misspelt");
  const CliResult command = run_cli("impedence '" + kDamperExample + "' --velocity 0.1 -o z.csv", dir);
  EXPECT_EQ(command.exit_code, 2);
  EXPECT_EQ(command.err, "stockbridge: unknown command 'impedence' for 'stockbridge': did you mean 'impedance'?\n");
  const CliResult flag = run_cli("impedance '" + kDamperExample + "' --velocty 0.1 -o z.csv", dir);
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_EQ(flag.err, "stockbridge: unknown option '--velocty' for 'stockbridge impedance': did you mean '--velocity'?\n");
}

TEST(NewUserCli, VersionComesFromTheProject) {
  const CliResult r = run_cli("--version", scratch_directory("version"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "stockbridge " STOCKBRIDGE_PROJECT_VERSION "\n");
}

}  // namespace
}  // namespace stockbridge::testing

namespace stockbridge::testing {
namespace {

// Progress goes to stderr only on a terminal or, elsewhere, for runs longer than 10 s:
// a short run to a file says nothing but its summary; --quiet is accepted.
TEST(NewUserCli, AShortRunToAFileSaysOnlyItsSummary) {
  const auto dir = scratch_directory("progress");
  for (const std::string quiet : {"", " --quiet"}) {
    const CliResult r = run_cli("impedance '" + kDamperExample + "' --velocity 0.2 --frequencies 10,20" + quiet + " -o z.csv", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.stderr_lines(), 1) << r.err;
    EXPECT_EQ(r.err.rfind("impedance: 2 points", 0), 0u) << r.err;
  }
}

}  // namespace
}  // namespace stockbridge::testing
