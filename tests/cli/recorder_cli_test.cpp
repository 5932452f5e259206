// `stockbridge recorder` as users run it: the bins CSV's header and rows, the
// --json sections, the calibrated span file, and bad input (exit 2, one line, no
// file written).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

// ASTER570 without dampers (a balance in milliseconds), a foti wind and a climate.
const std::string kRecorderSpan =
    "[conductor]\nname = \"ASTER570\"\nmass_per_length = 1.571\ndiameter = 0.03105\nrated_tensile_strength = 185300\n"
    "ei_min = 28.28\nouter_wire_diameter = 0.00345\nouter_wire_modulus = 68e9\naluminium_layers = 4\n"
    "[span]\nlength = 400\ntension_fraction = 0.15\n[wind]\nlaw = \"foti\"\nturbulence_intensity = 0.15\n"
    "[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n"
    "wind_weibull = { shape = 2.0, scale = 4.0 }\naeolian_fraction = 0.3\n";
// Counts near the undamped span's own amplitudes (0.3 to 2.8 mm), so that a turbulence
// intensity can meet them.
const std::string kRecorderCounts =
    "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n"
    "0.8,1.2,8,12,20000\n1.2,1.8,8,12,50000\n1.8,2.8,8,12,9000\n0.4,0.6,12,18,30000\n0.6,1,12,18,60000\n"
    "0.2,0.4,18,27,80000\n0.4,0.6,18,27,20000\n0.08,0.2,27,40,90000\n";
// A record a quarter of those amplitudes: far below what the undamped span does in any
// turbulence (the dampers forgotten in the span file, say).
const std::string kFarBelowCounts =
    "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles\n"
    "0.2,0.3,8,12,20000\n0.3,0.45,8,12,50000\n0.45,0.7,8,12,9000\n0.1,0.15,12,18,30000\n0.15,0.25,12,18,60000\n"
    "0.05,0.1,18,27,80000\n0.1,0.15,18,27,20000\n0.02,0.05,27,40,90000\n";

std::filesystem::path recorder_case(const std::string& name) {
  const std::filesystem::path dir = scratch_directory(name);
  std::ofstream(dir / "span.toml") << kRecorderSpan;
  std::ofstream(dir / "counts.csv") << kRecorderCounts;
  return dir;
}

TEST(RecorderCli, BinsJsonAndTheCalibratedSpanFile) {
  const std::filesystem::path dir = recorder_case("recorder-cli-run");
  const CliResult r = run_cli("recorder span.toml counts.csv --days 30 --calibrate wind.turbulence_intensity "
                              "--calibrated-span calibrated.toml --json -o bins.csv",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = lines_of(read_text(dir / "bins.csv"));
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[0], "yb_pp_mm_low,yb_pp_mm_high,frequency_hz_low,frequency_hz_high,cycles,stress_ps_mpa,"
                      "microstrain_pp,cycles_to_failure,damage");
  for (const std::string key : {"\"measured\": {", "\"predicted\": {", "\"calibrated\": {", "\"damage_per_year\"",
                                "\"life_years\"", "\"max_yb_pp_mm\"", "\"fraction_above_endurance\"", "\"bands\"",
                                "\"recorded_mean_ln_yb_mm\"", "\"wind.turbulence_intensity\": {", "\"standard_error\"",
                                "\"residual_before\"", "\"residual_after\""}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  const std::string calibrated = read_text(dir / "calibrated.toml");
  EXPECT_EQ(calibrated.find("turbulence_intensity = 0.15\n"), std::string::npos) << calibrated;
  EXPECT_NE(calibrated.find("aeolian_fraction = 0.3"), std::string::npos);
  // The calibrated file is a span file the program reads.
  const CliResult again = run_cli("recorder calibrated.toml counts.csv --days 30 --quiet -o again.csv", dir);
  EXPECT_EQ(again.exit_code, 0) << again.err;
}

// A record no value of the key can meet: the fit runs to the bound. That is no
// calibration: exit 3, the reason on stderr, the JSON's converged false, and no
// calibrated span file (the bins and the measured figures are still written).
TEST(RecorderCli, ACalibrationAtItsBoundIsNotAFitAndWritesNoSpanFile) {
  const std::filesystem::path dir = recorder_case("recorder-cli-bound");
  std::ofstream(dir / "below.csv") << kFarBelowCounts;
  const CliResult r = run_cli("recorder span.toml below.csv --days 30 --calibrate wind.turbulence_intensity "
                              "--calibrated-span calibrated.toml --json -o bins.csv",
                              dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("wind.turbulence_intensity ran to its bound, 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("calibrated.toml not written"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("\"converged\": false"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "bins.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "calibrated.toml"));
}

TEST(RecorderCli, BadInputIsOneLineAndWritesNothing) {
  const std::filesystem::path dir = recorder_case("recorder-cli-bad");
  const CliResult days = run_cli("recorder span.toml counts.csv --days 0 -o bins.csv", dir);
  EXPECT_EQ(days.exit_code, 2);
  EXPECT_EQ(lines_of(days.err).size(), 1u) << days.err;
  EXPECT_NE(days.err.find("--days = 0"), std::string::npos) << days.err;
  std::string cigre = kRecorderSpan;
  const std::string foti = "law = \"foti\"\nturbulence_intensity = 0.15";
  cigre.replace(cigre.find(foti), foti.size(), "law = \"cigre\"");
  std::ofstream(dir / "cigre.toml") << cigre;
  const CliResult law = run_cli("recorder cigre.toml counts.csv --days 30 --calibrate wind.turbulence_intensity -o bins.csv", dir);
  EXPECT_EQ(law.exit_code, 2);
  EXPECT_EQ(lines_of(law.err).size(), 1u) << law.err;
  EXPECT_NE(law.err.find("cigre.toml"), std::string::npos) << law.err;
  EXPECT_NE(law.err.find("'cigre'"), std::string::npos) << law.err;
  std::string no_climate = kRecorderSpan.substr(0, kRecorderSpan.find("wind_weibull"));
  std::ofstream(dir / "bare.toml") << no_climate;
  const CliResult climate = run_cli("recorder bare.toml counts.csv --days 30 -o bins.csv", dir);
  EXPECT_EQ(climate.exit_code, 2);
  EXPECT_NE(climate.err.find("bare.toml: fatigue.wind_weibull"), std::string::npos) << climate.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bins.csv"));
}

}  // namespace
}  // namespace stockbridge::testing
