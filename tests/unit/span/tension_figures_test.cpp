// The span's tension in its three forms and the span parameter on hand-computed
// numbers, and CIGRE TB 273's safe design tension by terrain category.

#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/span/tension_figures.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::aster570;
using testing::expect_relative;

Span aster570_span(double tension, std::optional<int> terrain) {
  FatigueSpec fatigue;
  fatigue.cycles = 5e8;
  return Span(aster570(), 400.0, tension, WindModel{}, SelfDampingModel{}, {}, fatigue, terrain);
}

TEST(TensionFigures, EveryFormOfTheTensionAndTheSpanParameter) {
  const TensionFigures t = tension_figures(aster570_span(27795.0, std::nullopt));
  EXPECT_EQ(t.tension, 27795.0);
  expect_relative(t.fraction_of_rts, 0.15, 1e-12);           // 27795 / 185300
  expect_relative(t.catenary_parameter, 1804.138, 1e-6);     // 27795 / (1.571 * 9.80665)
  expect_relative(t.span_parameter, 7.905792, 1e-6);         // 400 * 0.03105 / 1.571
}

TEST(TensionFigures, TheSafeDesignTensionOfAnUndampedSpanByTerrain) {
  EXPECT_FALSE(safe_design_tension(aster570_span(27795.0, std::nullopt)));
  // H/w = 1804 m: above every category's limit (1000, 1125, 1225, 1425 m).
  for (int category = 1; category <= 4; ++category) {
    const auto judged = safe_design_tension(aster570_span(27795.0, category));
    ASSERT_TRUE(judged);
    EXPECT_EQ(judged->terrain.category, category);
    EXPECT_FALSE(judged->within);
  }
  // At H/w = 1100 m: within the limits of categories 2 to 4 only; at the limit itself, within.
  const double weight = 1.571 * standard_gravity;
  EXPECT_FALSE(safe_design_tension(aster570_span(1100.0 * weight, 1))->within);
  EXPECT_TRUE(safe_design_tension(aster570_span(1100.0 * weight, 2))->within);
  EXPECT_TRUE(safe_design_tension(aster570_span(1425.0 * weight, 4))->within);
  EXPECT_EQ(terrain_category(1).catenary_parameter_limit, 1000.0);
  EXPECT_EQ(terrain_category(2).catenary_parameter_limit, 1125.0);
  EXPECT_EQ(terrain_category(3).catenary_parameter_limit, 1225.0);
  EXPECT_EQ(terrain_category(4).catenary_parameter_limit, 1425.0);
  EXPECT_EQ(invalid_parameter_message([] { aster570_span(27795.0, 0); }),
            "span.terrain = 0: expected an integer from 1 to 4");
}

// The turbulence intensity assumed per category: the log law at 10 m, I = 1 / ln(10 /
// z0), with z0 = 0.01, 0.05, 0.1 and 0.3 m (EN 1991-1-4's I, II, between II and III, III).
TEST(TerrainWind, TheTurbulenceIntensityOfEachCategoryIsTheLogLawAtTenMetres) {
  const double z0[] = {0.01, 0.05, 0.1, 0.3};
  for (int category = 1; category <= 4; ++category) {
    SCOPED_TRACE(category);
    const TerrainCategory& t = terrain_category(category);
    EXPECT_EQ(t.roughness_length, z0[category - 1]);
    EXPECT_DOUBLE_EQ(t.turbulence_intensity(), 1.0 / std::log(10.0 / z0[category - 1]));
  }
  EXPECT_NEAR(terrain_category(1).turbulence_intensity(), 0.14476, 1e-5);  // 1 / ln 1000
  EXPECT_NEAR(terrain_category(2).turbulence_intensity(), 0.18874, 1e-5);  // 1 / ln 200
  EXPECT_NEAR(terrain_category(3).turbulence_intensity(), 0.21715, 1e-5);  // 1 / ln 100
  EXPECT_NEAR(terrain_category(4).turbulence_intensity(), 0.28518, 1e-5);  // 1 / ln 33.3
}

// wind_law_by_terrain turns cigre into foti with the terrain's intensity: CIGRE's
// reduced power times 1 / sqrt(1 + (I / 0.09)^2).
TEST(TerrainWind, ByTerrainCigreBecomesFotiWithTheTerrainsIntensity) {
  for (int category = 1; category <= 4; ++category) {
    SCOPED_TRACE(category);
    const WindModel wind = terrain_wind(WindModel{}, category, true, false);
    const double intensity = 1.0 / std::log(10.0 / terrain_category(category).roughness_length);
    EXPECT_EQ(wind.law, WindLaw::foti);
    EXPECT_DOUBLE_EQ(wind.turbulence_intensity, intensity);
    EXPECT_EQ(wind.turbulence_terrain, category);
    for (const double y : {0.05, 0.3, 0.8}) {
      expect_relative(wind.fnc(y), cigre_fnc(y) / std::sqrt(1.0 + std::pow(intensity / 0.09, 2)), 1e-13);
    }
  }
  // Terrain 4's intensity, 0.285, takes the power to 0.30 of CIGRE's.
  expect_relative(terrain_wind(WindModel{}, 4, true, false).fnc(0.3) / cigre_fnc(0.3), 0.30096, 1e-4);
  // Without by_terrain the cigre law stays (laminar, CIGRE's), terrain or not.
  const WindModel kept = terrain_wind(WindModel{}, 2, false, false);
  EXPECT_EQ(kept.law, WindLaw::cigre);
  EXPECT_EQ(kept.turbulence_intensity, 0.0);
  EXPECT_FALSE(kept.turbulence_terrain.has_value());
}

TEST(TerrainWind, AFotiLawTakesTheTerrainsIntensityUnlessItGivesItsOwn) {
  WindModel foti;
  foti.law = WindLaw::foti;
  const WindModel from_terrain = terrain_wind(foti, 3, false, false);
  EXPECT_DOUBLE_EQ(from_terrain.turbulence_intensity, 1.0 / std::log(100.0));
  EXPECT_EQ(from_terrain.turbulence_terrain, 3);
  foti.turbulence_intensity = 0.05;
  for (const bool by_terrain : {false, true}) {
    const WindModel own = terrain_wind(foti, 3, by_terrain, true);
    EXPECT_EQ(own.law, WindLaw::foti);
    EXPECT_EQ(own.turbulence_intensity, 0.05);
    EXPECT_FALSE(own.turbulence_terrain.has_value());
  }
  // No terrain: the foti law keeps its intensity (0: CIGRE's laminar wind).
  foti.turbulence_intensity = 0.0;
  EXPECT_EQ(terrain_wind(foti, std::nullopt, false, false).turbulence_intensity, 0.0);
}

TEST(TerrainWind, ByTerrainNeedsATerrainAndALawItTurnsIntoFoti) {
  EXPECT_EQ(invalid_parameter_message([] { terrain_wind(WindModel{}, std::nullopt, true, false); }),
            "wind_law_by_terrain: the span gives no terrain (1 to 4) to take the wind's turbulence from");
  WindModel rawlins;
  rawlins.law = WindLaw::rawlins_1983;
  EXPECT_EQ(invalid_parameter_message([&] { terrain_wind(rawlins, 2, true, false); }),
            "wind_law_by_terrain: turns law cigre into foti (CIGRE's times the turbulence's reduction); the wind's "
            "law is rawlins-1983");
}

}  // namespace
}  // namespace stockbridge::span
