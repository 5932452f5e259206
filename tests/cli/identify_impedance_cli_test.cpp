// `stockbridge identify impedance` end to end: a curve `impedance` writes (the
// program's own CSV, its extra columns ignored) identified back to its cable, the
// cable file reused by a damper file to reproduce the curve; the other column
// forms; the shipped example; bad measurements and dampers.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"
#include "support/temp_file.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::testing {
namespace {

/// A damper of two identical arms of the verification damper's on 12-section
/// cables with the given cable keys (or a reference to a cable file).
std::string damper_toml(const std::string& cable_keys) {
  std::string text = "[clamp]\nmass = 0.7\n";
  for (const char* name : {"left", "right"}) {
    text += std::string("[[arm]]\nname = \"") + name +
            "\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n[arm.cable]\nlength = 0.1875\nsections = 12\n" +
            cable_keys;
  }
  return text;
}

const std::string kTruth = "ei = 2.8\njenkin = [ { c = 20.0, h = 0.7 } ]\n";
const std::string kGuess = "ei = 3.1\njenkin = [ { c = 17.0, h = 0.8 } ]\n";

/// Rows of a CSV as named columns.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<double> column(const std::string& name) const {
    const std::size_t c = static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    std::vector<double> out;
    for (const std::vector<double>& row : rows) out.push_back(c < row.size() ? row[c] : NAN);
    return out;
  }
};

CsvTable read_csv_table(const std::filesystem::path& path) {
  std::istringstream in(read_text(path));
  std::string line, cell;
  CsvTable csv;
  std::getline(in, line);
  for (std::istringstream h(line); std::getline(h, cell, ',');) csv.header.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::istringstream r(line); std::getline(r, cell, ',');) row.push_back(cell.empty() ? NAN : std::stod(cell));
    csv.rows.push_back(row);
  }
  return csv;
}

/// Frequencies per velocity of the measured curves (fewer under the sanitizers).
int curve_points() { return scaled(8, 4); }

/// `impedance`'s command line for the curves at 0.05 and 0.2 m/s over 4-60 Hz.
std::string two_velocity_curves(const std::string& damper_file, const std::string& output) {
  return "impedance " + damper_file + " --velocity 0.05,0.2 --fmin 4 --fmax 60 --points " + std::to_string(curve_points()) +
         " -o " + output;
}

/// The truth's curve at two velocities, as `impedance` writes it.
std::filesystem::path measured_curve(const std::filesystem::path& dir) {
  write_temp_file(dir, "truth.toml", damper_toml(kTruth));
  const CliResult r = run_cli(two_velocity_curves("truth.toml", "measured.csv"), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return dir / "measured.csv";
}

TEST(IdentifyImpedanceCli, RecoversTheCableOfACurveAndItsCableFileReproducesTheCurve) {
  const auto dir = scratch_directory("identify-impedance");
  measured_curve(dir);
  write_temp_file(dir, "start.toml", damper_toml(kGuess));
  const CliResult r =
      run_cli("identify impedance --damper start.toml --input measured.csv --json -o cable.toml --fitted z_fit.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(json_number(r.out, "ei"), 2.8, 1e-4) << r.out;
  EXPECT_NEAR(json_number(r.out, "c"), 20.0, 1e-3) << r.out;
  EXPECT_NEAR(json_number(r.out, "h"), 0.7, 1e-4) << r.out;
  EXPECT_LT(json_number(r.out, "rms_relative_error"), 1e-5) << r.out;
  EXPECT_NE(r.out.find("\"undetermined\": []"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"standard_error\": "), std::string::npos) << r.out;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;  // the summary line, no warning
  EXPECT_NE(r.err.find("identify impedance: ei = 2.8"), std::string::npos) << r.err;

  // The fitted CSV: the measured points and the model's Z there.
  const CsvTable fitted = read_csv_table(dir / "z_fit.csv");
  const CsvTable measured = read_csv_table(dir / "measured.csv");
  ASSERT_EQ(fitted.rows.size(), 2u * static_cast<std::size_t>(curve_points()));
  const std::vector<double> re = fitted.column("re_z_n_s_m"), model_re = fitted.column("model_re_z_n_s_m"),
                            im = fitted.column("im_z_n_s_m"), model_im = fitted.column("model_im_z_n_s_m");
  for (std::size_t i = 0; i < re.size(); ++i) {
    EXPECT_EQ(re[i], measured.column("re_z_n_s_m")[i]);
    EXPECT_LT(std::abs(std::complex(model_re[i] - re[i], model_im[i] - im[i])), 1e-4 * std::hypot(re[i], im[i])) << i;
  }

  // A damper file reuses the identified cable; `impedance` reproduces the curve.
  write_temp_file(dir, "reused.toml", damper_toml("file = \"cable.toml\"\n"));
  ASSERT_EQ(run_cli(two_velocity_curves("reused.toml", "again.csv"), dir).exit_code, 0);
  const CsvTable again = read_csv_table(dir / "again.csv");
  for (std::size_t i = 0; i < re.size(); ++i) {
    const std::complex<double> z(measured.column("re_z_n_s_m")[i], measured.column("im_z_n_s_m")[i]);
    const std::complex<double> z_again(again.column("re_z_n_s_m")[i], again.column("im_z_n_s_m")[i]);
    EXPECT_LT(std::abs(z_again - z), 1e-4 * std::abs(z)) << i;
  }
}

TEST(IdentifyImpedanceCli, AbsAndPhaseWithDisplacementGiveTheSameCable) {
  const auto dir = scratch_directory("identify-impedance-polar");
  const CsvTable measured = read_csv_table(measured_curve(dir));
  // Only the velocity 0.2 curve's points, as a constant-displacement measurement
  // would list them: displacement_m and |Z|, phase.
  std::string polar = "frequency_hz,displacement_m,abs_z_n_s_m,phase_deg\n", cartesian = "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n";
  for (const std::vector<double>& row : measured.rows) {
    auto at = [&](const char* name) { return row[static_cast<std::size_t>(
                                           std::find(measured.header.begin(), measured.header.end(), name) - measured.header.begin())]; };
    if (at("velocity_m_s") != 0.2) continue;
    char line[256];
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", at("frequency_hz"), at("displacement_m"), at("abs_z_n_s_m"),
                  at("phase_deg"));
    polar += line;
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", at("frequency_hz"), at("velocity_m_s"), at("re_z_n_s_m"),
                  at("im_z_n_s_m"));
    cartesian += line;
  }
  write_temp_file(dir, "polar.csv", polar);
  write_temp_file(dir, "cartesian.csv", cartesian);
  write_temp_file(dir, "start.toml", damper_toml(kGuess));
  const CliResult a = run_cli("identify impedance --damper start.toml --input polar.csv --json", dir);
  const CliResult b = run_cli("identify impedance --damper start.toml --input cartesian.csv --json", dir);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  for (const char* key : {"ei", "c", "h"}) {
    EXPECT_NEAR(json_number(a.out, key) / json_number(b.out, key), 1.0, 1e-4) << key << "\n" << a.out << "\n" << b.out;
  }
}

TEST(IdentifyImpedanceCli, TheShippedExampleRecoversItsCableWithinOnePercent) {
  if (short_tests()) GTEST_SKIP() << "the whole example fit on 40 sections: the Release build runs it";
  // examples/measured_impedance.csv: the verification damper (ei 2.8, c 20, h 0.7)
  // at 0.05 and 0.2 m/s with 1 % scatter; examples/damper_to_identify.toml guesses.
  const auto dir = scratch_directory("identify-impedance-example");
  const std::string examples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";
  const CliResult r = run_cli("identify impedance --damper " + examples + "damper_to_identify.toml --input " + examples +
                                  "measured_impedance.csv --json -o cable.toml",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(json_number(r.out, "ei"), 2.8, 0.028) << r.out;
  EXPECT_NEAR(json_number(r.out, "c"), 20.0, 0.2) << r.out;
  EXPECT_NEAR(json_number(r.out, "h"), 0.7, 0.007) << r.out;
  EXPECT_NEAR(json_number(r.out, "rms_relative_error"), 0.01, 0.003) << r.out;
  EXPECT_NE(read_text(dir / "cable.toml").find("length = 0.1875"), std::string::npos);
}

TEST(IdentifyImpedanceCli, ACurveBelowSlipSaysHIsNotDeterminedAndStillWritesTheCable) {
  const auto dir = scratch_directory("identify-impedance-stick");
  write_temp_file(dir, "truth.toml", damper_toml(kTruth));
  ASSERT_EQ(run_cli("impedance truth.toml --velocity 0.0002 --fmin 4 --fmax 60 --points 10 -o measured.csv", dir).exit_code, 0);
  write_temp_file(dir, "start.toml", damper_toml(kGuess));
  // 0.2 mm/s lies below a shaker test's velocities: taken as given where the user says so.
  const CliResult r =
      run_cli("identify impedance --damper start.toml --input measured.csv --json -o cable.toml --allow-unusual", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"undetermined\": [\"ei\", \"jenkin[0].c\", \"jenkin[0].h\"]"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: the fitted cable never slips"), std::string::npos) << r.err;
  EXPECT_NE(read_text(dir / "cable.toml").find("jenkin[0].h = "), std::string::npos);  // the comment says so
  EXPECT_NE(read_text(dir / "cable.toml").find("NOT determined"), std::string::npos);
}

TEST(IdentifyImpedanceCli, FreeFitsADampersNumbersAndTheFittedDamperFileHoldsThem) {
  const auto dir = scratch_directory("identify-impedance-free");
  measured_curve(dir);
  // The left arm's mass 12 % low in the start: fitted with the cable.
  std::string start = damper_toml(kGuess);
  start.replace(start.find("mass = 0.856"), 12, "mass = 0.75");
  write_temp_file(dir, "start.toml", start);
  const CliResult r = run_cli(
      "identify impedance --damper start.toml --input measured.csv --free arm.left.mass --json --fitted-damper fitted.toml",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(json_number(r.out, "arm.left.mass"), 0.856, 1e-5) << r.out;  // the "geometry" object
  EXPECT_NE(r.out.find("\"name\": \"arm.left.mass\", \"unit\": \"kg\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"geometry\": true"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"poor_fit\": false"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("arm.left.mass = 0.856"), std::string::npos) << r.err;
  // The fitted damper file: the fitted mass and cable, read back by the damper reader.
  const std::string fitted = read_text(dir / "fitted.toml");
  EXPECT_NE(fitted.find("Fitted with the cables: arm.left.mass."), std::string::npos) << fitted;
  EXPECT_NE(fitted.find("mass = 0.85"), std::string::npos) << fitted;
  EXPECT_EQ(fitted.find("mass = 0.75"), std::string::npos) << fitted;
  const CliResult again = run_cli("impedance fitted.toml --velocity 0.2 --frequencies 10 -o z.csv --quiet", dir);
  EXPECT_EQ(again.exit_code, 0) << again.err;
}

TEST(IdentifyImpedanceCli, APoorFitWritesItsFilesWarnsWithTheRmsAndTheLimitAndExitsThree) {
  // The measured curve with the sign of Im Z turned: no damper has it.
  const auto dir = scratch_directory("identify-impedance-poor");
  const CsvTable measured = read_csv_table(measured_curve(dir));
  std::string turned = "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n";
  for (const std::vector<double>& row : measured.rows) {
    auto at = [&](const char* name) {
      return row[static_cast<std::size_t>(std::find(measured.header.begin(), measured.header.end(), name) - measured.header.begin())];
    };
    char line[256];
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", at("frequency_hz"), at("velocity_m_s"), at("re_z_n_s_m"),
                  -at("im_z_n_s_m"));
    turned += line;
  }
  write_temp_file(dir, "turned.csv", turned);
  write_temp_file(dir, "start.toml", damper_toml(kGuess));
  const CliResult r = run_cli(
      "identify impedance --damper start.toml --input turned.csv --json -o cable.toml --fitted fit.csv --fitted-damper d.toml", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("warning: the fit's RMS relative error of Z "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("% is large (above 10 %)"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("\"poor_fit\": true"), std::string::npos) << r.out;
  EXPECT_EQ(json_number(r.out, "rms_limit"), 0.1) << r.out;
  EXPECT_GT(json_number(r.out, "rms_relative_error"), 0.1) << r.out;
  for (const char* file : {"cable.toml", "fit.csv", "d.toml"}) EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  EXPECT_NE(read_text(dir / "d.toml").find("a poor fit"), std::string::npos);
  // A limit above the error: the same fit is no longer poor, but it still exits 3:
  // an RMS error of over 100 % is a lack of fit at any scatter a measurement may state.
  const CliResult lenient = run_cli("identify impedance --damper start.toml --input turned.csv --rms-limit 5", dir);
  EXPECT_EQ(lenient.exit_code, 3) << lenient.err;
  EXPECT_EQ(lenient.err.find("is large"), std::string::npos) << lenient.err;
  EXPECT_NE(lenient.err.find("warning: lack of fit: "), std::string::npos) << lenient.err;
}

TEST(IdentifyImpedanceCli, AnArmInertiaOffIsALackOfFitThatExitsThreeNamingItUnlessTheStatedScatterCoversIt) {
  // The curves of the truth (two identical arms); the start's left arm 19 % too
  // heavy in rotation, which the cable alone cannot make up for.
  const auto dir = scratch_directory("identify-impedance-lack-of-fit");
  measured_curve(dir);
  std::string start = damper_toml(kGuess);
  start.replace(start.find("inertia = 0.001814"), 18, "inertia = 0.002159");
  write_temp_file(dir, "start.toml", start);
  const CliResult r = run_cli("identify impedance --damper start.toml --input measured.csv --json --fitted-damper d.toml", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("warning: lack of fit: the RMS relative error of Z "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("times the scatter of measured.csv (1 %, assumed"), std::string::npos) << r.err;
  // The suspects' line names the inertia among the three that explain most (on these
  // 16 points of two identical arms a cable length explains about as much: the
  // docs' vendor-sheet case, three velocities of two different arms, ranks it first).
  const std::size_t suspects = r.err.find("warning: fixed numbers of the damper that may be wrong, by the share of the "
                                          "misfit freeing each would remove: ");
  ASSERT_NE(suspects, std::string::npos) << r.err;
  const std::string suspects_line = r.err.substr(suspects, r.err.find('\n', suspects) - suspects);
  EXPECT_NE(suspects_line.find("arm.left.inertia "), std::string::npos) << suspects_line;
  EXPECT_NE(r.err.find("(lack of fit, p "), std::string::npos) << r.err;  // the summary line
  EXPECT_NE(r.out.find("\"lack_of_fit\": {\"scatter\": 0.01, \"scatter_assumed\": true, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"significant\": true"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{\"name\": \"arm.left.inertia\", \"unit\": \"kg m^2\", \"value\": 0.002159, \"misfit_reduction\": "),
            std::string::npos)
      << r.out;
  EXPECT_GT(json_number(r.out, "misfit_reduction"), 0.5) << r.out;  // the first suspect's
  EXPECT_NE(r.out.find("\"confounded_by\": \"arm."), std::string::npos) << r.out;
  EXPECT_NE(read_text(dir / "d.toml").find("LACK OF FIT"), std::string::npos);
  EXPECT_LT(json_number(r.out, "p_value"), 1e-6) << r.out;
  // A sheet whose stated scatter is above the error: no lack of fit, exit 0.
  const double rms = json_number(r.out, "rms_relative_error");
  const CliResult stated = run_cli("identify impedance --damper start.toml --input measured.csv --json --scatter " +
                                       std::to_string(2.0 * rms),
                                   dir);
  EXPECT_EQ(stated.exit_code, 0) << stated.err;
  EXPECT_EQ(stated.err.find("lack of fit"), std::string::npos) << stated.err;
  EXPECT_NE(stated.out.find("\"scatter_assumed\": false"), std::string::npos) << stated.out;
  EXPECT_NE(stated.out.find("\"significant\": false"), std::string::npos) << stated.out;
  EXPECT_NE(stated.out.find("\"suspects\": []"), std::string::npos) << stated.out;
  EXPECT_NEAR(json_number(stated.out, "ratio"), 0.5, 1e-3) << stated.out;
  // A scatter that is no fraction: exit 2, one line naming the option.
  const CliResult bad = run_cli("identify impedance --damper start.toml --input measured.csv --scatter 1", dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_EQ(bad.stderr_lines(), 1) << bad.err;
  EXPECT_NE(bad.err.find("scatter = 1: expected a fraction of |Z| > 0 and < 1 (0.01 for 1 %)"), std::string::npos) << bad.err;
}

// A sheet in mm/s is refused at its first row, naming the column and the slip;
// with --allow-unusual it is taken as given with a warning (and its radians warned of).
TEST(IdentifyImpedanceCli, AMeasurementInMmPerSecondIsRefusedNamingLineColumnAndSlip) {
  const auto dir = scratch_directory("identify-impedance-units");
  const CsvTable measured = read_csv_table(measured_curve(dir));
  std::string slipped = "frequency_hz,velocity_m_s,abs_z_n_s_m,phase_deg\n";
  for (const std::vector<double>& row : measured.rows) {
    auto at = [&](const char* name) {
      return row[static_cast<std::size_t>(std::find(measured.header.begin(), measured.header.end(), name) - measured.header.begin())];
    };
    char line[256];
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", at("frequency_hz"), 1000.0 * at("velocity_m_s"),
                  at("abs_z_n_s_m"), at("phase_deg") * 3.141592653589793 / 180.0);
    slipped += line;
  }
  write_temp_file(dir, "slipped.csv", slipped);
  write_temp_file(dir, "start.toml", damper_toml(kGuess));
  const CliResult refused = run_cli("identify impedance --damper start.toml --input slipped.csv --json", dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "stockbridge: slipped.csv:2: column 'velocity_m_s' = 50: outside the typical 0.001 to 2 m/s of "
                         "the clamp velocity amplitude (in mm/s? 50 mm/s = 0.05 m/s); a measured sheet's values lie "
                         "within it (--allow-unusual takes it as given)\n");
  EXPECT_TRUE(refused.out.empty()) << refused.out;
  const CliResult r = run_cli("identify impedance --damper start.toml --input slipped.csv --json --allow-unusual", dir);
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.err;
  EXPECT_NE(r.err.find("warning: slipped.csv:2: column 'velocity_m_s' = 50: outside the typical 0.001 to 2 m/s of the "
                       "clamp velocity amplitude (in mm/s? 50 mm/s = 0.05 m/s)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("phase_deg looks like radians"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("column 'velocity_m_s' = 50: outside"), std::string::npos) << r.out;  // the JSON's warnings too
}

struct BadFit {
  const char* name;
  const char* damper;    ///< the damper file's text ("" for the valid start)
  const char* measured;  ///< the measured file's text ("" for a valid curve)
  const char* must_mention;
  const char* options = "";  ///< added to the command
};

class IdentifyImpedanceCliRejects : public ::testing::TestWithParam<BadFit> {};

TEST_P(IdentifyImpedanceCliRejects, WithOneLineExitTwoAndNoFile) {
  const BadFit& bad = GetParam();
  const auto dir = scratch_directory(std::string("identify-impedance-bad-") + bad.name);
  write_temp_file(dir, "start.toml", *bad.damper ? std::string(bad.damper) : damper_toml(kGuess));
  write_temp_file(dir, "z.csv", *bad.measured ? std::string(bad.measured)
                                              : "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,5,80\n20,0.05,12,150\n");
  const CliResult r =
      run_cli(std::string("identify impedance --damper start.toml --input z.csv -o out.toml --fitted fit.csv ") + bad.options, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find(bad.must_mention), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.toml"));
  EXPECT_FALSE(std::filesystem::exists(dir / "fit.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    BadInputs, IdentifyImpedanceCliRejects,
    ::testing::Values(
        BadFit{"missing_column", "", "frequency_hz,re_z_n_s_m,im_z_n_s_m\n10,5,80\n20,12,150\n",
               "z.csv: missing column 'velocity_m_s' (or 'displacement_m')"},
        BadFit{"frequency_zero", "", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,5,80\n0,0.05,12,150\n",
               "z.csv:3: column 'frequency_hz' = 0: expected > 0"},
        BadFit{"velocity_negative", "", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,-0.05,5,80\n20,0.05,12,150\n",
               "z.csv:2: column 'velocity_m_s' = -0.05: expected > 0"},
        BadFit{"nan", "", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,NaN,80\n20,0.05,12,150\n",
               "z.csv:2: column 're_z_n_s_m' = NaN: expected a finite number"},
        BadFit{"profile_start",
               "[clamp]\nmass = 0.7\n[[arm]]\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n[arm.cable]\nlength = 0.1875\nsections = 12\n"
               "ei = { s = [0.0, 0.1], value = [2.8, 3.0] }\njenkin = [ { c = 20.0, h = 0.7 } ]\n",
               "", "start.toml: arm[0].cable.ei: a profile along the cable"},
        BadFit{"too_few_points", "", "frequency_hz,velocity_m_s,re_z_n_s_m,im_z_n_s_m\n10,0.05,5,80\n20,0.05,12,150\n",
               "z.csv: 2 points for 5 parameters", "--elements 2"},
        BadFit{"free_unknown_arm", "", "", "--free = arm.middle.mass: no arm is named 'middle' (the arms: left, right",
               "--free arm.left.mass,arm.middle.mass"},
        BadFit{"free_cable_parameter", "", "", "--free = arm[1].cable.jenkin[0].h: a cable parameter",
               "--free arm[1].cable.jenkin[0].h"},
        BadFit{"rms_limit_zero", "", "", "rms_limit = 0: expected a finite fraction > 0", "--rms-limit 0"}),
    [](const ::testing::TestParamInfo<BadFit>& info) { return info.param.name; });

}  // namespace
}  // namespace stockbridge::testing
