// What the damper commands do when points do not converge: the file is written with
// the points marked (exit 3), the summary says none rather than a number it does not
// have, and the reason is the solver's termination.

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

// The sampled energy balance of a converged point is about 1e-5: this tolerance forces the path.
const std::string kUnreachable = " --energy-tolerance 1e-12";

TEST(NotConvergedCli, ResponseWritesTheLastIterateMarkedAndExitsThree) {
  const auto dir = scratch_directory("response-not-converged");
  const CliResult r = run_cli("response '" + kDamperExample + "' --frequency 20 --velocity 0.2 --json -o t.csv" + kUnreachable, dir);
  ASSERT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;  // the reason, in one line
  EXPECT_NE(r.out.find("\"termination\": \"energy_mismatch\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"re_z_n_s_m\": null"), std::string::npos) << r.out;
  std::istringstream csv(read_text(dir / "t.csv"));
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header.substr(header.rfind(',') + 1), "converged");
  EXPECT_EQ(first.substr(first.rfind(',') + 1), "0");
}

TEST(NotConvergedCli, ASweepWithNoConvergedPointReportsNoEnergyError) {
  const auto dir = scratch_directory("impedance-none-converged");
  const CliResult r =
      run_cli("impedance '" + kDamperExample + "' --velocity 0.2 --frequencies 15,20 --json -o z.csv" + kUnreachable, dir);
  ASSERT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.out.find("\"max_energy_error\": null"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"termination\": \"energy_mismatch\""), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("largest energy error none"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "z.csv"));
}

}  // namespace
}  // namespace stockbridge::testing
