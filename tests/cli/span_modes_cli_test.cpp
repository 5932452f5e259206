// `stockbridge span --modes` as users run it: the example span with a warning sphere
// added (the modes CSV's header and rows, the shapes CSV, the --json keys), the
// bare span's harmonics with the dampers removed, the wind band's top as the default
// fmax, a damper known by its sheet, and bad options (exit 2, one line, no file).

#include <cmath>
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
const std::string kModesExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

/// The example span and its damper in a scratch folder, with `extra` appended to the span file.
std::filesystem::path modes_example(const std::string& name, const std::string& extra = "") {
  const auto dir = scratch_directory(name);
  std::filesystem::copy_file(kModesExamples + "aster570_400m.toml", dir / "span.toml");
  std::filesystem::copy_file(kModesExamples + "sauter2003.toml", dir / "sauter2003.toml");
  std::ofstream(dir / "span.toml", std::ios::app) << extra;
  return dir;
}

const std::string kSphere = "\n[[mass]]\nname = \"sphere\"\nmass = 15.0\npositions = [150.0, 250.0]\n";

TEST(SpanModesCli, TheExampleWithASphereWritesTheModesAndShapes) {
  const auto dir = modes_example("span-modes-sphere", kSphere);
  const CliResult r = run_cli("span span.toml --modes --fmax 5 --shapes shapes.csv --json -o modes.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string header = lines_of(read_text(dir / "modes.csv")).at(0);
  EXPECT_EQ(header,
            "mode,frequency_hz,wavelength_m,bare_frequency_ratio,end_residual,sauter2003_1_deflection,"
            "sphere_1_deflection,sphere_2_deflection,sauter2003_2_deflection");
  const Csv modes = read_csv(dir / "modes.csv");
  const std::vector<double> f = modes.column("frequency_hz");
  ASSERT_EQ(static_cast<double>(f.size()), json_number(r.out, "modes"));
  ASSERT_GT(f.size(), 20u);
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_EQ(modes.column("mode")[i], static_cast<double>(i + 1));
    EXPECT_LT(f[i], 5.0);
    if (i > 0) {
      EXPECT_GT(f[i], f[i - 1]);
    }
    EXPECT_LT(modes.column("bare_frequency_ratio")[i], 1.0 + 1e-12);  // masses only lower them
    EXPECT_LT(modes.column("end_residual")[i], 1e-9);
  }
  EXPECT_EQ(r.out.rfind("{\"length_m\": 400, \"wave_speed_m_s\": ", 0), 0u) << r.out;
  for (const char* key : {"\"fmax_hz\": 5", "\"fmax_from_wind_band\": false", "\"dampers\": \"linear\"",
                          "\"clamp_still_modes\": 0", "\"name\": \"sphere\", \"column\": \"sphere_1\", \"kind\": \"mass\", "
                          "\"position_m\": 150, \"mass_kg\": 15"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  const Csv shapes = read_csv(dir / "shapes.csv");
  EXPECT_EQ(lines_of(read_text(dir / "shapes.csv")).at(0).rfind("attachment,x_m,mode_1,mode_2,", 0), 0u);
  const std::vector<double> x = shapes.column("x_m");
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), 400.0);
  const std::vector<double> first = shapes.column("mode_1");
  EXPECT_EQ(first.front(), 0.0);
  EXPECT_LT(std::abs(first.back()), 1e-9);
  EXPECT_EQ(shapes.column("mode_" + std::to_string(f.size())).size(), x.size());
}

TEST(SpanModesCli, WithTheDampersRemovedTheBareSpanHasItsHarmonics) {
  const auto dir = modes_example("span-modes-bare");
  const CliResult r = run_cli("span span.toml --modes --dampers removed --fmax 3 --json -o modes.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double c = json_number(r.out, "wave_speed_m_s");
  EXPECT_NEAR(c, std::sqrt(0.15 * 185300.0 / 1.571), 1e-9 * c);
  const std::vector<double> f = read_csv(dir / "modes.csv").column("frequency_hz");
  ASSERT_EQ(f.size(), static_cast<std::size_t>(std::floor(3.0 * 800.0 / c)));
  for (std::size_t n = 1; n <= f.size(); ++n) EXPECT_NEAR(f[n - 1], n * c / 800.0, 1e-10 * f[n - 1]) << n;
  EXPECT_NE(r.out.find("\"attachments\": []"), std::string::npos) << r.out;
}

TEST(SpanModesCli, ByDefaultTheModesGoUpToTheWindBandsTop) {
  const auto dir = modes_example("span-modes-default");
  const CliResult r = run_cli("span span.toml --modes -o modes.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("modes below 41.71 Hz (the top of the wind band"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dampers: at their linear impedance, every element sticking"), std::string::npos) << r.out;
  // Sauter's damper has two identical arms: at their clamp-held frequencies (21.17 Hz
  // sticking) they swing against each other with the clamp still, at both ends.
  EXPECT_NE(r.out.find("left out: 2 frequencies"), std::string::npos) << r.out;
  EXPECT_GT(read_csv(dir / "modes.csv").column("frequency_hz").back(), 41.0);
}

TEST(SpanModesCli, ADamperKnownByItsSheetIsRemovedOrRefused) {
  const auto dir = modes_example("span-modes-sheet");
  std::filesystem::copy_file(kModesExamples + "vendor_sheet.csv", dir / "vendor_sheet.csv");
  std::string text = read_text(dir / "span.toml");
  text.replace(text.find("file = \"sauter2003.toml\""), 24, "impedance = \"vendor_sheet.csv\"");
  std::ofstream(dir / "sheet.toml") << text;
  const CliResult refused = run_cli("span sheet.toml --modes --fmax 2 -o modes.csv", dir);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_EQ(refused.stderr_lines(), 1) << refused.err;
  EXPECT_NE(refused.err.find("dampers = linear: damper[0] ('vendor_sheet') is known by its measured sheet only"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "modes.csv"));
  const CliResult removed = run_cli("span sheet.toml --modes --fmax 2 --dampers removed --quiet -o modes.csv", dir);
  EXPECT_EQ(removed.exit_code, 0) << removed.err;
  EXPECT_EQ(removed.out, "");
  EXPECT_TRUE(std::filesystem::exists(dir / "modes.csv"));
}

void expect_bad_modes(const std::string& arguments, const std::string& mention) {
  const auto dir = modes_example("span-modes-bad");
  const CliResult r = run_cli(arguments, dir);
  EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << arguments << "\n" << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << "\n" << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv")) << arguments;
  EXPECT_FALSE(std::filesystem::exists(dir / "shapes.csv")) << arguments;
}

TEST(SpanModesCli, BadOptionsExitTwoWithOneLineAndNoFile) {
  expect_bad_modes("span span.toml --modes --fmax 0 -o out.csv", "fmax = 0");
  expect_bad_modes("span span.toml --modes --fmax -3 --shapes shapes.csv -o out.csv", "fmax = -3");
  expect_bad_modes("span span.toml --modes --fmax 1e5 -o out.csv", "fmax = 100000: expected a frequency with at most 10000 modes");
  expect_bad_modes("span span.toml --modes --dampers stick -o out.csv", "dampers = 'stick': expected removed");
  expect_bad_modes("span span.toml --fmax 10 -o out.csv", "--fmax requires --modes");
  expect_bad_modes("span span.toml --shapes shapes.csv -o out.csv", "--shapes requires --modes");
  expect_bad_modes("span span.toml --modes --points 5 -o out.csv", "excludes");
  expect_bad_modes("span span.toml --modes --no-dampers -o out.csv", "excludes");
  expect_bad_modes("span span.toml --modes --report r.html -o out.csv", "excludes");
  expect_bad_modes("span span.toml --modes --shapes out.csv -o out.csv", "out.csv");
  expect_bad_modes("span span.toml --modes --shapes span.toml -o out.csv", "span.toml");
}

}  // namespace
}  // namespace stockbridge::testing
