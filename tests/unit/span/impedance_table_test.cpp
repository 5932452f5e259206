// The span's impedance table: which frequencies it solves, that its solved columns
// are the sweep's, and that the others lie on the line in log f between them.

#include <cmath>

#include <gtest/gtest.h>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/span/impedance_table.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::span {
namespace {

TEST(ImpedanceTableColumns, AreTheFewestAtMostTheRatioApart) {
  const std::vector<double> f = damper::log_spaced(6.0, 42.0, 100);
  for (const double ratio : {1.0, 1.05, 1.2, 2.0, 10.0}) {
    SCOPED_TRACE(ratio);
    const std::vector<std::size_t> solved = ImpedanceTable::solved_frequencies(f, ratio);
    ASSERT_GE(solved.size(), 2u);
    EXPECT_EQ(solved.front(), 0u);
    EXPECT_EQ(solved.back(), f.size() - 1);
    for (std::size_t k = 1; k < solved.size(); ++k) {
      const std::size_t a = solved[k - 1], b = solved[k];
      EXPECT_TRUE(b == a + 1 || f[b] <= ratio * f[a]) << a << " to " << b;
      if (b + 1 < f.size()) {
        EXPECT_GT(f[b + 1], ratio * f[a]) << "one more would fit after " << a;
      }
    }
  }
  EXPECT_EQ(ImpedanceTable::solved_frequencies(f, 1.0).size(), f.size());
}

TEST(ImpedanceTableColumns, InterpolateLinearlyInLogFrequencyBetweenTheSolvedOnes) {
  const damper::Damper damper =
      stockbridge::testing::damper_of({stockbridge::testing::sauter_arm(), stockbridge::testing::sauter_arm()});
  const std::vector<double> f = damper::log_spaced(10.0, 14.0, 7);
  ImpedanceTableOptions options;
  options.velocities = 5;
  options.column_ratio = 1.12;  // solves 10, 11.2, 12.5, 14 Hz (indices 0, 2, 4, 6)
  const ImpedanceTable table(damper, f, options);
  ASSERT_EQ(ImpedanceTable::solved_frequencies(f, options.column_ratio), (std::vector<std::size_t>{0, 2, 4, 6}));
  EXPECT_EQ(table.nodes(), 4 * 5);
  EXPECT_EQ(table.failed_nodes(), 0);
  for (const double v : {0.002, 0.05, 0.3}) {
    SCOPED_TRACE(v);
    for (const std::size_t i : {1u, 3u, 5u}) {
      const double t = std::log(f[i] / f[i - 1]) / std::log(f[i + 1] / f[i - 1]);
      const auto lo = table.at(i - 1, v), mid = table.at(i, v), hi = table.at(i + 1, v);
      ASSERT_TRUE(lo && mid && hi);
      EXPECT_LE(std::abs(*mid - ((1.0 - t) * *lo + t * *hi)), 1e-12 * std::abs(*mid));
    }
    // A solved column is the sweep's own point at a node velocity.
    damper::SweepSpec lone;
    lone.frequencies = {f[0]};
    lone.amplitudes = {table.velocities()[2]};
    const damper::ImpedancePoint direct = damper::run_sweep(damper, lone).front().points.front();
    EXPECT_LE(std::abs(*table.at(0, table.velocities()[2]) - direct.impedance), 1e-9 * std::abs(direct.impedance));
  }
  EXPECT_THROW(table.at(7, 0.1), std::out_of_range);
}

// The span's fixed point takes dZ/d(ln v) from the table: the interpolant's own
// derivative, against central differences of at(), at a solved and an interpolated
// frequency; zero where Z is held beyond the nodes.
TEST(ImpedanceTableColumns, GiveTheSlopeOfTheirInterpolant) {
  const damper::Damper damper =
      stockbridge::testing::damper_of({stockbridge::testing::sauter_arm(), stockbridge::testing::sauter_arm()});
  const std::vector<double> f = damper::log_spaced(10.0, 14.0, 7);
  ImpedanceTableOptions options;
  options.velocities = 5;
  options.column_ratio = 1.12;
  const ImpedanceTable table(damper, f, options);
  for (const std::size_t i : {0u, 3u}) {
    for (const double v : {0.0021, 0.013, 0.05, 0.31, 1.7}) {
      SCOPED_TRACE(::testing::Message() << f[i] << " Hz, " << v << " m/s");
      const auto at = table.at_with_slope(i, v);
      ASSERT_TRUE(at);
      EXPECT_EQ(at->z, *table.at(i, v));
      const double h = 1e-6;
      const std::complex<double> difference = (*table.at(i, v * std::exp(h)) - *table.at(i, v * std::exp(-h))) / (2.0 * h);
      EXPECT_NEAR(std::abs(at->slope - difference), 0.0, 1e-6 * std::max(1.0, std::abs(difference)));
      EXPECT_GT(std::abs(at->slope), 0.0);
    }
    for (const double v : {1e-4, 10.0}) {  // below the lowest node and above the highest: held
      const auto at = table.at_with_slope(i, v);
      ASSERT_TRUE(at);
      EXPECT_EQ(at->slope, std::complex<double>(0.0));
    }
  }
}

}  // namespace
}  // namespace stockbridge::span
