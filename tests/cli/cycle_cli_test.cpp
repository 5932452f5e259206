// `stockbridge cycle` as users run it: closed forms from the CLI, the JSON
// summary, and one line + exit 2 + no file for every kind of bad cable file.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::testing {
namespace {

/// The rows of a CSV file as numbers (empty cells as NaN), header dropped.
std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(cell.empty() ? NAN : std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(CycleCli, ElasticCableReproducesClosedFormsA) {
  const auto dir = scratch_directory("cycle-elastic-a");
  write_temp_file(dir, "cable.toml", "[cable]\nlength = 0.3\nsections = 20\nei = 22.8\n");
  const CliResult r = run_cli("cycle cable.toml --experiment a --amplitude 0.01 --cycles 1 --points 40 -o c.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_text(dir / "c.csv");
  EXPECT_EQ(csv.rfind("step,x_m,phi_rad,force_n,clamp_moment_n_m,tip_moment_n_m", 0), 0u);
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 41u);
  for (const auto& row : rows) {
    const double x = row[1], force = row[3];
    EXPECT_NEAR(force, 3.0 * 22.8 * x / 0.027, 1e-10 * 3.0 * 22.8 * 0.01 / 0.027);  // relative to the amplitude
    EXPECT_NEAR(row[4], force * 0.3, 1e-12);  // T = F l
  }
}

TEST(CycleCli, ElasticCableReproducesClosedFormsB) {
  const auto dir = scratch_directory("cycle-elastic-b");
  write_temp_file(dir, "cable.toml", "[cable]\nlength = 0.3\nsections = 20\nei = 22.8\n");
  const CliResult r = run_cli("cycle cable.toml --experiment b --amplitude 0.1 --cycles 1 --points 40 -o c.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& row : csv_rows(read_text(dir / "c.csv"))) {
    EXPECT_NEAR(row[1], 0.0, 1e-15);                                   // x = 0
    EXPECT_NEAR(row[4], -2.0 * 22.8 * row[2] / 0.3, 1e-10 * 2.0 * 22.8 * 0.1 / 0.3);  // T, relative to the amplitude
  }
}

/// The steady cycle of experiment (a) on a uniform cable (ei, one element c, h),
/// tip deflection +-amplitude, in closed form up to a fine quadrature: the cable is
/// loaded proportionally, M = F u with u = l - s (Q = 0), so by Masing's rule every
/// branch is the virgin curve doubled and the extremes lie on the virgin curve:
/// kappa(M) = M / (ei + c) while |M| <= h (ei + c) / c, else (M - h sign M) / ei.
/// The peak force F_a solves amplitude = int_0^l u kappa(F_a u) du; each element
/// dissipates 4 h (kappa_a - h / c) per cycle where it slips (MODEL.md section 1).
struct SteadyCycle {
  double peak_force;  ///< N
  double dissipated;  ///< J per cycle
};

SteadyCycle steady_cycle_a(double length, double ei, double c, double h, double amplitude) {
  constexpr int kPoints = 20000;
  const double stick_limit = h * (ei + c) / c;
  auto kappa = [&](double m) { return m <= stick_limit ? m / (ei + c) : (m - h) / ei; };  // m >= 0
  auto deflection = [&](double force) {
    double x = 0.0;
    for (int i = 0; i < kPoints; ++i) {
      const double u = (i + 0.5) * length / kPoints;
      x += u * kappa(force * u) * length / kPoints;
    }
    return x;
  };
  double lo = 0.0, hi = 1.0;
  while (deflection(hi) < amplitude) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) (deflection(0.5 * (lo + hi)) < amplitude ? lo : hi) = 0.5 * (lo + hi);
  const double peak_force = 0.5 * (lo + hi);
  double dissipated = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double u = (i + 0.5) * length / kPoints;
    dissipated += 4.0 * h * std::max(0.0, kappa(peak_force * u) - h / c) * length / kPoints;
  }
  return {peak_force, dissipated};
}

// examples/cable_sauter2003.toml: l = 0.3, ei = 2.8, one element c = 20, h = 0.7 (40
// sections). The peak force (12.78 N) and the sliders' dissipation of the last cycle
// (0.3607 J) against the closed form (40 sections: 2e-5 and 1e-4 off), and the loop
// work (the trapezoid rule over 400 samples: 6e-5 off).
TEST(CycleCli, JsonSummaryOfTheShippedCable) {
  const auto dir = scratch_directory("cycle-json");
  const std::string cable = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/cable_sauter2003.toml";
  const CliResult r = run_cli("cycle '" + cable + "' --experiment a --amplitude 0.03 --json -o c.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const SteadyCycle expected = steady_cycle_a(0.3, 2.8, 20.0, 0.7, 0.03);
  EXPECT_NEAR(json_number_after(r.out, "force_n", "max"), expected.peak_force,
              2e-4 * expected.peak_force) << r.out;
  EXPECT_NEAR(json_number(r.out, "last_cycle_dissipation_sliders_j"), expected.dissipated, 1e-3 * expected.dissipated)
      << r.out;
  EXPECT_NEAR(json_number(r.out, "last_cycle_dissipation_loop_j"), expected.dissipated, 1e-3 * expected.dissipated)
      << r.out;
  EXPECT_NE(r.out.find("\"newton_iterations\": {\"max\": "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"failed_points\": 0"), std::string::npos) << r.out;
}

struct BadCable {
  const char* name;
  const char* contents;
  const char* must_mention;
};

class CycleCliRejects : public ::testing::TestWithParam<BadCable> {};

TEST_P(CycleCliRejects, WithOneLineExitTwoAndNoFile) {
  const auto dir = scratch_directory(std::string("cycle-bad-") + GetParam().name);
  write_temp_file(dir, "cable.toml", GetParam().contents);
  const CliResult r = run_cli("cycle cable.toml --experiment a --amplitude 0.01 -o out.csv", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("cable.toml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(GetParam().must_mention), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

INSTANTIATE_TEST_SUITE_P(
    BadFiles, CycleCliRejects,
    ::testing::Values(
        BadCable{"syntax", "[cable\nlength = 0.3\n", "syntax error"},
        BadCable{"missing_length", "[cable]\nsections = 40\nei = 2.8\n", "'length'"},
        BadCable{"missing_table", "length = 0.3\n", "'cable'"},
        BadCable{"unknown_key", "[cable]\nlength = 0.3\nsections = 4\nei = 2.8\nstiffness = 1\n", "cable.stiffness"},
        BadCable{"wrong_type", "[cable]\nlength = \"0.3\"\nsections = 4\nei = 2.8\n", "cable.length"},
        BadCable{"negative_ei", "[cable]\nlength = 0.3\nsections = 4\nei = -2.8\n", "cable.ei = -2.8"},
        BadCable{"zero_h", "[cable]\nlength = 0.3\nsections = 4\nei = 2.8\njenkin = [{c = 20, h = 0}]\n", "jenkin[0].h = 0"},
        BadCable{"inf_c", "[cable]\nlength = 0.3\nsections = 4\nei = 2.8\njenkin = [{c = inf, h = 0.7}]\n", "jenkin[0].c = inf"},
        BadCable{"huge_sections", "[cable]\nlength = 0.3\nsections = 1000000000\nei = 2.8\n", "cable.sections"},
        BadCable{"zero_sections", "[cable]\nlength = 0.3\nsections = 0\nei = 2.8\n", "cable.sections"},
        BadCable{"mirror_too_short", "[cable]\nlength = 0.3\nsections = 4\nei = 2.8\nmirror_length = 0.1\n", "mirror_length"},
        BadCable{"bad_profile", "[cable]\nlength = 0.3\nsections = 4\nei = { s = [0, 0.1], value = [2.8] }\n", "cable.ei"},
        BadCable{"empty", "", "'cable'"}),
    [](const ::testing::TestParamInfo<BadCable>& info) { return info.param.name; });

TEST(CycleCli, BadOptionsAndMissingFile) {
  const auto dir = scratch_directory("cycle-bad-options");
  write_temp_file(dir, "cable.toml", "[cable]\nlength = 0.3\nsections = 4\nei = 2.8\n");
  for (const std::string args : {"cycle cable.toml --experiment c --amplitude 0.01 -o out.csv",
                                 "cycle cable.toml --amplitude -0.01 -o out.csv",
                                 "cycle cable.toml --amplitude 0.01 --cycles 0 -o out.csv",
                                 "cycle nope.toml --amplitude 0.01 -o out.csv",
                                 "cycle cable.toml --amplitude 0.01"}) {
    const CliResult r = run_cli(args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.stderr_lines(), 1) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.csv")) << args;
  }
}

}  // namespace
}  // namespace stockbridge::testing
