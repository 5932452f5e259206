// `stockbridge fatigue-tests` from the command line: the shipped dohl example's
// table and JSON, the design curve written and taken by a span file's [fatigue]
// curve, and one line naming file, line and column for bad input, no file written.

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {
namespace {

const std::string kFatigueExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";
const std::string kTests = "'" + kFatigueExamples + "fatigue_tests.csv'";

void write_fatigue_file(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(FatigueTestsCli, TheExamplesTableAndJson) {
  const auto dir = scratch_directory("fatigue-tests-example");
  const CliResult r = run_cli("fatigue-tests " + kTests + " --conductor 'ACSR Drake' --json -o out.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("\"failures\": 12, \"runouts\": 13"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"below_sbl\": {\"count\": "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"aluminium_layers\": 2, \"name\": \"the CIGRE Safe Border Line (several aluminium layers)\""),
            std::string::npos);
  const std::vector<std::string> lines = lines_of(read_text(dir / "out.csv"));
  ASSERT_EQ(lines.size(), 26u);
  EXPECT_EQ(lines[0], "test,conductor,tension_n,yb_pp_mm,cycles,failed,stress_ps_mpa,microstrain_pp,sbl_cycles,below_sbl");
  EXPECT_EQ(lines[1].rfind("Dalpe_1999_angle10 #1,ACSR Drake,35000,0.8272,3412811,1,", 0), 0u) << lines[1];
}

TEST(FatigueTestsCli, TheDesignCurveIsASpansSnCurve) {
  const auto dir = scratch_directory("fatigue-tests-curve");
  ASSERT_EQ(run_cli("fatigue-tests " + kTests + " --conductor Drake --curve curve.toml -o out.csv", dir).exit_code, 0);
  const std::string curve = read_text(dir / "curve.toml");
  EXPECT_NE(curve.find("name = \"ACSR Drake fatigue tests, mean - 2 s\""), std::string::npos) << curve;
  std::filesystem::copy_file(kFatigueExamples + "sauter2003.toml", dir / "sauter2003.toml");
  std::string span = read_text(kFatigueExamples + "drake_300m.toml");
  span.replace(span.find("cycles = 5e8"), 12, "cycles = 5e8\ncurve = \"curve.toml\"");
  write_fatigue_file(dir / "span.toml", span);
  const CliResult r = run_cli("span span.toml --points 4 --json -o span.csv", dir);
  ASSERT_LE(r.exit_code, 3) << r.err;
  EXPECT_NE(r.out.find("\"criterion_description\": \"the S-N curve 'ACSR Drake fatigue tests, mean - 2 s' (curve.toml) at 5e+08 "
                       "cycles\""),
            std::string::npos)
      << r.out;
  // A missing curve file is named at the span file's line.
  span.replace(span.find("curve.toml"), 10, "none.toml");
  write_fatigue_file(dir / "bad.toml", span);
  const CliResult bad = run_cli("span bad.toml --points 4 -o bad.csv", dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(std::regex_search(bad.err, std::regex(R"(^stockbridge: bad\.toml:\d+: fatigue\.curve: "none\.toml": expected an existing S-N curve file)")))
      << bad.err;
}

TEST(FatigueTestsCli, BadCellsAreNamedAndNothingIsWritten) {
  const auto dir = scratch_directory("fatigue-tests-bad");
  write_fatigue_file(dir / "out.csv", "kept\n");
  const std::string header = "test,conductor,tension_n,yb_pp_mm,cycles,failed\n";
  write_fatigue_file(dir / "kn.csv", header + "a,ACSR Drake,35000,0.8,3e6,true\nb,ACSR Drake,35,0.8,3e6,true\n");
  CliResult r = run_cli("fatigue-tests kn.csv -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "stockbridge: kn.csv:3: column tension_n = 35: outside the typical 1000 to 500000 N of the conductor "
                   "tension (in kN? 35 kN = 35000 N) (--allow-unusual takes it as given)\n");
  EXPECT_EQ(read_text(dir / "out.csv"), "kept\n");
  write_fatigue_file(dir / "m.csv", header + "a,ACSR Drake,35000,0.0008,3e6,true\n");
  r = run_cli("fatigue-tests m.csv -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("m.csv:2: column yb_pp_mm = 0.0008: outside the typical 0.01 to 5 mm"), std::string::npos) << r.err;
  write_fatigue_file(dir / "yes.csv", header + "a,ACSR Drake,35000,0.8,3e6,yes\n");
  r = run_cli("fatigue-tests yes.csv -o out.csv", dir);
  EXPECT_EQ(r.err, "stockbridge: yes.csv:2: column 'failed' = 'yes': expected true (the conductor broke) or false (a runout)\n");
  write_fatigue_file(dir / "few.csv", header + "a,ACSR Drake,35000,0.8,3e6,true\nb,ACSR Drake,35000,0.6,3e7,true\nc,ACSR Drake,35000,0.5,1e8,false\n");
  r = run_cli("fatigue-tests few.csv -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("2 failure(s) at 2 stress(es): the fit needs 3 failures or more at 2 stresses or more"),
            std::string::npos) << r.err;
  write_fatigue_file(dir / "steel.csv", header + "a,EHS 3/8,20000,0.8,3e6,true\n");
  r = run_cli("fatigue-tests steel.csv -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "stockbridge: steel.csv:2: column 'conductor' = 'EHS 3/8': outer wires of steel: expected a "
                   "conductor with aluminium or aluminium-alloy outer wires (the tests are set against the CIGRE Safe "
                   "Border Line, stated for those only)\n");
  write_fatigue_file(dir / "who.csv", header + "a,ACSR Nonesuch,35000,0.8,3e6,true\n");
  r = run_cli("fatigue-tests who.csv -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("stockbridge: who.csv:2: column 'conductor'", 0), 0u) << r.err;
  EXPECT_EQ(read_text(dir / "out.csv"), "kept\n");
}

}  // namespace
}  // namespace stockbridge::testing
