// Life from the wind's climate: the Weibull bins (edges, probabilities summing to
// the CDF difference over the band), Miner's damage for constant stresses against
// hand computation, and validation messages.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/life.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::expect_relative;

constexpr double kDiameter = 0.03105;

LifeModel climate() { return {WeibullWind{2.0, 4.0}, 0.1}; }

/// F(U) of the Weibull wind (2, 4 m/s), written out.
double weibull_2_4(double u) { return 1.0 - std::exp(-(u / 4.0) * (u / 4.0)); }

TEST(FatigueLife, WeibullBinsHoldTheBandsProbability) {
  const WindModel wind;  // St 0.185, band 1 to 7 m/s (5.96 to 41.7 Hz for D = 31.05 mm)
  // 50 Hz lies above the band: its bin is empty
  const std::vector<double> frequencies{8.0, 12.0, 20.0, 30.0, 38.0, 50.0};
  const std::vector<LifeBin> bins = life_bins(frequencies, wind, kDiameter, climate().wind_weibull);
  ASSERT_EQ(bins.size(), frequencies.size());
  double total = 0.0;
  for (const LifeBin& bin : bins) total += bin.probability;
  expect_relative(total, weibull_2_4(7.0) - weibull_2_4(1.0), 1e-14);  // 0.8926424
  expect_relative(total, 0.8926424, 1e-6);
  EXPECT_EQ(bins.front().speed_low, 1.0);
  expect_relative(bins[1].wind_speed, 12.0 * kDiameter / 0.185, 1e-15);
  expect_relative(bins[1].speed_high, 0.5 * (12.0 + 20.0) * kDiameter / 0.185, 1e-15);  // the midpoint
  expect_relative(bins[1].probability, weibull_2_4(bins[1].speed_high) - weibull_2_4(bins[1].speed_low), 1e-14);
  EXPECT_EQ(bins.back().speed_low, 7.0);
  EXPECT_EQ(bins.back().probability, 0.0);
}

TEST(FatigueLife, MinerLifeForAConstantStress) {
  const WindModel wind;
  const SafeBorderLine line = safe_border_line(1);
  // one frequency: its bin is the whole band. 20 MPa on the one-layer line (beyond the
  // knee): N = (430 / 20)^(1 / 0.17) = 6.884514e7 cycles; a year holds
  // 20 Hz * 0.1 * 0.8926424 * 365.25 * 86400 s = 5.633931e7 cycles: life 1.221974 years.
  const std::vector<double> one{20.0};
  const LifeEstimate single = estimate_life(one, std::vector<double>{20e6}, wind, kDiameter, climate(), line);
  expect_relative(single.bins[0].cycles_to_failure, 6.884514e7, 1e-6);
  expect_relative(single.bins[0].cycles_per_year, 5.633931e7, 1e-6);
  expect_relative(single.life_years, 1.221974, 1e-6);
  expect_relative(single.damage_per_year, 1.0 / 1.221974, 1e-6);

  // several frequencies, one stress: damage = 0.1 year / N sum f_i p_i
  const std::vector<double> frequencies{10.0, 20.0, 30.0};
  const LifeEstimate several =
      estimate_life(frequencies, std::vector<double>(3, 20e6), wind, kDiameter, climate(), line);
  const double u12 = 15.0 * kDiameter / 0.185, u23 = 25.0 * kDiameter / 0.185;
  const double sum_fp = 10.0 * (weibull_2_4(u12) - weibull_2_4(1.0)) + 20.0 * (weibull_2_4(u23) - weibull_2_4(u12)) +
                        30.0 * (weibull_2_4(7.0) - weibull_2_4(u23));
  expect_relative(several.damage_per_year, 0.1 * 365.25 * 86400.0 * sum_fp / 6.884514e7, 1e-6);
}

TEST(FatigueLife, NoStressNoDamage) {
  const std::vector<double> frequencies{10.0, 20.0};
  const LifeEstimate estimate = estimate_life(frequencies, std::vector<double>{0.0, 0.0}, WindModel{}, kDiameter,
                                              climate(), safe_border_line(2));
  EXPECT_EQ(estimate.damage_per_year, 0.0);
  EXPECT_EQ(estimate.life_years, std::numeric_limits<double>::infinity());
  EXPECT_GT(estimate.bins[1].cycles_per_year, 0.0);
}

TEST(FatigueLife, ValidationNamesTheField) {
  LifeModel life = climate();
  ASSERT_NO_THROW(life.validate());
  life.wind_weibull.shape = 0.0;
  EXPECT_EQ(invalid_parameter_message([&] { life.validate(); }), "wind_weibull.shape = 0: expected a finite value > 0");
  life = climate();
  life.aeolian_fraction = 1.5;
  EXPECT_EQ(invalid_parameter_message([&] { life.validate(); }),
            "aeolian_fraction = 1.5: expected a share of the year, > 0 and <= 1");
  EXPECT_EQ(invalid_parameter_message([] { life_bins(std::vector<double>{20.0, 10.0}, WindModel{}, kDiameter, {2, 4}); }),
            "frequencies[1] = 10: expected more than the frequency before (20 Hz): strictly increasing");
  EXPECT_EQ(invalid_parameter_message([] {
              estimate_life(std::vector<double>{20.0}, std::vector<double>{}, WindModel{}, kDiameter, climate(),
                            safe_border_line(1));
            }),
            "stresses: 0 given for 1 frequencies; expected one per frequency");
}

}  // namespace
}  // namespace stockbridge::span
