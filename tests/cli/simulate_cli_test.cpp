// `stockbridge simulate` as users run it: the example span at 20 Hz settles beside
// the balance (the history's header and rows, the JSON's figures), a run too short
// to settle writes its history and exits 3 with no steady figure, Ctrl-C keeps the
// rows done, and bad input exits 2 with one line and no file.

#include <sys/wait.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"
#include "support/csv_table.hpp"

namespace stockbridge::testing {
namespace {

// Names here are unique among the CLI tests (the sanitizers' unity batches).
const std::string kSimulateExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

/// The example span and its damper in a scratch folder.
std::filesystem::path simulate_example(const std::string& name) {
  const auto dir = scratch_directory(name);
  std::filesystem::copy_file(kSimulateExamples + "aster570_400m.toml", dir / "span.toml");
  std::filesystem::copy_file(kSimulateExamples + "sauter2003.toml", dir / "sauter2003.toml");
  return dir;
}

// At 20 Hz, on a coarse mesh and step (10 elements a wavelength, 40 steps a period:
// seconds, not minutes), the example settles in about 20 s simulated. The history
// has a row per period (--every 40), its clamp-1 Y_b point, the dampers' and
// mid-span's displacements, each damper's force and velocity; the summary gives the
// figures beside the balance's: each damper's power equals its cables' dissipation,
// and its clamp velocity is within 5 % of the balance's (docs/time-domain.md).
TEST(SimulateCli, TheExampleSettlesBesideTheBalance) {
  const auto dir = simulate_example("simulate-example");
  const CliResult r = run_cli("simulate span.toml --frequency 20 --elements-per-wavelength 10 --steps-per-period 40 --every 40 --json -o history.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines_of(read_text(dir / "history.csv")).at(0),
            "time_s,y_at_89mm_m,y_at_1000mm_m,y_at_200000mm_m,y_at_399000mm_m,damper_1_force_n,"
            "damper_1_velocity_m_s,damper_2_force_n,damper_2_velocity_m_s");
  const Csv history = read_csv(dir / "history.csv");
  const std::vector<double> t = history.column("time_s");
  EXPECT_EQ(static_cast<double>(t.size()), json_number(r.out, "periods"));
  const double dt = json_number(r.out, "dt_s");
  for (std::size_t i = 1; i < t.size(); ++i) ASSERT_NEAR(t[i] - t[i - 1], 40 * dt, 1e-9);
  EXPECT_NEAR(t.back(), json_number(r.out, "simulated_s"), 1e-9);
  for (const char* key : {"\"settled\": true", "\"interrupted\": false", "\"ends\": \"clamped\"",
                          "\"asked_frequency_hz\": 20", "\"ebm_converged\": true", "\"column\": \"damper_2\"",
                          "\"probes_m\": [0.089, 1, 200, 399]"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  EXPECT_NEAR(json_number(r.out, "antinode_amplitude_m_ratio"), 1.0, 0.1);
  for (const char* damper : {"\"column\": \"damper_1\"", "\"column\": \"damper_2\""}) {
    const std::size_t at = r.out.find(damper);
    ASSERT_NE(at, std::string::npos);
    EXPECT_NEAR(json_number(r.out, "power_w", at) / json_number(r.out, "dissipated_w", at), 1.0, 0.02);
    EXPECT_NEAR(json_number(r.out, "velocity_m_s_ratio", at), 1.0, 0.05);
  }
  // The history's last rows against the summary: the velocity's amplitude over the
  // last period is the first harmonic's within the harmonics' share.
  const std::vector<double> v = history.column("damper_1_velocity_m_s");
  double largest = 0.0;
  for (std::size_t i = v.size() - 1; i + 40 > v.size(); --i) largest = std::max(largest, std::abs(v[i]));
  EXPECT_GT(largest, 0.0);
}

// Two seconds do not settle the span: the history is written, the exit status is 3,
// and no steady figure is given (null), only the last period's envelope.
TEST(SimulateCli, TooShortARunWritesItsHistoryAndExitsThree) {
  const auto dir = simulate_example("simulate-short");
  const CliResult r = run_cli("simulate span.toml --frequency 30 --duration 2 --elements-per-wavelength 10 --steps-per-period 40 --probe 100,200 --json -o history.csv", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("did not settle within 2 s"), std::string::npos) << r.err;
  const Csv history = read_csv(dir / "history.csv");
  EXPECT_GT(history.column("y_at_100000mm_m").size(), 2000u);
  for (const char* key : {"\"settled\": false", "\"antinode_amplitude_m\": null", "\"power_w\": null",
                          "\"probes_m\": [100, 200]"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  EXPECT_GT(json_number(r.out, "last_envelope_m"), 0.0);
}

// Ctrl-C ends the run after the step under way: the rows simulated are written
// (nothing in them unfinished), status 130.
TEST(SimulateCli, CtrlCKeepsTheRowsDone) {
  const auto dir = simulate_example("simulate-stopped");
  const int status = run_cli_stopped_when(
      "simulate span.toml --frequency 30 --duration 1000 --start-amplitude 0.001 --quiet -o history.csv", dir,
      [&] {
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
          std::error_code ec;
          if (entry.path().filename().string().starts_with(".history.csv.tmp-") &&
              std::filesystem::file_size(entry.path(), ec) > 100000 && !ec) {
            return true;
          }
        }
        return false;
      },
      SIGINT);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << read_text(dir / "run.err");
  EXPECT_NE(read_text(dir / "run.err").find("simulate: interrupted; the "), std::string::npos) << read_text(dir / "run.err");
  const Csv history = read_csv(dir / "history.csv");
  EXPECT_GT(history.column("time_s").size(), 100u);
}

void expect_bad_simulate(const std::string& arguments, const std::string& mention, const std::string& extra = "") {
  const auto dir = simulate_example("simulate-bad");
  std::ofstream(dir / "span.toml", std::ios::app) << extra;
  const CliResult r = run_cli(arguments, dir);
  EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << arguments << "\n" << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << "\n" << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv")) << arguments;
}

TEST(SimulateCli, BadInputExitsTwoWithOneLineAndNoFile) {
  expect_bad_simulate("simulate span.toml --frequency 0 -o out.csv", "frequency = 0");
  expect_bad_simulate("simulate span.toml -o out.csv", "--frequency is required");
  expect_bad_simulate("simulate span.toml --frequency 20 --ends hinged -o out.csv", "ends = 'hinged'");
  expect_bad_simulate("simulate span.toml --frequency 20 --probe 500 -o out.csv", "probes[0] = 500");
  expect_bad_simulate("simulate span.toml --frequency 20 --probe 10,10.0001 -o out.csv", "probes[1]");
  expect_bad_simulate("simulate span.toml --frequency 20 --every 0 -o out.csv", "every = 0");
  expect_bad_simulate("simulate span.toml --frequency 20 --steps-per-period 4 -o out.csv", "steps_per_period = 4");
  expect_bad_simulate("simulate span.toml --frequency 20 -o span.toml", "span.toml");
  expect_bad_simulate("simulate span.toml --frequency 20 -o out.csv", "mass[0]: masses along the span are not modelled in time",
                      "\n[[mass]]\nname = \"sphere\"\nmass = 15.0\npositions = [150.0]\n");
  expect_bad_simulate("simulate span.toml --frequency 20 -o out.csv", "is a measured impedance sheet",
                      "\n[[damper]]\nimpedance = \"" + kSimulateExamples + "vendor_sheet.csv\"\nposition = 2.0\n");
}

}  // namespace
}  // namespace stockbridge::testing
