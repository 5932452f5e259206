// The span's tension in its three forms and the span parameter on hand-computed
// numbers, and CIGRE TB 273's safe design tension by terrain category.

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/span/tension_figures.hpp"

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

}  // namespace
}  // namespace stockbridge::span
