// `stockbridge span` as users run it: the shipped example (CSV header and rows,
// --json keys, the report), the undamped check numbers through the program,
// --no-dampers, the position search, and bad input (exit 2, one line, no file
// written or overwritten).
//
// Under the sanitizers (STOCKBRIDGE_TEST_SCALE=short) a damped run costs 10-40 times
// more, most of it the damper's impedance tables and the polish at the upper end of
// the band: the damped runs there take fewer points of the same band (or, for the
// weak model, two frequencies instead of three) and check the same things.

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"
#include "support/csv_table.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::testing {
namespace {

const std::string kExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";
const std::string kSpanExample = kExamples + "aster570_400m.toml";

const std::string kHeader =
    "frequency_hz,wind_speed_m_s,wavelength_m,amplitude_m,amplitude_over_diameter,wind_power_w,self_damping_power_w,"
    "damper_power_w,clamp_loop_amplitude_m,damper_clamp_velocity_m_s,stress_fymax_mpa,stress_ps_mpa,"
    "damper_clamp_stress_mpa,undamped_amplitude_m,undamped_stress_fymax_mpa,converged";

/// A scratch folder holding a copy of the example span and its damper file.
std::filesystem::path example_copy(const std::string& name) {
  const auto dir = scratch_directory(name);
  std::filesystem::copy_file(kSpanExample, dir / "span.toml");
  std::filesystem::copy_file(kExamples + "sauter2003.toml", dir / "sauter2003.toml");
  return dir;
}

TEST(SpanCli, RunsTheExampleAndWritesTheCsv) {
  const auto dir = scratch_directory("span-example");
  const int points = scaled(12, 4);
  const CliResult r = run_cli("span '" + kSpanExample + "' --points " + std::to_string(points) + " -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read_text(dir / "span.csv");
  EXPECT_EQ(text.rfind(kHeader + ",endurance_limit_mpa,energy_identity_error,undamped_stress_ps_mpa,several_states,"
                                 "bending_amplitude_pp_m,bending_strain_pp_microstrain,undamped_bending_amplitude_pp_m,"
                                 "undamped_bending_strain_pp_microstrain,stress_fymax_low_mpa,stress_fymax_high_mpa,"
                                 "endurance_limit_pp_microstrain,"
                                 "sauter2003_end1_velocity_m_s,",
                       0),
            0u)
      << text.substr(0, text.find('\n'));
  const Csv csv = read_csv(dir / "span.csv");
  ASSERT_EQ(csv.rows.size(), static_cast<std::size_t>(points));
  for (const char* column : {"sauter2003_end1_velocity_m_s", "sauter2003_end1_re_z_n_s_m", "sauter2003_end1_im_z_n_s_m",
                             "sauter2003_end1_power_w", "sauter2003_end1_clamp_stress_mpa", "sauter2003_end2_velocity_m_s",
                             "sauter2003_end2_power_w"}) {
    csv.index(column);
  }
  const std::vector<double> f = csv.column("frequency_hz");
  EXPECT_NEAR(f.front(), 0.185 * 1.0 / 0.03105, 1e-9);  // the wind band St U / D
  EXPECT_NEAR(f.back(), 0.185 * 7.0 / 0.03105, 1e-9);
  const auto converged = csv.column("converged");
  const auto amplitude = csv.column("amplitude_m"), undamped = csv.column("undamped_amplitude_m");
  const auto stress = csv.column("stress_fymax_mpa"), limit = csv.column("endurance_limit_mpa");
  const auto damper_power = csv.column("damper_power_w"), end1 = csv.column("sauter2003_end1_power_w"),
             end2 = csv.column("sauter2003_end2_power_w");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_EQ(converged[i], 1.0) << "row " << i;
    EXPECT_LE(amplitude[i], undamped[i] * (1 + 1e-9)) << "a damper lowers the amplitude, f = " << f[i];
    EXPECT_GE(stress[i], 0.0);
    EXPECT_NEAR(limit[i], 8.7, 0.05);  // the several-layer Safe Border Line at 5e8 cycles
    EXPECT_NEAR(damper_power[i], end1[i] + end2[i], 1e-6 * (1.0 + damper_power[i])) << "f = " << f[i];
  }
  EXPECT_NE(r.out.find("criterion safe-border-line: the CIGRE Safe Border Line at 5e+08 cycles, 8.73 MPa"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("life: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lives are comparative: they rest on the assumed wind climate"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("span: " + std::to_string(points) + " points in "), std::string::npos) << r.err;
}

// Without --report the rows go to the CSV as the points are balanced and the summary,
// the profile and the notes are tallied on the way (nothing held); with it the points
// are held for the report's curves. Both write the same CSV, profile and summary.
TEST(SpanCli, RowsStreamedAreTheRowsARunThatHoldsThemWrites) {
  const auto dir = scratch_directory("span-streamed-held");
  const std::string points = std::to_string(scaled(16, 4));
  const CliResult streamed =
      run_cli("span '" + kSpanExample + "' --points " + points + " --json -o a.csv --profile pa.csv", dir);
  const CliResult held =
      run_cli("span '" + kSpanExample + "' --points " + points + " --json -o b.csv --profile pb.csv --report r.html", dir);
  ASSERT_EQ(streamed.exit_code, 0) << streamed.err;
  ASSERT_EQ(held.exit_code, 0) << held.err;
  EXPECT_EQ(read_text(dir / "a.csv"), read_text(dir / "b.csv"));
  EXPECT_EQ(read_text(dir / "pa.csv"), read_text(dir / "pb.csv"));
  const auto without_seconds = [](const std::string& json) {
    const std::size_t at = json.find("\"seconds\"");
    return at == std::string::npos ? json : json.substr(0, at) + json.substr(json.find_first_of(",}", at));
  };
  EXPECT_EQ(without_seconds(streamed.out), without_seconds(held.out));
  EXPECT_TRUE(std::filesystem::exists(dir / "r.html"));
}

// The span's rows are written as they are final: a long band's temporary file grows
// while it runs. Ctrl-C then ends it with status 130, the temporary file removed and
// no output file.
TEST(SpanCli, RowsAreStreamedAndCtrlCLeavesNothing) {
  const auto dir = scratch_directory("span-streamed");
  const StreamedStop stop =
      run_cli_stopped_streaming("span '" + kSpanExample + "' --points 100000 -o s.csv --quiet", dir, "s.csv", SIGINT);
  ASSERT_TRUE(stop.seen) << "no rows in a temporary file within five minutes";
  ASSERT_TRUE(WIFEXITED(stop.status));
  EXPECT_EQ(WEXITSTATUS(stop.status), 130) << read_text(dir / "run.err");
  EXPECT_NE(read_text(dir / "run.err").find("span: interrupted; nothing written"), std::string::npos)
      << read_text(dir / "run.err");
  EXPECT_FALSE(std::filesystem::exists(dir / "s.csv"));
  EXPECT_TRUE(temporary_beside(dir, "s.csv").empty());
}

TEST(SpanCli, JsonSummaryHasEveryKey) {
  const auto dir = scratch_directory("span-json");
  const std::string points = std::to_string(scaled(10, 3));
  const CliResult r = run_cli("span '" + kSpanExample + "' --points " + points + " --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{\"points\": " + points + ", \"converged\": " + points +
                            ", \"damper_model\": \"travelling\", \"dampers\": 1, ",
                        0),
            0u)
      << r.out;
  for (const char* key : {"endurance_limit_mpa", "max_stress_fymax_mpa", "max_stress_frequency_hz",
                          "max_damper_clamp_stress_mpa", "undamped_max_stress_fymax_mpa",
                          "undamped_max_stress_frequency_hz", "position_m", "life_years", "damage_per_year",
                          "undamped_life_years", "undamped_damage_per_year", "impedance_nodes",
                          "failed_impedance_nodes", "direct_solves", "max_energy_identity_error", "life_missing_points",
                          "undamped_life_missing_points", "seconds"}) {
    EXPECT_NE(r.out.find(std::string("\"") + key + "\": "), std::string::npos) << key << " in " << r.out;
  }
  // The band's first frequency, 5.96 Hz, is among the points: 26.1 MPa there, above the 8.73 MPa limit.
  EXPECT_NE(r.out.find("\"verdict\": \"unsafe\""), std::string::npos) << r.out;
  EXPECT_GT(json_number(r.out, "max_stress_fymax_mpa"), json_number(r.out, "endurance_limit_mpa"));
  EXPECT_EQ(json_number(r.out, "life_missing_points"), 0.0);
  EXPECT_NE(r.out.find("\"several_states_hz\": ["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"position_optimized\": false"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"failed\": []"), std::string::npos) << r.out;
  EXPECT_EQ(json_number(r.out, "position_m"), 1.0);
  EXPECT_LT(json_number(r.out, "max_stress_fymax_mpa"), json_number(r.out, "undamped_max_stress_fymax_mpa"));
  EXPECT_GE(json_number(r.out, "life_years"), json_number(r.out, "undamped_life_years"));
  EXPECT_LT(json_number(r.out, "max_energy_identity_error"), 1e-6);
  // The largest stress is the CSV's largest.
  const Csv csv = read_csv(dir / "span.csv");
  double largest = 0.0;
  for (double s : csv.column("stress_fymax_mpa")) largest = std::max(largest, s);
  EXPECT_NEAR(json_number(r.out, "max_stress_fymax_mpa"), largest, 1e-9 * largest);
}

// MODEL.md section 9's undamped check numbers through the program.
TEST(SpanCli, WithoutDampersTheColumnsAreTheUndampedOnes) {
  const auto dir = scratch_directory("span-undamped");
  const CliResult r = run_cli("span '" + kSpanExample + "' --frequencies 10,20,30,40 --no-dampers -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv csv = read_csv(dir / "span.csv");
  EXPECT_EQ(csv.header.back(), "governing_stress_mpa");  // no damper or mass columns
  ASSERT_EQ(csv.rows.size(), 4u);
  const auto amplitude = csv.column("amplitude_m"), undamped = csv.column("undamped_amplitude_m");
  const auto stress = csv.column("stress_fymax_mpa"), undamped_stress = csv.column("undamped_stress_fymax_mpa");
  const auto velocity = csv.column("damper_clamp_velocity_m_s"), power = csv.column("damper_power_w");
  const double expected[] = {26.5e-3, 10.6e-3, 3.04e-3, 1.58e-3};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(amplitude[i], expected[i], 0.005 * expected[i]);
    EXPECT_DOUBLE_EQ(amplitude[i], undamped[i]);
    EXPECT_DOUBLE_EQ(stress[i], undamped_stress[i]);
    EXPECT_TRUE(std::isnan(velocity[i])) << "no damper: empty";
    EXPECT_EQ(power[i], 0.0);
  }
  EXPECT_NE(r.out.find("dampers: none"), std::string::npos) << r.out;
}

// The figures of field practice: the tension in its three forms and TB 273's judgement
// in the report and the JSON; Yb and the strain in microstrain (2 sigma_ps / E_a) in
// every row, at the span clamp and at each damper clamp, and the endurance limit in
// microstrain.
TEST(SpanCli, TensionFiguresAndFieldFiguresOfTheUndampedSpan) {
  const auto dir = example_copy("span-field-figures");
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("tension_fraction = 0.15"), 23, "catenary_parameter = 1100\nterrain = 2");
  std::ofstream(dir / "span.toml") << text;
  const CliResult r = run_cli("span span.toml --frequencies 10,20 --no-dampers -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // T = 1100 * 1.571 * 9.80665 = 16946.6 N = 9.15 % of 185.3 kN; L D / m = 400 * 0.03105 / 1.571 = 7.906
  EXPECT_NE(r.out.find("tension: 16.95 kN, 9.15 % RTS, H/w = 1100 m; span parameter L D / m = 7.906 m^3/kg"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("CIGRE TB 273, terrain category 2: H/w 1100 m is within the 1125 m an undamped single "
                       "conductor allows"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("largest Yb (89 mm from the clamp): "), std::string::npos) << r.out;
  const Csv csv = read_csv(dir / "span.csv");
  const auto ps = csv.column("stress_ps_mpa"), strain = csv.column("bending_strain_pp_microstrain");
  const auto yb = csv.column("bending_amplitude_pp_m"), undamped_yb = csv.column("undamped_bending_amplitude_pp_m");
  const auto limit = csv.column("endurance_limit_mpa"), limit_strain = csv.column("endurance_limit_pp_microstrain");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_NEAR(strain[i], 2.0 * ps[i] * 1e6 / 68e9 * 1e6, 1e-9 * strain[i]);
    EXPECT_NEAR(limit_strain[i], 2.0 * limit[i] * 1e6 / 68e9 * 1e6, 1e-9 * limit_strain[i]);
    EXPECT_DOUBLE_EQ(yb[i], undamped_yb[i]);
    EXPECT_GT(yb[i], 0.0);
  }
  const CliResult json = run_cli("span span.toml --frequencies 10,20 --no-dampers --json -o span2.csv", dir);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NEAR(json_number(json.out, "catenary_parameter_m"), 1100.0, 1e-9);
  EXPECT_NEAR(json_number(json.out, "tension_n"), 1100.0 * 1.571 * 9.80665, 1e-6);
  EXPECT_NEAR(json_number(json.out, "tension_percent_rts"), 100.0 * 1100.0 * 1.571 * 9.80665 / 185300.0, 1e-9);
  EXPECT_NEAR(json_number(json.out, "span_parameter_m3_kg"), 400.0 * 0.03105 / 1.571, 1e-9);
  EXPECT_EQ(json_number(json.out, "terrain"), 2.0);
  EXPECT_EQ(json_number(json.out, "safe_design_catenary_parameter_m"), 1125.0);
  EXPECT_NE(json.out.find("\"safe_design_tension\": \"within\""), std::string::npos) << json.out;
  EXPECT_NEAR(json_number(json.out, "max_bending_amplitude_pp_m"), std::max(yb[0], yb[1]), 1e-9);
  EXPECT_NEAR(json_number(json.out, "max_bending_strain_pp_microstrain"), std::max(strain[0], strain[1]), 1e-6);
  EXPECT_NEAR(json_number(json.out, "endurance_limit_pp_microstrain"), limit_strain[0], 1e-6);
}

// The weak model's dampers sit in the string's own standing wave: v = w Y |sin(k a)|,
// S = Y. The span file's [balance] damper_model gives the same as the option.
TEST(SpanCli, TheWeakDamperModelIsTheStringsOwnStandingWave) {
  const auto dir = example_copy("span-weak");
  const std::string frequencies = scaled<std::string>("10,20,30", "10,15");
  const CliResult r = run_cli("span span.toml --frequencies " + frequencies + " --damper-model weak --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"damper_model\": \"weak\""), std::string::npos) << r.out;
  const Csv csv = read_csv(dir / "span.csv");
  const auto f = csv.column("frequency_hz"), y = csv.column("amplitude_m"), s = csv.column("clamp_loop_amplitude_m");
  const auto lambda = csv.column("wavelength_m"), v = csv.column("sauter2003_end1_velocity_m_s");
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_EQ(s[i], y[i]);
    const double expected = 2.0 * M_PI * f[i] * y[i] * std::abs(std::sin(2.0 * M_PI * 1.0 / lambda[i]));
    EXPECT_NEAR(v[i], expected, 1e-9 * expected) << f[i];
  }
  std::ofstream(dir / "span.toml", std::ios::app) << "\n[balance]\ndamper_model = \"weak\"\n";
  const CliResult from_file = run_cli("span span.toml --frequencies " + frequencies + " -o file.csv", dir);
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  EXPECT_EQ(read_text(dir / "file.csv"), read_text(dir / "span.csv"));
  EXPECT_NE(from_file.out.find("(weak model)"), std::string::npos) << from_file.out;
}

// Points that do not converge (no balance below an amplitude limit of 0.2 D at 10
// and 20 Hz) are said first, kept out of the life (unknown) and of the verdict
// (unsafe only because a converged point exceeds the limit), and listed on stderr.
TEST(SpanCli, PointsThatDidNotConvergeNeverEnterTheLifeOrTheVerdict) {
  const auto dir = example_copy("span-failed");
  std::ofstream(dir / "span.toml", std::ios::app) << "\n[balance]\namplitude_max_over_diameter = 0.2\n";
  const std::string run = "span span.toml --no-dampers --frequencies 10,20,30,40 ";
  const CliResult r = run_cli(run + "-o span.csv", dir);
  ASSERT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.out.rfind("converged 2 of 4 frequencies: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("8.73 MPa (256.8 microstrain peak-to-peak) against the largest fymax stress: unsafe (undamped: "
                       "unsafe)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("life: unknown (2 points missing) (undamped "), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("span: 2 points did not converge"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("f = 10 Hz: no root in the range searched (the wind's power exceeds the dissipation up to "
                       "Y = 0.00621 m)"),
            std::string::npos)
      << r.err;
  const Csv csv = read_csv(dir / "span.csv");
  EXPECT_EQ(csv.column("converged"), (std::vector<double>{0.0, 0.0, 1.0, 1.0}));
  EXPECT_TRUE(std::isnan(csv.column("stress_fymax_mpa")[0]));
  const CliResult json = run_cli(run + "--json -o span.csv", dir);
  ASSERT_EQ(json.exit_code, 3) << json.err;
  EXPECT_TRUE(std::isnan(json_number(json.out, "life_years"))) << json.out;
  EXPECT_EQ(json_number(json.out, "life_missing_points"), 2.0);
  EXPECT_GT(json_number(json.out, "undamped_life_years"), 0.0);
  EXPECT_NE(json.out.find("\"termination\": \"no_root\""), std::string::npos) << json.out;
  // Every converged point within a limit of 1000 MPa, two missing: neither safe nor unsafe.
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("cycles = 5e8"), 12, "endurance_limit = 1e9");
  std::ofstream(dir / "span.toml") << text;
  const CliResult unknown = run_cli(run + "--json -o span.csv", dir);
  EXPECT_NE(unknown.out.find("\"verdict\": \"unknown\""), std::string::npos) << unknown.out;
  EXPECT_NE(unknown.out.find("\"undamped_verdict\": \"safe\""), std::string::npos) << unknown.out;
}

TEST(SpanCli, PositionSearchReportsAndBalancesAtThePositionFound) {
  const auto dir = scratch_directory("span-position");
  // 5 points (short scale) still put the optimum inside the range (2.1 m; 1.9 m on 8); on 3 it is the range's end.
  const std::string band = "span '" + kSpanExample + "' --points " + std::to_string(scaled(8, 5));
  const CliResult at_file = run_cli(band + " --json -o file.csv", dir);
  ASSERT_EQ(at_file.exit_code, 0) << at_file.err;
  const CliResult r = run_cli(band + " --optimize-position 0.5:3 --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"position_optimized\": true"), std::string::npos) << r.out;
  const double position = json_number(r.out, "position_m");
  EXPECT_GE(position, 0.5);
  EXPECT_LE(position, 3.0);
  // 1.0 m (the file's) is one of the scan's positions: the optimum is no worse.
  EXPECT_LE(json_number(r.out, "max_stress_fymax_mpa"), json_number(at_file.out, "max_stress_fymax_mpa") * (1 + 1e-9));
  const CliResult report = run_cli(band + " --optimize-position 0.5:3 -o span2.csv", dir);
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_NE(report.out.find("positions: "), std::string::npos) << report.out;
  EXPECT_NE(report.out.find("minimise the largest fymax stress"), std::string::npos) << report.out;
}

/// The JSON object after "key": in `json` (balanced braces; none: empty).
std::string span_json_object(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": {");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no object " << key << " in " << json;
    return {};
  }
  const std::size_t open = json.find('{', at);
  int depth = 0;
  for (std::size_t i = open; i < json.size(); ++i) {
    depth += json[i] == '{' ? 1 : json[i] == '}' ? -1 : 0;
    if (depth == 0) return json.substr(open, i - open + 1);
  }
  return {};
}

// --quiet: nothing on stdout and no progress on stderr; --json still prints its summary.
TEST(SpanCli, QuietPrintsNothingButTheJsonItIsAskedFor) {
  const auto dir = example_copy("span-quiet");
  const CliResult quiet = run_cli("span span.toml --frequencies 10,20 --no-dampers --quiet -o span.csv", dir);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.out, "");
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(read_csv(dir / "span.csv").rows.size(), 2u);
  const CliResult json = run_cli("span span.toml --frequencies 10,20 --no-dampers --quiet --json -o span.csv", dir);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(json.out.rfind("{\"points\": 2, \"converged\": 2, ", 0), 0u) << json.out;
  EXPECT_EQ(lines_of(json.out).size(), 1u) << json.out;
  EXPECT_EQ(json.err, "");
}

// The JSON's inputs restate the span as computed: the catalogue's Drake (26/7, EI_min
// 44.25 N m^2) at 20 % of its RTS, T = 0.2 RTS = (H/w) m g; CIGRE's wind, Lilien's k.
TEST(SpanCli, TheJsonRestatesTheInputsAsUsed) {
  const auto dir = scratch_directory("span-inputs-json");
  const CliResult r = run_cli("span '" + kExamples + "drake_300m.toml' --frequencies 10,20 --no-dampers --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string inputs = span_json_object(r.out, "inputs");
  const std::string conductor = span_json_object(inputs, "conductor");
  EXPECT_NE(conductor.find("\"name\": \"ACSR Drake\""), std::string::npos) << conductor;
  EXPECT_NE(conductor.find("\"source\": \"the catalogue's ACSR Drake\""), std::string::npos) << conductor;
  EXPECT_NE(conductor.find("\"stranding\": \"26/7"), std::string::npos) << conductor;
  EXPECT_NEAR(json_number(conductor, "ei_min_n_m2"), 44.25, 0.01);
  EXPECT_EQ(json_number(conductor, "aluminium_layers"), 2.0);
  const double rts = json_number(conductor, "rated_tensile_strength_n");
  const double mass = json_number(conductor, "mass_per_length_kg_m");
  EXPECT_NEAR(rts, 138.8e3, 0.1e3);
  EXPECT_EQ(json_number(inputs, "length_m"), 300.0);
  const std::string tension = span_json_object(inputs, "tension");
  const double t = json_number(tension, "tension_n");
  EXPECT_NEAR(json_number(tension, "fraction_of_rts"), 0.2, 1e-12);
  EXPECT_NEAR(t, 0.2 * rts, 1e-9 * t);
  EXPECT_NEAR(t, json_number(tension, "catenary_parameter_m") * mass * 9.80665, 1e-9 * t);
  EXPECT_EQ(t, json_number(r.out, "tension_n"));  // the summary's own
  const std::string wind = span_json_object(inputs, "wind");
  EXPECT_NE(wind.find("\"law\": \"cigre\""), std::string::npos) << wind;
  EXPECT_EQ(wind.find("turbulence"), std::string::npos) << wind;  // only foti has one
  EXPECT_EQ(json_number(wind, "strouhal"), 0.185);
  EXPECT_EQ(json_number(wind, "speed_max_m_s"), 7.0);
  const std::string self_damping = span_json_object(inputs, "self_damping");
  EXPECT_NE(self_damping.find("\"law\": \"noiseux-1991\""), std::string::npos) << self_damping;
  EXPECT_NE(self_damping.find("\"k_source\": \"Lilien's\""), std::string::npos) << self_damping;
  // Lilien's k, D[mm] / sqrt(m RTS[kN]).
  const double diameter = json_number(conductor, "diameter_m");
  EXPECT_NEAR(json_number(self_damping, "k"), 1e3 * diameter / std::sqrt(mass * rts / 1e3), 1e-9);
  const std::string fatigue = span_json_object(inputs, "fatigue");
  EXPECT_NE(fatigue.find("\"criterion\": \"safe-border-line\""), std::string::npos) << fatigue;
  EXPECT_NE(fatigue.find("\"criterion_description\": \"the CIGRE Safe Border Line at 5e+08 cycles\""),
            std::string::npos)
      << fatigue;
  EXPECT_EQ(json_number(fatigue, "endurance_limit_mpa"), json_number(r.out, "endurance_limit_mpa"));
}

/// The example Drake span (examples/drake_300m.toml) with D. Sauter's damper known by
/// the vendor's sheet (examples/vendor_sheet.csv) in `dir`, its [span] and [fatigue]
/// lines `tension` and `cycles` replaced by `tension_to` and `cycles_to`.
void write_drake_with_vendor_sheet(const std::filesystem::path& dir, const std::string& tension_to = "",
                                   const std::string& cycles_to = "") {
  std::string text = read_text(kExamples + "drake_300m.toml");
  text.replace(text.find("file = \"sauter2003.toml\""), 24, "impedance = \"vendor_sheet.csv\"");
  if (!tension_to.empty()) text.replace(text.find("tension_fraction = 0.2 "), 22, tension_to);
  if (!cycles_to.empty()) text.replace(text.find("cycles = 5e8"), 12, cycles_to);
  std::ofstream(dir / "span.toml") << text;
  std::filesystem::copy_file(kExamples + "vendor_sheet.csv", dir / "vendor_sheet.csv",
                             std::filesystem::copy_options::overwrite_existing);
}

// The microstrain criterion (the IEEE committee's 150 microstrain peak-to-peak,
// 0.5e-6 * 150 * 68.9 GPa = 5.17 MPa) judges the Poffenberger-Swart stress, the strain
// a recorder's Yb gives: the Drake span at 18 % RTS with the vendor's sheet, safe by
// the Safe Border Line (fymax 5.46 MPa, the band's top 7.96 MPa, against 8.73 MPa),
// bends its outer wires by 158.6 microstrain: unsafe by it.
TEST(SpanCli, TheMicrostrainCriterionJudgesThePoffenbergerSwartStrain) {
  const auto dir = scratch_directory("span-microstrain");
  write_drake_with_vendor_sheet(dir, "tension_fraction = 0.18");
  const CliResult sbl = run_cli("span span.toml --json -o span.csv", dir);
  ASSERT_EQ(sbl.exit_code, 0) << sbl.err;
  EXPECT_NE(sbl.out.find("\"criterion\": \"safe-border-line\", \"verdict\": \"safe\""), std::string::npos) << sbl.out;

  write_drake_with_vendor_sheet(dir, "tension_fraction = 0.18", "criterion = \"microstrain\"");
  const CliResult r = run_cli("span span.toml --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"criterion\": \"microstrain\", \"verdict\": \"unsafe\""), std::string::npos) << r.out;
  EXPECT_NEAR(json_number(r.out, "endurance_limit_mpa"), 0.5e-6 * 150.0 * 68.9e3, 1e-12);
  EXPECT_NEAR(json_number(r.out, "endurance_limit_pp_microstrain"), 150.0, 1e-9);
  EXPECT_NEAR(json_number(r.out, "max_bending_strain_pp_microstrain"), 158.6, 0.05);
  // The stress judged is the largest Poffenberger-Swart stress, not the fymax one.
  const Csv csv = read_csv(dir / "span.csv");
  const std::vector<double> ps = csv.column("stress_ps_mpa"), fymax = csv.column("stress_fymax_mpa");
  const double judged = json_number(r.out, "max_judged_stress_mpa");
  EXPECT_EQ(judged, *std::max_element(ps.begin(), ps.end()));
  EXPECT_LT(judged, json_number(r.out, "max_stress_fymax_mpa"));
  EXPECT_EQ(json_number(r.out, "max_stress_fymax_mpa"), *std::max_element(fymax.begin(), fymax.end()));
  EXPECT_NEAR(judged, 158.6e-6 / 2.0 * 68.9e3, 0.002);  // E_a eps / 2
  const std::string fatigue = span_json_object(span_json_object(r.out, "inputs"), "fatigue");
  EXPECT_NE(fatigue.find("\"criterion\": \"microstrain\", \"criterion_description\": \"150 microstrain peak-to-peak (the "
                         "IEEE committee's limit)\""),
            std::string::npos)
      << fatigue;
  const CliResult report = run_cli("span span.toml -o span.csv", dir);
  EXPECT_NE(report.out.find("criterion microstrain: 150 microstrain peak-to-peak (the IEEE committee's limit), 5.17 MPa "
                            "(150 microstrain peak-to-peak) against the largest bending strain from Yb: unsafe"),
            std::string::npos)
      << report.out;
}

// The wind's turbulence: the terrain's assumed intensity where wind_law_by_terrain
// asks for it, named as such; a foti law's own intensity "given".
TEST(SpanCli, TheJsonSaysWhereTheTurbulenceComesFrom) {
  const auto dir = example_copy("span-terrain-json");
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("tension_fraction = 0.15"), 23, "tension_fraction = 0.15\nterrain = 4\nwind_law_by_terrain = true");
  std::ofstream(dir / "terrain.toml") << text;
  const CliResult r = run_cli("span terrain.toml --frequencies 10,20 --no-dampers --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string wind = span_json_object(span_json_object(r.out, "inputs"), "wind");
  EXPECT_NE(wind.find("\"law\": \"foti\""), std::string::npos) << wind;
  EXPECT_NEAR(json_number(wind, "turbulence_intensity"), 1.0 / std::log(10.0 / 0.3), 1e-12);
  EXPECT_NE(wind.find("\"turbulence_source\": \"terrain category 4 (this program's assumed intensity)\""),
            std::string::npos)
      << wind;
  text.replace(text.find("law = \"cigre\""), 13, "law = \"foti\"\nturbulence_intensity = 0.05");
  std::ofstream(dir / "given.toml") << text;
  const CliResult given = run_cli("span given.toml --frequencies 10,20 --no-dampers --json -o span.csv", dir);
  ASSERT_EQ(given.exit_code, 0) << given.err;
  const std::string own = span_json_object(span_json_object(given.out, "inputs"), "wind");
  EXPECT_EQ(json_number(own, "turbulence_intensity"), 0.05);
  EXPECT_NE(own.find("\"turbulence_source\": \"given\""), std::string::npos) << own;
}

// The example Drake span with D. Sauter's damper known by the vendor's sheet instead:
// every stress within the 8.73 MPa limit, but the sheet's band reaches 8.98 MPa.
TEST(SpanCli, TheVendorSheetsBandAboveTheLimitMakesTheVerdictUncertain) {
  const auto dir = scratch_directory("span-uncertain");
  write_drake_with_vendor_sheet(dir);
  const CliResult r = run_cli("span span.toml --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"verdict\": \"uncertain\""), std::string::npos) << r.out;
  const double limit = json_number(r.out, "endurance_limit_mpa");
  const double stress = json_number(r.out, "max_judged_stress_mpa");
  const double high = json_number(r.out, "max_judged_stress_high_mpa");
  EXPECT_NEAR(limit, 8.73, 0.005);
  EXPECT_LT(stress, limit);
  EXPECT_GT(high, limit);
  EXPECT_NEAR(high, 8.98, 0.005);
  // The top is the largest of the CSV's band.
  double top = 0.0;
  for (const double v : read_csv(dir / "span.csv").column("stress_fymax_high_mpa")) top = std::max(top, v);
  EXPECT_NEAR(high, top, 1e-9 * top);
  const CliResult report = run_cli("span span.toml -o span.csv", dir);
  EXPECT_NE(report.out.find("against the largest fymax stress: uncertain"), std::string::npos) << report.out;
}

// The largest stress at the first or last frequency balanced may not be the span's
// largest: a warning says so. Undamped, the stress falls with the frequency.
TEST(SpanCli, TheLargestStressAtAnEdgeOfTheBandWarns) {
  const auto dir = example_copy("span-edge");
  const CliResult r = run_cli("span span.toml --frequencies 10,20,30 --no-dampers --quiet -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "warning: the largest stress lies at the low edge of the frequencies balanced (10 Hz, wind 1.68 m/s): "
                   "a larger one may lie beyond it ([wind] speed_min and speed_max bound the band)\n");
  const CliResult json = run_cli("span span.toml --frequencies 10,20,30 --no-dampers --json -o span.csv", dir);
  EXPECT_NE(json.out.find("\"warnings\": [\"the largest stress lies at the low edge"), std::string::npos) << json.out;
  // Two frequencies are no band to have an edge.
  const CliResult two = run_cli("span span.toml --frequencies 10,20 --no-dampers --quiet -o span.csv", dir);
  EXPECT_EQ(two.err, "");
}

/// Exit 2, one line on stderr containing `mention`, and no output file.
void expect_bad(const std::string& arguments, const std::string& mention) {
  const auto dir = example_copy("span-bad");
  const CliResult r = run_cli(arguments, dir);
  EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << arguments << "\n" << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << "\n" << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv")) << arguments;
}

TEST(SpanCli, BadOptionsExitTwoWithOneLineAndNoFile) {
  expect_bad("span span.toml --frequencies 20,10 -o out.csv", "frequencies[1] = 10");
  expect_bad("span span.toml --frequencies 10,,20 -o out.csv", "--frequencies");
  expect_bad("span span.toml --frequencies 10 --points 5 -o out.csv", "excludes");
  expect_bad("span span.toml --points 1 -o out.csv", "points = 1");
  expect_bad("span span.toml --damper-model linear -o out.csv", "linear");
  expect_bad("span span.toml --optimize-position 3:0.5 -o out.csv", "optimize_position = 3:0.5");
  expect_bad("span span.toml --optimize-position 2 -o out.csv", "--optimize-position = '2': expected AMIN:AMAX");
  expect_bad("span span.toml --optimize-position 0.5:x -o out.csv", "--optimize-position AMAX = 'x'");
  expect_bad("span span.toml --optimize-position 0.5:3 --no-dampers -o out.csv", "no_dampers");
  expect_bad("span span.toml --threads 0 -o out.csv", "threads = 0");
  expect_bad("span span.toml", "--output");
  expect_bad("span missing.toml -o out.csv", "missing.toml: no such file");
}

TEST(SpanCli, BadSpanFilesExitTwoNamingFileLineAndValue) {
  const auto dir = example_copy("span-bad-file");
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("length = 400"), 12, "length = -400");
  std::ofstream(dir / "bad.toml") << text;
  const CliResult r = run_cli("span bad.toml -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("bad.toml:19: span.length = -400"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

TEST(SpanCli, InputsAreNeverOverwritten) {
  for (const std::string output : {"span.toml", "sauter2003.toml"}) {
    const auto dir = example_copy("span-inputs");
    const std::string before = read_text(dir / output);
    const CliResult r = run_cli("span span.toml --points 4 -o " + output, dir);
    EXPECT_EQ(r.exit_code, 2) << output;
    EXPECT_EQ(r.stderr_lines(), 1) << r.err;
    EXPECT_EQ(read_text(dir / output), before) << output;
  }
}

}  // namespace
}  // namespace stockbridge::testing
