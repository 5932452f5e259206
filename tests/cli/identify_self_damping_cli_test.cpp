// `stockbridge identify self-damping` end to end: the shipped example's fit and its
// -o table, the one-tension case (--n), a unit slip refused and taken, bad input
// named in one line with nothing written.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::testing {
namespace {

const std::string kSelfDampingExample = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/self_damping_tests.csv";

/// The "value" (or "standard_error") of a JSON member {"value": ..., "standard_error": ...}.
double sd_json_estimate(const std::string& json, const std::string& key, const std::string& member = "value") {
  const std::size_t at = json.find("\"" + key + "\": {");
  if (at == std::string::npos) return NAN;
  const std::size_t m = json.find("\"" + member + "\": ", at);
  return m == std::string::npos ? NAN : std::stod(json.substr(m + member.size() + 4));
}

TEST(IdentifySelfDampingCli, FitsTheShippedExampleAndWritesASpanTable) {
  const auto dir = scratch_directory("identify-self-damping");
  const CliResult r = run_cli("identify self-damping '" + kSelfDampingExample + "' --json -o sd.toml", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The example follows Noiseux's law (2.44, 5.63, 2.76) with 10 % scatter: the fit
  // lies within a few standard errors of it.
  const double l = sd_json_estimate(r.out, "l"), m = sd_json_estimate(r.out, "m"), n = sd_json_estimate(r.out, "n");
  EXPECT_NEAR(l, 2.44, 4.0 * sd_json_estimate(r.out, "l", "standard_error"));
  EXPECT_NEAR(m, 5.63, 4.0 * sd_json_estimate(r.out, "m", "standard_error"));
  EXPECT_NEAR(n, 2.76, 4.0 * sd_json_estimate(r.out, "n", "standard_error"));
  EXPECT_NE(r.out.find("\"n_given\": false"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"points\": 45"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"tensions_n\": [20820, 27760, 34700]"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("identify self-damping: k = "), std::string::npos) << r.err;
  const std::string table = read_text(dir / "sd.toml");
  EXPECT_NE(table.find("[self_damping]\nlaw = \"power\"\n"), std::string::npos) << table;
  const std::size_t at = table.find("\nl = ");
  ASSERT_NE(at, std::string::npos) << table;
  EXPECT_EQ(std::stod(table.substr(at + 5)), l) << "the table's l is the JSON's, every digit";
}

TEST(IdentifySelfDampingCli, OneTensionNeedsN) {
  const auto dir = scratch_directory("identify-self-damping-one-tension");
  write_temp_file(dir, "one.csv",
                  "tension_n,frequency_hz,amplitude_m,power_w_per_m\n28000,10,0.004,0.0002\n28000,20,0.002,0.001\n"
                  "28000,20,0.004,0.005\n28000,30,0.001,0.0012\n");
  write_temp_file(dir, "sd.toml", "untouched\n");
  const CliResult missing = run_cli("identify self-damping one.csv -o sd.toml", dir);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.stderr_lines(), 1) << missing.err;
  EXPECT_NE(missing.err.find("--n: not determined: every test is at one tension (28000 N)"), std::string::npos)
      << missing.err;
  EXPECT_NE(missing.err.find("one.csv"), std::string::npos) << missing.err;
  EXPECT_EQ(read_text(dir / "sd.toml"), "untouched\n");
  const CliResult given = run_cli("identify self-damping one.csv --n 2.5 --json", dir);
  ASSERT_EQ(given.exit_code, 0) << given.err;
  EXPECT_NE(given.out.find("\"n_given\": true"), std::string::npos) << given.out;
  EXPECT_NE(given.out.find("\"n\": {\"value\": 2.5, \"standard_error\": null}"), std::string::npos) << given.out;
  EXPECT_NE(given.out.find("n is not determined by the tests"), std::string::npos) << given.out;
  EXPECT_NE(given.err.find("note: one tension only"), std::string::npos) << given.err;
}

TEST(IdentifySelfDampingCli, NamesBadInputInOneLine) {
  const auto dir = scratch_directory("identify-self-damping-bad");
  const std::string header = "tension_n,frequency_hz,amplitude_m,power_w_per_m\n";
  write_temp_file(dir, "kn.csv", header + "28000,10,0.004,0.0002\n28,20,0.002,0.001\n");
  write_temp_file(dir, "cell.csv", header + "28000,10,0.004,0.0002\n28000,20,abc,0.001\n");
  write_temp_file(dir, "one_f.csv", header + "20000,20,0.004,0.002\n28000,20,0.002,0.001\n35000,20,0.004,0.003\n"
                                             "28000,20,0.003,0.001\n20000,20,0.001,0.001\n");
  const CliResult kn = run_cli("identify self-damping kn.csv -o sd.toml", dir);
  EXPECT_EQ(kn.exit_code, 2);
  EXPECT_EQ(kn.stderr_lines(), 1) << kn.err;
  EXPECT_NE(kn.err.find("kn.csv:3: column 'tension_n' = 28: outside"), std::string::npos) << kn.err;
  EXPECT_NE(kn.err.find("(in kN?"), std::string::npos) << kn.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "sd.toml"));
  const CliResult cell = run_cli("identify self-damping cell.csv", dir);
  EXPECT_EQ(cell.exit_code, 2);
  EXPECT_EQ(cell.stderr_lines(), 1) << cell.err;
  EXPECT_NE(cell.err.find("cell.csv:3"), std::string::npos) << cell.err;
  EXPECT_NE(cell.err.find("amplitude_m"), std::string::npos) << cell.err;
  const CliResult one_f = run_cli("identify self-damping one_f.csv", dir);
  EXPECT_EQ(one_f.exit_code, 2);
  EXPECT_NE(one_f.err.find("one_f.csv: frequency_hz: every test is at one frequency (20 Hz): m is not determined"),
            std::string::npos)
      << one_f.err;
}

}  // namespace
}  // namespace stockbridge::testing
