// S-N curves (span/fatigue.hpp, io/sn_curve_file.hpp): the Safe Border Line as a
// curve equals the line; a table interpolates log-log and extrapolates along its end
// segments (hand-computed); a file's bad table is named at its line; a span whose
// [fatigue] curve is the Safe Border Line sampled gives the line's endurance limit,
// verdict and life, and another table the hand-computed ones.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "span/balance_summary.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/sn_curve_file.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/span.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

constexpr double kMpa = 1e6;

TEST(SnCurve, TheSafeBorderLineAsACurveIsTheLine) {
  for (int layers : {1, 4}) {
    const SafeBorderLine line = safe_border_line(layers);
    const SnCurve curve = safe_border_curve(layers);
    EXPECT_EQ(curve.branches().size(), 2u);
    for (double n : {1e4, 1e6, line.knee, 1.0000001 * line.knee, 1e8, 1e10}) {
      expect_relative(curve.endurance_limit(n), line.endurance_limit(n), 1e-15);
    }
    // Through the step at the knee too (a stress inside it fails at the knee).
    for (double mpa : {60.0, 30.0, 25.0, 24.9, 16.0, 15.9, 10.0, 5.0}) {
      expect_relative(curve.cycles_to_failure(mpa * kMpa), line.cycles_to_failure(mpa * kMpa), 1e-14);
    }
  }
  EXPECT_EQ(safe_border_curve(1).name(), "the CIGRE Safe Border Line (one aluminium layer)");
  EXPECT_EQ(safe_border_curve(1).cycles_to_failure(0.0), std::numeric_limits<double>::infinity());
}

TEST(SnCurve, ATableIsLogLogLinearAndExtrapolatesItsEndSegments) {
  const SnCurve t = SnCurve::from_table({40.0, 20.0, 15.0}, {1e6, 1e7, 1e8}, "t", "t.toml");
  EXPECT_EQ(t.description(), "'t' (t.toml)");
  expect_relative(t.endurance_limit(1e6), 40.0 * kMpa, 1e-14);
  expect_relative(t.endurance_limit(1e7), 20.0 * kMpa, 1e-14);
  // The log-log midpoint of a segment: the geometric mean of its ends.
  expect_relative(t.endurance_limit(std::sqrt(1e6 * 1e7)), std::sqrt(40.0 * 20.0) * kMpa, 1e-13);
  // Extrapolated: a decade before the first point along the first slope (40 -> 20 a decade): 80 MPa;
  // a decade beyond the last along the last (20 -> 15): 15 * 0.75 = 11.25 MPa.
  expect_relative(t.endurance_limit(1e5), 80.0 * kMpa, 1e-13);
  expect_relative(t.endurance_limit(1e9), 11.25 * kMpa, 1e-13);
  for (double n : {1e3, 2e6, 5e7, 3e9}) expect_relative(t.cycles_to_failure(t.endurance_limit(n)), n, 1e-12);
  expect_relative(t.cycles_to_failure(80.0 * kMpa), 1e5, 1e-12);
  expect_relative(t.cycles_to_failure(11.25 * kMpa), 1e9, 1e-12);
}

TEST(SnCurve, ATableThatIsNoCurveIsRefusedNamingItsValue) {
  EXPECT_EQ(invalid_parameter_message([] { SnCurve::from_table({40.0}, {1e6}, "t"); }),
            "stress_mpa: 1 value(s): expected at least 2 points");
  EXPECT_EQ(invalid_parameter_message([] { SnCurve::from_table({40.0, 20.0}, {1e6}, "t"); }),
            "cycles: 1 value(s) for 2 stresses: expected one per stress");
  EXPECT_EQ(invalid_parameter_message([] { SnCurve::from_table({40.0, 45.0}, {1e6, 1e7}, "t"); }),
            "stress_mpa[1] = 45: expected stresses > 0, strictly decreasing (zero-to-peak, MPa)");
  EXPECT_EQ(invalid_parameter_message([] { SnCurve::from_table({40.0, 30.0}, {1e6, 1e6}, "t"); }),
            "cycles[1] = 1000000: expected cycles > 0, strictly increasing");
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "stockbridge_sn_curve_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

std::string input_error_of(const std::filesystem::path& path) {
  try {
    io::read_sn_curve_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SnCurveFile, WrittenAndReadBack) {
  const auto path = write_file("written.toml", io::sn_curve_toml("Drake \"tests\"", "x.csv", {40.0, 20.0}, {1e6, 1e7}));
  const SnCurve c = io::read_sn_curve_file(path);
  EXPECT_EQ(c.name(), "Drake \"tests\"");
  EXPECT_EQ(c.source(), path.string());
  expect_relative(c.endurance_limit(1e7), 20.0 * kMpa, 1e-14);
}

TEST(SnCurveFile, ABadTableIsNamedAtItsLine) {
  const auto rising = write_file("rising.toml", "[sn_curve]\nname = \"x\"\nstress_mpa = [40, 50]\ncycles = [1e6, 1e7]\n");
  EXPECT_EQ(input_error_of(rising),
            rising.string() + ":3: sn_curve.stress_mpa[1] = 50: expected stresses > 0, strictly decreasing (zero-to-peak, MPa)");
  const auto text = write_file("text.toml", "[sn_curve]\nname = \"x\"\nstress_mpa = [40, \"a\"]\ncycles = [1e6, 1e7]\n");
  EXPECT_NE(input_error_of(text).find(text.string() + ":3: "), std::string::npos) << input_error_of(text);
  const auto unknown = write_file("unknown.toml", "[sn_curve]\nname = \"x\"\nstres_mpa = [40, 20]\ncycles = [1e6, 1e7]\n");
  EXPECT_NE(input_error_of(unknown).find("unknown key 'sn_curve.stres_mpa'"), std::string::npos) << input_error_of(unknown);
}

/// ASTER570 at 15 % RTS judged against `curve` (none: the Safe Border Line) at 5e8 cycles, with a climate.
Span curve_span(std::optional<SnCurve> curve) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  fatigue.life = LifeModel{WeibullWind{2.0, 4.0}, 0.2};
  fatigue.curve = std::move(curve);
  return Span(aster570(), 400.0, aster570_tension, WindModel{}, SelfDampingModel{}, {}, fatigue);
}

/// Points over the wind band, each of Poffenberger-Swart stress `mpa` (fymax twice that).
std::vector<BalancePoint> points_at(double mpa) {
  std::vector<BalancePoint> points;
  for (double f : {8.0, 12.0, 18.0, 25.0, 35.0}) {
    BalancePoint p;
    p.frequency_hz = f;
    p.stress_poffenberger_swart = mpa * kMpa;
    p.stress_fymax = 2.0 * mpa * kMpa;
    p.undamped_stress_fymax = p.stress_fymax;
    p.undamped_stress_poffenberger_swart = p.stress_poffenberger_swart;
    p.summary.termination = Termination::converged;
    points.push_back(p);
  }
  return points;
}

TEST(SnCurveSpan, TheSafeBorderLineSampledGivesTheLinesVerdictAndLife) {
  // ASTER570 has four aluminium layers: 450 N^-0.2 to 1.56e7 cycles, 263 N^-0.17 beyond;
  // sampled on both sides of the knee (its step a segment 1e-9 of the knee wide).
  const SafeBorderLine line = safe_border_line(4);
  std::vector<double> cycles{1e4, 1e5, 1e6, 1e7, line.knee, line.knee * (1.0 + 1e-9), 1e8, 1e9, 1e10};
  std::vector<double> stress;
  for (double n : cycles) stress.push_back(line.endurance_limit(n) / kMpa);
  stress[4] = line.a_low * std::pow(line.knee, line.b_low);  // the knee's upper end of the step
  const Span sbl = curve_span(std::nullopt);
  const Span table = curve_span(SnCurve::from_table(stress, cycles, "the line sampled", "sampled.toml"));
  EXPECT_EQ(table.criterion_description(), "the S-N curve 'the line sampled' (sampled.toml) at 5e+08 cycles");
  EXPECT_EQ(sbl.sn_curve().name(), "the CIGRE Safe Border Line (several aluminium layers)");
  expect_relative(table.endurance_limit(), sbl.endurance_limit(), 1e-12);
  for (double mpa : {3.0, 8.0, 16.0, 40.0}) {  // 16 MPa lies inside the step
    SCOPED_TRACE(mpa);
    const BalanceSummary a = summarise(sbl, points_at(mpa));
    const BalanceSummary b = summarise(table, points_at(mpa));
    EXPECT_EQ(a.verdict, b.verdict);
    ASSERT_TRUE(a.life && b.life);
    expect_relative(b.life->damage_per_year, a.life->damage_per_year, 1e-8);
  }
}

TEST(SnCurveSpan, AnotherTableGivesItsOwnHandComputedLimitAndLife) {
  // 30 MPa at 1e6 cycles, 10 MPa at 1e8: b = log(1/3) / log(100) = -0.2385606;
  // at 5e8 cycles (extrapolated): 10 * 5^b = 6.811665 MPa.
  const Span sbl = curve_span(std::nullopt);
  const Span table = curve_span(SnCurve::from_table({30.0, 10.0}, {1e6, 1e8}, "own", "own.toml"));
  expect_relative(table.endurance_limit(), 6.811665e6, 1e-6);
  // Every point at 20 MPa: the damage per year is the cycles per year over N(20 MPa),
  // N = 1e6 (20 / 30)^(1 / b) = 5.471929e6 on the table, (20 / 450)^-5 = 5.766504e6 on the
  // line; the cycles per year are the line's damage times its N.
  const double b = std::log(1.0 / 3.0) / std::log(100.0);
  const double n_table = 1e6 * std::pow(20.0 / 30.0, 1.0 / b);
  const double n_line = std::pow(20.0 / 450.0, -5.0);
  expect_relative(n_table, 5.471929e6, 1e-6);
  const BalanceSummary a = summarise(sbl, points_at(20.0));
  const BalanceSummary t = summarise(table, points_at(20.0));
  ASSERT_TRUE(a.life && t.life);
  expect_relative(t.life->damage_per_year, a.life->damage_per_year * n_line / n_table, 1e-12);
  EXPECT_EQ(t.verdict, Verdict::unsafe);  // 40 MPa fymax against 6.8 MPa
}

}  // namespace
}  // namespace stockbridge::span
