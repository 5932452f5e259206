// A damper whose messengers follow the Bouc-Wen law (slenderpy's, MODEL.md section
// 13) through the program as users run it: impedance, modes (stick: EI_max, slip:
// EI_min), a span with it at both ends, a design study of its numbers, the
// identifications (local from a loop, impedance from curves), and a cable
// table with a key of the other law (exit 2, one line naming file and line, nothing
// written).

#include <cmath>
#include <cstdlib>
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

const std::string kBoucWenExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";
const std::string kSlenderpy = kBoucWenExamples + "slenderpy_damper.toml";

/// A damper file of two identical arms with constant Bouc-Wen numbers.
std::string uniform_bouc_wen_damper(double ei_max, int sections = 30) {
  std::ostringstream text;
  text << "[clamp]\nmass = 0.7\n";
  for (const char* name : {"left", "right"}) {
    text << "[[arm]]\nname = \"" << name << "\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
         << "[arm.cable]\nlaw = \"bouc-wen\"\nlength = 0.1875\nsections = " << sections << "\nei_min = 2.5\nei_max = " << ei_max
         << "\nchi0 = 0.03\n";
  }
  return text.str();
}

TEST(BoucWenCli, ImpedanceOfSlenderpysDamperConvergesWithItsEnergyBalance) {
  const auto dir = scratch_directory("bouc-wen-impedance");
  const CliResult r = run_cli("impedance '" + kSlenderpy + "' --velocity 0.2 --frequencies 10,25,60 --json -o z.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_number(r.out, "converged"), 3.0) << r.out;
  EXPECT_LT(json_number(r.out, "max_energy_error"), 1e-4) << r.out;
  const Csv csv = read_csv(dir / "z.csv");
  for (const double re : csv.column("re_z_n_s_m")) EXPECT_GT(re, 0.0);  // the law dissipates
}

// The modes take EI_max sticking and EI_min slipping: each arm's stick modes lie
// above its slip modes, near MODEL.md section 13's 25 / 78 Hz and 8 / 25 Hz.
TEST(BoucWenCli, ModesStickOnEiMaxAndSlipOnEiMin) {
  const auto dir = scratch_directory("bouc-wen-modes");
  const CliResult r = run_cli("modes '" + kSlenderpy + "' --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t at = r.out.find("\"stick_hz\": [");
  ASSERT_NE(at, std::string::npos) << r.out;
  double stick[2], slip[2];
  std::sscanf(r.out.c_str() + at, "\"stick_hz\": [%lf, %lf], \"slip_hz\": [%lf, %lf]", &stick[0], &stick[1], &slip[0],
              &slip[1]);
  EXPECT_NEAR(stick[0], 25.0, 2.5) << r.out;
  EXPECT_NEAR(stick[1], 78.0, 7.8) << r.out;
  EXPECT_NEAR(slip[0], 8.0, 0.8) << r.out;
  EXPECT_NEAR(slip[1], 25.0, 2.5) << r.out;
}

TEST(BoucWenCli, ASpanWithTheDamperAtBothEnds) {
  const auto dir = scratch_directory("bouc-wen-span");
  std::string span = read_text(kBoucWenExamples + "aster570_400m.toml");
  span.replace(span.find("file = \"sauter2003.toml\""), 24, "file = \"" + kSlenderpy + "\"");
  std::ofstream(dir / "span.toml") << span;
  const int points = 3;
  const CliResult r = run_cli("span span.toml --points " + std::to_string(points) + " --json -o span.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv csv = read_csv(dir / "span.csv");
  ASSERT_EQ(csv.rows.size(), static_cast<std::size_t>(points));
  const auto converged = csv.column("converged"), amplitude = csv.column("amplitude_m"),
             undamped = csv.column("undamped_amplitude_m"), identity = csv.column("energy_identity_error");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_EQ(converged[i], 1.0) << "row " << i;
    EXPECT_LE(amplitude[i], undamped[i] * (1 + 1e-9)) << "row " << i;
    EXPECT_LT(std::abs(identity[i]), 1e-6) << "row " << i;
  }
  EXPECT_GT(json_number(r.out, "max_stress_fymax_mpa"), 0.0) << r.out;
}

// The law's numbers are design variables: a study of arm.left.cable.ei_max (the
// right arm tied to it) evaluates every candidate and writes a best damper whose
// cable is a Bouc-Wen table with the chosen ei_max.
TEST(BoucWenCli, ADesignStudyOfItsNumbers) {
  const auto dir = scratch_directory("bouc-wen-design");
  std::ofstream(dir / "damper.toml") << uniform_bouc_wen_damper(25.0);
  std::ofstream(dir / "study.toml")
      << "damper = \"damper.toml\"\nspans = [\"" << kBoucWenExamples
      << "aster570_400m.toml\"]\nsamples = 1\npolish = 0\npoints = 3\nseed = 2\n"
      << "[[variable]]\nname = \"arm.left.cable.ei_max\"\nmin = 15.0\nmax = 40.0\n"
      << "[[tie]]\nname = \"arm.right.cable.ei_max\"\nequals = \"arm.left.cable.ei_max\"\n"
      << "[constraints]\ntotal_mass_max = 4.0\n";
  const CliResult r = run_cli("design study.toml --json -o designs.csv --best best.toml", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Csv csv = read_csv(dir / "designs.csv");
  const auto ei_max = csv.column("arm.left.cable.ei_max"), converged = csv.column("converged");
  ASSERT_GE(csv.rows.size(), 2u);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_EQ(converged[i], 1.0) << "row " << i;
    EXPECT_GE(ei_max[i], 15.0);
    EXPECT_LE(ei_max[i], 40.0);
  }
  const std::string best = read_text(dir / "best.toml");
  EXPECT_NE(best.find("law = \"bouc-wen\""), std::string::npos) << best;
  const double chosen = json_number_after(r.out, "rounded", "arm.left.cable.ei_max");
  char line[64];
  std::snprintf(line, sizeof line, "ei_max = %.3g   # N m^2", chosen);
  EXPECT_NE(best.find(line), std::string::npos) << line << "\n" << best;
}

TEST(BoucWenCli, AKeyOfTheOtherLawIsNamedWithItsLine) {
  const auto dir = scratch_directory("bouc-wen-bad");
  std::string text = uniform_bouc_wen_damper(25.0);
  text.replace(text.find("ei_min = 2.5"), 12, "ei = 2.5");
  std::ofstream(dir / "damper.toml") << text;
  const CliResult r = run_cli("impedance damper.toml --velocity 0.2 --frequencies 20 -o z.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "stockbridge: damper.toml:12: arm[0].cable.ei: is a number of the Masing and Iwan laws: law = \"bouc-wen\" takes "
            "ei_min, ei_max and chi0\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "z.csv"));
  text = uniform_bouc_wen_damper(25.0);
  text.replace(text.find("\"bouc-wen\""), 10, "\"boucwen\"");
  std::ofstream(dir / "damper.toml") << text;
  const CliResult bad_law = run_cli("impedance damper.toml --velocity 0.2 --frequencies 20 -o z.csv", dir);
  EXPECT_EQ(bad_law.exit_code, 2);
  EXPECT_NE(bad_law.err.find("damper.toml:9: arm[0].cable.law: \"boucwen\" is not a section law: expected \"masing\", "
                             "\"bouc-wen\" or \"iwan\""),
            std::string::npos)
      << bad_law.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "z.csv"));
}

// identify local --law bouc-wen on the loop of the loop command gives the law's
// numbers back as the keys of a cable table, which the cycle command then runs.
TEST(BoucWenCli, IdentifyLocalGivesTheLoopsNumbersAsCableKeys) {
  const auto dir = scratch_directory("bouc-wen-identify");
  ASSERT_EQ(run_cli("loop --law bouc-wen --ei-min 2.5 --ei-max 25 --chi0 0.03 --amplitude 0.1 --cycles 3 -o loop.csv", dir)
                .exit_code,
            0);
  const CliResult r = run_cli("identify local --law bouc-wen --input loop.csv --json -o keys.toml", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{\"law\": \"bouc-wen\", \"ei_min\": ", 0), 0u) << r.out;
  EXPECT_NEAR(json_number(r.out, "ei_min"), 2.5, 1e-6);
  EXPECT_NEAR(json_number(r.out, "ei_max"), 25.0, 1e-5);
  EXPECT_NEAR(json_number(r.out, "chi0"), 0.03, 1e-8);
  std::ofstream(dir / "cable.toml") << "[cable]\nlength = 0.1875\nsections = 40\n" << read_text(dir / "keys.toml");
  const CliResult cycle = run_cli("cycle cable.toml --experiment a --amplitude 0.005 -o cycle.csv", dir);
  EXPECT_EQ(cycle.exit_code, 0) << cycle.err;
  const CliResult two = run_cli("identify local --law bouc-wen --elements 2 --input loop.csv", dir);
  EXPECT_EQ(two.exit_code, 2);
  EXPECT_NE(two.err.find("elements = 2: Jenkin elements belong to the Masing law"), std::string::npos) << two.err;
}

// identify impedance from a Bouc-Wen start fits ei_min, ei_max and chi0 to the
// curves `impedance` writes of a Bouc-Wen damper; the cable file it writes has the
// law and reproduces the curves.
TEST(BoucWenCli, IdentifyImpedanceFitsTheLawToCurvesAndItsCableFileReproducesThem) {
  const auto dir = scratch_directory("bouc-wen-identify-impedance");
  std::ofstream(dir / "truth.toml") << uniform_bouc_wen_damper(25.0, 12);
  std::ofstream(dir / "start.toml") << uniform_bouc_wen_damper(24.0, 12);
  const std::string curves = " --velocity 0.05,0.2 --fmin 4 --fmax 60 --points 4";
  ASSERT_EQ(run_cli("impedance truth.toml" + curves + " -o measured.csv", dir).exit_code, 0);
  const CliResult r = run_cli("identify impedance --damper start.toml --input measured.csv --json -o cable.toml", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{\"law\": \"bouc-wen\", \"ei_min\": ", 0), 0u) << r.out;
  EXPECT_NEAR(json_number(r.out, "ei_min"), 2.5, 1e-4) << r.out;
  EXPECT_NEAR(json_number(r.out, "ei_max"), 25.0, 1e-3) << r.out;
  EXPECT_NEAR(json_number(r.out, "chi0"), 0.03, 1e-6) << r.out;
  EXPECT_NE(r.err.find("identify impedance: ei_min = "), std::string::npos) << r.err;
  EXPECT_NE(read_text(dir / "cable.toml").find("law = \"bouc-wen\""), std::string::npos);

  std::string reused = uniform_bouc_wen_damper(24.0, 12);
  for (std::size_t at = reused.find("law = "); at != std::string::npos; at = reused.find("law = ", at)) {
    const std::size_t end = reused.find("chi0 = 0.03\n", at) + 12;
    reused.replace(at, end - at, "file = \"cable.toml\"\n");
  }
  std::ofstream(dir / "reused.toml") << reused;
  ASSERT_EQ(run_cli("impedance reused.toml" + curves + " -o again.csv", dir).exit_code, 0);
  const Csv measured = read_csv(dir / "measured.csv"), again = read_csv(dir / "again.csv");
  for (const char* column : {"re_z_n_s_m", "im_z_n_s_m"}) {
    for (std::size_t i = 0; i < measured.column(column).size(); ++i) {
      EXPECT_NEAR(again.column(column)[i], measured.column(column)[i], 1e-4 * std::abs(measured.column(column)[i]) + 1e-6)
          << column << " " << i;
    }
  }

  const CliResult two = run_cli("identify impedance --damper start.toml --input measured.csv --elements 2 -o two.toml", dir);
  EXPECT_EQ(two.exit_code, 2);
  EXPECT_NE(two.err.find("--elements = 2: Jenkin elements belong to the Masing law"), std::string::npos) << two.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "two.toml"));
}

}  // namespace
}  // namespace stockbridge::testing
