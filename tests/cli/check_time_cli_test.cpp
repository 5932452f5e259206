// `stockbridge span --check-time` and the span file's settings of a run in time, as
// users run them: each frequency's simulation is `simulate`'s at that frequency,
// beside the span command's own balance; the CSV, the JSON and the report give the
// same figures; a warning stands for each check more than 10 % apart, and for none
// other; [span] ends and [time] steer `simulate` unless its options say otherwise;
// bad input exits 2 with one line and nothing written.

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
const std::string kCheckTimeExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

/// The example span and its damper in a scratch folder, `extra` appended to the span
/// file; by default a coarse mesh and step (seconds, not minutes, a run).
std::filesystem::path check_time_example(const std::string& name,
                                         const std::string& extra = "\n[time]\nelements_per_wavelength = 10\n"
                                                                    "steps_per_period = 40\n") {
  const auto dir = scratch_directory(name);
  std::filesystem::copy_file(kCheckTimeExamples + "aster570_400m.toml", dir / "span.toml");
  std::filesystem::copy_file(kCheckTimeExamples + "sauter2003.toml", dir / "sauter2003.toml");
  std::ofstream(dir / "span.toml", std::ios::app) << extra;
  return dir;
}

// At 20 and 30 Hz on the coarse mesh: each row's figures are `simulate`'s at the
// same frequency and settings (the same run), its ratios theirs, `agrees` the 10 %
// rule of its own ratios, and a warning names each frequency that does not agree
// and no other. The JSON's list and the report's section give the same rows.
TEST(SpanCheckTime, EachFrequencyIsTheSimulationBesideTheBalance) {
  const auto dir = check_time_example("check-time");
  const CliResult r = run_cli(
      "span span.toml --points 10 --check-time 20,30 --check-time-output checks.csv --report r.html --json -o s.csv",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv checks = read_csv(dir / "checks.csv");
  EXPECT_EQ(checks.header,
            (std::vector<std::string>{"asked_frequency_hz", "frequency_hz", "settled", "simulated_s",
                                      "antinode_amplitude_m", "ebm_antinode_amplitude_m", "antinode_amplitude_ratio",
                                      "stress_fymax_mpa", "ebm_stress_fymax_mpa", "stress_fymax_ratio",
                                      "bending_amplitude_m", "ebm_bending_amplitude_m", "bending_amplitude_ratio",
                                      "agrees"}));
  ASSERT_EQ(checks.rows.size(), 2u);
  const std::string report = read_text(dir / "r.html");
  EXPECT_NE(report.find("Checked in time"), std::string::npos);
  const std::size_t listed = r.out.find("\"check_time\": [");
  ASSERT_NE(listed, std::string::npos) << r.out;
  for (std::size_t i = 0; i < 2; ++i) {
    const double f = checks.column("asked_frequency_hz")[i];
    EXPECT_EQ(f, i == 0 ? 20.0 : 30.0);
    EXPECT_EQ(checks.column("settled")[i], 1.0);
    const CliResult alone = run_cli(
        "simulate span.toml --frequency " + std::to_string(static_cast<int>(f)) + " --every 100000 --json -o h.csv", dir);
    ASSERT_EQ(alone.exit_code, 0) << alone.err;
    for (const char* key : {"frequency_hz", "antinode_amplitude_m", "ebm_antinode_amplitude_m", "antinode_amplitude_m_ratio"}) {
      const std::string column = std::string(key) == "antinode_amplitude_m_ratio" ? "antinode_amplitude_ratio" : key;
      EXPECT_NEAR(checks.column(column)[i], json_number(alone.out, key), 1e-12 * std::abs(checks.column(column)[i]))
          << key << " at " << f << " Hz";
    }
    EXPECT_NEAR(checks.column("stress_fymax_mpa")[i], 1e-6 * json_number(alone.out, "stress_fymax_pa"), 1e-9);
    EXPECT_NEAR(checks.column("ebm_stress_fymax_mpa")[i], 1e-6 * json_number(alone.out, "ebm_stress_fymax_pa"), 1e-9);
    const double y = checks.column("antinode_amplitude_ratio")[i], s = checks.column("stress_fymax_ratio")[i];
    EXPECT_DOUBLE_EQ(y, checks.column("antinode_amplitude_m")[i] / checks.column("ebm_antinode_amplitude_m")[i]);
    EXPECT_NEAR(s, checks.column("bending_amplitude_ratio")[i], 1e-12);  // both the clamp loop's ratio
    const bool agrees = std::abs(y - 1.0) <= 0.1 && std::abs(s - 1.0) <= 0.1;
    EXPECT_EQ(checks.column("agrees")[i], agrees ? 1.0 : 0.0);
    const std::string warning = "warning: check in time at " + std::to_string(static_cast<int>(f)) + " Hz (";
    EXPECT_EQ(r.err.find(warning) != std::string::npos, !agrees) << r.err;
    // The JSON's row for this frequency, and the report's.
    const std::size_t row = r.out.find("\"asked_frequency_hz\": " + std::to_string(static_cast<int>(f)), listed);
    ASSERT_NE(row, std::string::npos) << r.out;
    EXPECT_DOUBLE_EQ(json_number(r.out, "antinode_amplitude_ratio", row), y);
    const std::string cell = std::string(">").append(std::to_string(static_cast<int>(f))).append("</td>");
    EXPECT_NE(report.find(cell), std::string::npos) << f;
  }
  // The coarse mesh's 30 Hz is a quarter below the balance (docs/time-domain.md).
  EXPECT_LT(checks.column("antinode_amplitude_ratio")[1], 0.9);
  EXPECT_NE(r.err.find("more than 10 % apart"), std::string::npos) << r.err;
}

// [span] ends and [time] are simulate's defaults; its options replace them.
TEST(SpanCheckTime, TheSpanFilesEndsAndTimeTableSteerSimulate) {
  const auto dir = check_time_example(
      "check-time-settings", "\n[time]\nelements_per_wavelength = 8\nsteps_per_period = 24\nduration = 0.5\n");
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("[span]\n"), 7, "[span]\nends = \"pinned\"\n");
  std::ofstream(dir / "span.toml") << text;
  const CliResult file = run_cli("simulate span.toml --frequency 20 --json -o h.csv", dir);
  EXPECT_EQ(file.exit_code, 3) << file.err;  // half a second does not settle
  EXPECT_NE(file.out.find("\"ends\": \"pinned\""), std::string::npos) << file.out;
  EXPECT_NEAR(json_number(file.out, "simulated_s"), 0.5, 0.01);
  const double dt = json_number(file.out, "dt_s"), f = json_number(file.out, "frequency_hz");
  EXPECT_NEAR(dt * f, 1.0 / 24.0, 1e-9);
  const CliResult options = run_cli(
      "simulate span.toml --frequency 20 --ends clamped --steps-per-period 30 --elements-per-wavelength 9 "
      "--duration 0.25 --json -o h.csv",
      dir);
  EXPECT_EQ(options.exit_code, 3) << options.err;
  EXPECT_NE(options.out.find("\"ends\": \"clamped\""), std::string::npos) << options.out;
  EXPECT_NEAR(json_number(options.out, "dt_s") * json_number(options.out, "frequency_hz"),
              1.0 / 30.0, 1e-9);
  EXPECT_NEAR(json_number(options.out, "simulated_s"), 0.25, 0.01);
  EXPECT_GT(json_number(options.out, "elements"), json_number(file.out, "elements"));
}

// The wake oscillator's wind on the example with its dampers at 30 Hz (the coarse
// mesh): the run settles, the wind's speed sheds at 30 Hz, and the wind's power is the
// self-damping's and the dampers' (the rule's own work, within 1 %).
TEST(SpanCheckTime, TheWakesWindFeedsTheDampingAndTheDampers) {
  const auto dir = check_time_example("wake-wind");
  const CliResult r = run_cli("simulate span.toml --frequency 30 --wind wake --duration 300 --every 100000 --json "
                              "--report wake.html -o h.csv",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"wind\": \"wake\""), std::string::npos) << r.out;
  EXPECT_NEAR(json_number(r.out, "wind_speed_m_s"), 30.0 * 0.03105 / 0.185, 1e-9);
  double dampers = 0.0;
  for (const char* damper : {"\"column\": \"damper_1\"", "\"column\": \"damper_2\""}) {
    const std::size_t at = r.out.find(damper);
    ASSERT_NE(at, std::string::npos);
    dampers += json_number(r.out, "power_w", at);
  }
  const double wind = json_number(r.out, "wind_power_w");
  EXPECT_GT(dampers, 0.5 * wind);
  EXPECT_NEAR((json_number(r.out, "damping_power_w") + dampers) / wind, 1.0, 0.01);
  EXPECT_NE(read_text(dir / "wake.html").find("the wake oscillator at U = "), std::string::npos);
}

// Ctrl-C while the checks run ends them: status 130 and nothing written, the
// balance's files neither (the run as a whole is not done).
TEST(SpanCheckTime, CtrlCWhileCheckingWritesNothing) {
  const auto dir = check_time_example("check-time-stopped", "\n[time]\nduration = 1000\n");
  const int status = run_cli_stopped_when(
      "span span.toml --points 10 --check-time 12 --check-time-output checks.csv -o s.csv", dir,
      [&] { return std::filesystem::exists(dir / "run.err") && read_text(dir / "run.err").find("checking 1 frequency") != std::string::npos; },
      SIGINT);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << read_text(dir / "run.err");
  EXPECT_NE(read_text(dir / "run.err").find("interrupted while checking in time; nothing written"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "s.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "checks.csv"));
}

void expect_bad_check_time(const std::string& arguments, const std::string& mention, const std::string& extra = "") {
  const auto dir = check_time_example("check-time-bad", extra);
  const CliResult r = run_cli(arguments, dir);
  EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << arguments << "\n" << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << "\n" << r.err;
  for (const char* output : {"out.csv", "checks.csv", "r.html"}) EXPECT_FALSE(std::filesystem::exists(dir / output)) << arguments;
}

TEST(SpanCheckTime, BadInputExitsTwoWithOneLineAndNothingWritten) {
  expect_bad_check_time("span span.toml --check-time 0 --check-time-output checks.csv -o out.csv", "check_time[0] = 0");
  expect_bad_check_time("span span.toml --check-time 20,x -o out.csv", "--check-time");
  expect_bad_check_time("span span.toml --check-time-output checks.csv -o out.csv", "--check-time");
  expect_bad_check_time("span span.toml --modes --check-time 20 -o out.csv", "--check-time");
  expect_bad_check_time("span span.toml --check-time 20 --report r.html -o out.csv", "is a measured impedance sheet",
                        "\n[[damper]]\nimpedance = \"" + kCheckTimeExamples + "vendor_sheet.csv\"\nposition = 2.0\n");
  expect_bad_check_time("span span.toml --check-time 20 -o out.csv", "time.steps_per_period", "\n[time]\nsteps_per_period = 4\n");
  expect_bad_check_time("span span.toml --check-time 20 -o out.csv", "time.duration", "\n[time]\nduration = -1\n");
  expect_bad_check_time("span span.toml --check-time 20 -o out.csv", "time.step", "\n[time]\nstep = 1\n");
  expect_bad_check_time("simulate span.toml --frequency 20 --wind breeze -o out.csv", "wind = 'breeze'");
  expect_bad_check_time("simulate span.toml --frequency 20 --wind wake -o out.csv", "wake.epsilon = 0",
                        "\n[wake]\nepsilon = 0\n");
  expect_bad_check_time("simulate span.toml --frequency 20 -o out.csv", "wake.lift", "\n[wake]\nlift = 0.3\n");
  const auto dir = check_time_example("check-time-bad-ends", "");
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("[span]\n"), 7, "[span]\nends = \"hinged\"\n");
  std::ofstream(dir / "span.toml") << text;
  const CliResult r = run_cli("simulate span.toml --frequency 20 -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("span.ends = 'hinged'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("span.toml:"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stockbridge::testing
