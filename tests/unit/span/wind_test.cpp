// Wind power into a span: MODEL.md's check values of the reduced power at
// y = 0.1, the measured laws through their published points, the extension rules
// outside them, the user table, the frequency band, and validation messages.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::expect_relative;

WindModel wind_model_of(WindLaw law) {
  WindModel wind;
  wind.law = law;
  return wind;
}

TEST(WindLaw, NamesRoundTrip) {
  for (WindLaw law : {WindLaw::cigre, WindLaw::foti, WindLaw::diana_falco_1971, WindLaw::rawlins_1983,
                      WindLaw::brika_laneville_1995, WindLaw::table}) {
    EXPECT_EQ(parse_wind_law(wind_law_name(law)), law);
  }
  EXPECT_EQ(wind_law_name(WindLaw::diana_falco_1971), "diana-falco");
  EXPECT_EQ(invalid_parameter_message([] { parse_wind_law("pon"); }),
            "law = 'pon': expected cigre, foti, diana-falco, rawlins-1983, brika-laneville or table");
}

TEST(WindLaw, CheckValuesAtATenthOfTheDiameter) {
  // MODEL.md 9: CIGRE 1.158, Diana-Falco 1.8, Rawlins 1983 1.6, Brika-Laneville 1.1,
  // each to the precision given.
  EXPECT_NEAR(wind_model_of(WindLaw::cigre).fnc(0.1), 1.158, 0.0005);  // 1.15834
  EXPECT_NEAR(wind_model_of(WindLaw::diana_falco_1971).fnc(0.1), 1.8, 0.05);
  EXPECT_NEAR(wind_model_of(WindLaw::rawlins_1983).fnc(0.1), 1.6, 0.05);
  EXPECT_NEAR(wind_model_of(WindLaw::brika_laneville_1995).fnc(0.1), 1.1, 0.05);
}

TEST(WindLaw, FotiScalesCigreByTheTurbulenceFactor) {
  WindModel foti = wind_model_of(WindLaw::foti);
  EXPECT_DOUBLE_EQ(foti.fnc(0.3), cigre_fnc(0.3));  // I_v = 0: CIGRE's
  foti.turbulence_intensity = 0.09;                 // 1 / sqrt(1 + 1)
  expect_relative(foti.fnc(0.3), cigre_fnc(0.3) / std::sqrt(2.0), 1e-14);
  foti.turbulence_intensity = 0.27;  // 1 / sqrt(1 + 9)
  expect_relative(foti.fnc(0.1), 1.15834 / std::sqrt(10.0), 1e-12);
}

TEST(WindLaw, CigreFallsThroughZeroJustAboveOneDiameter) {
  EXPECT_GT(cigre_fnc(1.02), 0.0);
  EXPECT_LT(cigre_fnc(1.025), 0.0);
  EXPECT_LT(cigre_fnc(2.0), cigre_fnc(1.5));  // and keeps falling: the amplitude is bounded
  EXPECT_DOUBLE_EQ(cigre_fnc(0.0), 0.2256);
}

TEST(WindLaw, MeasuredLawsPassThroughTheirPublishedPoints) {
  for (WindLaw law : {WindLaw::diana_falco_1971, WindLaw::rawlins_1983, WindLaw::brika_laneville_1995}) {
    const WindModel wind = wind_model_of(law);
    ASSERT_GE(published_points(law).size(), 7u) << wind_law_name(law);
    for (const WindPoint& p : published_points(law)) EXPECT_DOUBLE_EQ(wind.fnc(p.y_over_d), p.fnc);
    ASSERT_TRUE(wind.measured_range().has_value());
    EXPECT_EQ(wind.measured_range()->lo, published_points(law).front().y_over_d);
  }
  EXPECT_TRUE(published_points(WindLaw::cigre).empty());
  EXPECT_FALSE(wind_model_of(WindLaw::cigre).measured_range().has_value());
  // the ranges the curves were measured over
  EXPECT_EQ(wind_model_of(WindLaw::diana_falco_1971).measured_range()->hi, 0.8);
  EXPECT_EQ(wind_model_of(WindLaw::rawlins_1983).measured_range()->hi, 0.7);
  EXPECT_EQ(wind_model_of(WindLaw::brika_laneville_1995).measured_range()->hi, 0.4);
}

TEST(WindLaw, PointsAreExtendedToTheOriginAndHeldBeyondTheLast) {
  const WindModel rawlins = wind_model_of(WindLaw::rawlins_1983);
  EXPECT_DOUBLE_EQ(rawlins.fnc(0.0), 0.0);
  EXPECT_NEAR(rawlins.fnc(0.015), 0.09, 1e-15);  // half of 0.18 at 0.03
  EXPECT_DOUBLE_EQ(rawlins.fnc(0.7), 10.8);
  EXPECT_DOUBLE_EQ(rawlins.fnc(3.0), 10.8);
}

TEST(WindModel, TableInterpolatesBetweenTheUsersPoints) {
  WindModel wind = wind_model_of(WindLaw::table);
  wind.table = {{0.0, 0.5}, {0.2, 2.5}, {0.6, -1.5}};
  ASSERT_NO_THROW(wind.validate());
  EXPECT_DOUBLE_EQ(wind.fnc(0.0), 0.5);   // a point at y = 0 keeps its own value
  EXPECT_NEAR(wind.fnc(0.05), 1.0, 1e-14);  // 0.5 + (2.5 - 0.5) * 0.05 / 0.2
  EXPECT_NEAR(wind.fnc(0.4), 0.5, 1e-14);  // 2.5 + (-1.5 - 2.5) * 0.2 / 0.4
  EXPECT_DOUBLE_EQ(wind.fnc(0.9), -1.5);  // held beyond the last point
  wind.table = {{0.1, 2.0}, {0.3, 4.0}};
  EXPECT_NEAR(wind.fnc(0.05), 1.0, 1e-14);  // from the origin to the first point
}

TEST(WindModel, PowerOnHandNumbers) {
  // ASTER570, Y = 10 mm, f = 20 Hz, L = 400 m: y = 0.01 / 0.03105 = 0.322061,
  // fnc = 0.2256 + 0.1627 y + 101.62 y^2 - 99.73 y^3 = 7.486863,
  // P_w = 400 * 20^3 * 0.03105^4 * 7.486863 = 22.26877 W
  const Conductor c = testing::aster570();
  expect_relative(wind_model_of(WindLaw::cigre).power(0.01, 20.0, c.diameter, 400.0), 22.26877, 1e-6);
}

TEST(WindModel, FrequencyBandIsTheStrouhalFrequencyOfTheSpeedBand) {
  const WindModel wind = wind_model_of(WindLaw::cigre);  // St 0.185, 1 to 7 m/s
  const Interval band = wind.frequency_band(0.03105);
  expect_relative(band.lo, 0.185 * 1.0 / 0.03105, 1e-15);  // 5.958 Hz
  expect_relative(band.hi, 0.185 * 7.0 / 0.03105, 1e-15);  // 41.71 Hz
  expect_relative(wind.wind_speed(band.hi, 0.03105), 7.0, 1e-14);
  expect_relative(wind.wind_speed(20.0, 0.03105), 20.0 * 0.03105 / 0.185, 1e-15);  // 3.357 m/s
}

TEST(WindModel, ValidationNamesTheField) {
  EXPECT_NO_THROW(wind_model_of(WindLaw::brika_laneville_1995).validate());
  WindModel wind = wind_model_of(WindLaw::cigre);
  wind.speed_max = 0.5;
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }), "speed_max = 0.5: expected more than speed_min = 1 m/s");
  wind = wind_model_of(WindLaw::cigre);
  wind.strouhal = 0.0;
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }), "strouhal = 0: expected a finite value > 0");
  wind = wind_model_of(WindLaw::cigre);
  wind.turbulence_intensity = 0.1;
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }),
            "turbulence_intensity = 0.1: expected 0: only law = 'foti' uses it (law is 'cigre')");
  wind.law = WindLaw::foti;
  EXPECT_NO_THROW(wind.validate());
  wind = wind_model_of(WindLaw::table);
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }),
            "table: 0 point(s); expected at least 2 (y_over_d, fnc) points");
  wind.table = {{0.0, 0.2}, {0.2, 3.0}, {0.2, 4.0}};
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }),
            "table[2].y_over_d = 0.2: expected more than the point before (0.2): y_over_d strictly increasing");
  wind.table = {{-0.1, 0.2}, {0.2, 3.0}};
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }), "table[0].y_over_d = -0.1: expected a finite value >= 0");
  wind.law = WindLaw::cigre;
  EXPECT_EQ(invalid_parameter_message([&] { wind.validate(); }),
            "table: only law = 'table' uses points (law is 'cigre')");
}

}  // namespace
}  // namespace stockbridge::span
