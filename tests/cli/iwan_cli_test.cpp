// Segalman's four-parameter Iwan law (MODEL.md section 17) through the program as
// users run it: loop against the closed-form dissipation, a cycle of the example
// cable, the impedance of a damper of Iwan cables by harmonic balance, collocation,
// time integration and shooting, the local identification of its own loop, and bad
// input (exit 2, one line naming the key).

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/csv_table.hpp"

namespace stockbridge::testing {
namespace {

const std::string kIwanCable = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/cable_iwan.toml";

/// A damper file of two identical arms of Iwan cables.
std::string iwan_damper(int sections = 24) {
  std::ostringstream text;
  text << "[clamp]\nmass = 0.7\n";
  for (const char* name : {"left", "right"}) {
    text << "[[arm]]\nname = \"" << name << "\"\nmass = 0.856\ninertia = 0.001814\noffset = 0.0325\n"
         << "[arm.cable]\nlaw = \"iwan\"\nlength = 0.1875\nsections = " << sections
         << "\nei = 2.8\nslip_moment = 0.7\ntangent_stiffness = 20.0\nexponent = -0.5\nbeta = 0.2\n";
  }
  return text.str();
}

TEST(IwanCli, ALoopDissipatesTheClosedForm) {
  const auto dir = scratch_directory("iwan-loop");
  const CliResult r = run_cli(
      "loop --law iwan --ei 2.8 --slip-moment 0.7 --tangent-stiffness 20 --exponent -0.5 --beta 0.2 --amplitude 0.05 "
      "--cycles 3 -o iwan.csv",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // phi_max = M_S (1 + beta) / (K_T c), R = M_S (chi + 1) / (phi_max^(chi+2) c); 4 R a^(chi+3) / ((chi+2)(chi+3)).
  const double chi = -0.5, c = 0.2 + (chi + 1) / (chi + 2), phi_max = 0.7 * 1.2 / (20.0 * c);
  const double r_ = 0.7 * (chi + 1) / (std::pow(phi_max, chi + 2) * c);
  const double expected = 4 * r_ * std::pow(0.05, chi + 3) / ((chi + 2) * (chi + 3));
  const std::size_t at = r.err.find("dissipated energy in the last cycle ");
  ASSERT_NE(at, std::string::npos) << r.err;
  const double printed = std::strtod(r.err.c_str() + at + 36, nullptr);
  EXPECT_NEAR(printed, expected, 1e-5 * expected) << r.err;
  const Csv csv = read_csv(dir / "iwan.csv");
  EXPECT_EQ(csv.column("moment_n_m").size(), 3u * 400u + 1u);
}

TEST(IwanCli, TheExampleCableCyclesAndADamperOfItSolvesByEveryMethod) {
  const auto dir = scratch_directory("iwan-damper");
  const CliResult cycle = run_cli("cycle '" + kIwanCable + "' --experiment a --amplitude 0.02 --json -o cycle.csv", dir);
  ASSERT_EQ(cycle.exit_code, 0) << cycle.err;
  std::ofstream(dir / "damper.toml") << iwan_damper();
  double reference = 0.0;
  for (const char* method : {"hb", "collocation", "time", "shooting"}) {
    const CliResult r = run_cli(std::string("impedance damper.toml --velocity 0.1 --frequencies 20 --method ") + method +
                                    " -o z.csv",
                                dir);
    ASSERT_EQ(r.exit_code, 0) << method << ": " << r.err;
    const Csv csv = read_csv(dir / "z.csv");
    const double re = csv.column("re_z_n_s_m").front(), im = csv.column("im_z_n_s_m").front();
    EXPECT_GT(re, 0.0) << method;  // the law dissipates
    const double magnitude = std::hypot(re, im);
    if (reference == 0.0) reference = magnitude;
    EXPECT_NEAR(magnitude, reference, 5e-3 * reference) << method;
  }
}

TEST(IwanCli, IdentifyLocalFindsTheNumbersOfItsOwnLoop) {
  const auto dir = scratch_directory("iwan-identify");
  ASSERT_EQ(run_cli("loop --law iwan --ei 2.8 --slip-moment 0.7 --tangent-stiffness 20 --exponent -0.4 --beta 0.3 "
                    "--amplitude 0.1 --cycles 2 -o loop.csv",
                    dir)
                .exit_code,
            0);
  const Csv loop = read_csv(dir / "loop.csv");
  std::ofstream record(dir / "record.csv");
  record << "curvature_per_m,moment_n_m\n";
  for (std::size_t k = 0; k < loop.column("moment_n_m").size(); ++k) {
    record << loop.column("curvature_per_m")[k] << "," << loop.column("moment_n_m")[k] << "\n";
  }
  record.close();
  const CliResult r = run_cli("identify local --law iwan --input record.csv --json -o fit.toml", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"law\": \"iwan\""), std::string::npos) << r.out;
  std::ifstream fit(dir / "fit.toml");
  const std::string text((std::istreambuf_iterator<char>(fit)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("law = \"iwan\""), std::string::npos) << text;
  const std::size_t at = r.out.find("\"error\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_LT(std::strtod(r.out.c_str() + at + 9, nullptr), 1e-3) << r.out;
}

TEST(IwanCli, BadNumbersAndKeysOfOtherLawsAreOneLine) {
  const auto dir = scratch_directory("iwan-bad");
  const CliResult missing = run_cli("loop --law iwan --ei 2.8 --slip-moment 0.7 --amplitude 0.05 -o x.csv", dir);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("--law iwan needs --ei (N m^2), --slip-moment (N m), --tangent-stiffness (N m^2), "
                             "--exponent and --beta"),
            std::string::npos)
      << missing.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.csv"));
  std::string text = iwan_damper();
  text.replace(text.find("exponent = -0.5"), 15, "exponent = 0.5");
  std::ofstream(dir / "damper.toml") << text;
  const CliResult exponent = run_cli("impedance damper.toml --velocity 0.1 --frequencies 20 -o z.csv", dir);
  EXPECT_EQ(exponent.exit_code, 2);
  EXPECT_NE(exponent.err.find("arm[0].cable.exponent = 0.5: expected a value > -1 and <= 0"), std::string::npos)
      << exponent.err;
  text = iwan_damper();
  text.replace(text.find("beta = 0.2"), 10, "jenkin = [ { c = 20.0, h = 0.7 } ]");
  std::ofstream(dir / "damper.toml") << text;
  const CliResult jenkin = run_cli("impedance damper.toml --velocity 0.1 --frequencies 20 -o z.csv", dir);
  EXPECT_EQ(jenkin.exit_code, 2);
  EXPECT_NE(jenkin.err.find("arm[0].cable.jenkin: is a number of the Masing law: law = \"iwan\" takes ei, slip_moment, "
                            "tangent_stiffness, exponent and beta"),
            std::string::npos)
      << jenkin.err;
  EXPECT_EQ(jenkin.err.find('\n'), jenkin.err.size() - 1) << jenkin.err;
}

}  // namespace
}  // namespace stockbridge::testing
