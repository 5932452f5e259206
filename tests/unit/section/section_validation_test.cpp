// Bad parameters are rejected with a typed error that names the quantity and value.

#include <gtest/gtest.h>

#include "support/error_message.hpp"

#include <cmath>
#include <limits>

#include "stockbridge/core/error.hpp"
#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/regularised_section.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::section {
namespace {

using testing::invalid_parameter_message;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(SectionValidation, RejectsBadStiffnessesAndSlipMoments) {
  EXPECT_EQ(invalid_parameter_message([] { MasingSection s({-1.0, {}}); }), "ei = -1: expected a finite value >= 0 (N m^2)");
  EXPECT_EQ(invalid_parameter_message([] { MasingSection s({kNaN, {}}); }), "ei = nan: expected a finite value >= 0 (N m^2)");
  EXPECT_EQ(invalid_parameter_message([] { MasingSection s({kInf, {}}); }), "ei = inf: expected a finite value >= 0 (N m^2)");
  EXPECT_EQ(invalid_parameter_message([] { MasingSection s({2.8, {{20.0, 0.0}}}); }),
            "jenkin[0].h = 0: expected a finite value > 0 (N m)");
  EXPECT_EQ(invalid_parameter_message([] { MasingSection s({2.8, {{20.0, 0.7}, {-5.0, 0.7}}}); }),
            "jenkin[1].c = -5: expected a finite value > 0 (N m^2)");
  EXPECT_EQ(invalid_parameter_message([] { MasingSection s({0.0, {}}); }),
            "ei = 0: expected a value > 0 for a section without Jenkin elements");
}

TEST(SectionValidation, RejectsBadDrivesAndExponents) {
  MasingSection section({2.8, {{20.0, 0.7}}});
  EXPECT_EQ(invalid_parameter_message([&] { run_loop(section, {0.05, 0, 400}); }), "cycles = 0: expected an integer from 1 to 100000");
  EXPECT_EQ(invalid_parameter_message([&] { run_loop(section, {0.05, 1, 3}); }), "points = 3: expected an integer from 4 to 10000000");
  EXPECT_EQ(invalid_parameter_message([&] { run_loop(section, {-0.05, 1, 400}); }),
            "amplitude = -0.05: expected a finite value >= 0 (1/m)");
  EXPECT_EQ(invalid_parameter_message([] { RegularisedSection s({2.8, {{20.0, 0.7}}}, RegularisedOptions{1.0}); }),
            "exponent = 1: expected a finite value > 1");
  EXPECT_THROW(section.set_trial_curvature(kNaN), InvalidParameter);
  EXPECT_THROW(section.set_trial_moment(kInf), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::section
