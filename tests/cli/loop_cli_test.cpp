// `stockbridge loop` from the command line: the file it writes, and its refusals.

#include <filesystem>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

TEST(LoopCli, WritesTheLoopAndSummarisesTheLastCycle) {
  const auto dir = scratch_directory("loop-ok");
  const CliResult r = run_cli("loop --ei 2.8 --jenkin 20:0.7 --amplitude 0.05 --cycles 2 --points 400 -o loop.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_text(dir / "loop.csv");
  EXPECT_EQ(csv.rfind("step,curvature_per_m,moment_n_m", 0), 0u);
  int rows = 0;
  for (char ch : csv) rows += ch == '\n';
  EXPECT_EQ(rows, 1 + 2 * 400 + 1);
  EXPECT_EQ(r.stderr_lines(), 1);
  EXPECT_NE(r.err.find("0.0420000000"), std::string::npos) << r.err;  // 4 h (ka - h/c)
}

TEST(LoopCli, RegularisedLawRuns) {
  const auto dir = scratch_directory("loop-reg");
  const CliResult r = run_cli("loop --ei 2.8 --jenkin 20:0.7 --amplitude 0.05 --law regularised --exponent 50 -o l.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "l.csv"));
}

TEST(LoopCli, BoucWenLawDissipatesItsClosedFormPerSteadyCycle) {
  const auto dir = scratch_directory("loop-bouc-wen");
  const CliResult r =
      run_cli("loop --law bouc-wen --ei-min 5 --ei-max 40 --chi0 0.15 --amplitude 0.5 --cycles 4 --points 400 -o bw.csv",
              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // 4 (EI_max - EI_min) chi0 (chi_a - chi0 tanh(chi_a / chi0)) = 7.35800740... J/m (MODEL.md 13)
  EXPECT_NE(r.err.find("bouc-wen law, 4 cycles x 400 points: dissipated energy in the last cycle 7.3580074"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read_text(dir / "bw.csv").rfind("step,curvature_per_m,moment_n_m,dissipated_energy_j_per_m\n", 0), 0u);
}

struct BadCase {
  const char* arguments;
  const char* must_mention;
};

class LoopCliRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(LoopCliRejects, WithOneLineExitTwoAndNoFile) {
  const auto dir = scratch_directory("loop-bad");
  const CliResult r = run_cli(std::string("loop ") + GetParam().arguments + " -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().must_mention), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    BadOptions, LoopCliRejects,
    ::testing::Values(BadCase{"--ei -1 --amplitude 0.05", "ei = -1"},
                      BadCase{"--ei nan --amplitude 0.05", "ei = nan"},
                      BadCase{"--ei 2.8 --jenkin 20:0 --amplitude 0.05", "jenkin[0].h = 0"},
                      BadCase{"--ei 2.8 --jenkin -20:0.7 --amplitude 0.05", "jenkin[0].c = -20"},
                      BadCase{"--ei 2.8 --jenkin 20 --amplitude 0.05", "'20'"},
                      BadCase{"--ei 2.8 --jenkin 20:abc --amplitude 0.05", "'abc'"},
                      BadCase{"--ei 2.8 --amplitude inf", "amplitude = inf"},
                      BadCase{"--ei 2.8 --amplitude 0.05 --cycles 0", "cycles = 0"},
                      BadCase{"--ei 2.8 --amplitude 0.05 --points 2", "points = 2"},
                      BadCase{"--ei 2.8 --amplitude 0.05 --law foo", "foo"},
                      BadCase{"--ei 2.8 --jenkin 20:0.7 --amplitude 0.05 --law regularised --exponent 0.5",
                              "exponent = 0.5"},
                      BadCase{"--ei 2.8 --amplitude 0.05 --bogus 3", "bogus"},
                      BadCase{"--amplitude 0.05", "--ei"},
                      BadCase{"--law bouc-wen --ei-min 5 --ei-max 40 --amplitude 0.05", "needs --ei-min, --ei-max"},
                      BadCase{"--law bouc-wen --ei 2.8 --ei-min 5 --ei-max 40 --chi0 0.15 --amplitude 0.05",
                              "--ei and --jenkin are the Masing law's: --law bouc-wen takes --ei-min, --ei-max and --chi0"},
                      BadCase{"--ei 2.8 --chi0 0.15 --amplitude 0.05", "are the Bouc-Wen law's"},
                      BadCase{"--law bouc-wen --ei-min 5 --ei-max 4 --chi0 0.15 --amplitude 0.05", "ei_max = 4"},
                      BadCase{"--law bouc-wen --ei-min 5 --ei-max 40 --chi0 0 --amplitude 0.05", "chi0 = 0"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return "case" + std::to_string(info.index); });

TEST(LoopCli, FailureLeavesAnExistingOutputUntouched) {
  const auto dir = scratch_directory("loop-keep");
  {
    std::ofstream(dir / "out.csv") << "precious\n";
  }
  const CliResult r = run_cli("loop --ei -2 --amplitude 0.05 -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_text(dir / "out.csv"), "precious\n");
}

TEST(LoopCli, UnwritableOutputIsOneLineAndExitTwo) {
  const auto dir = scratch_directory("loop-nodir");
  const CliResult r = run_cli("loop --ei 2.8 --amplitude 0.05 -o missing/dir/out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("missing/dir/out.csv"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stockbridge::testing
