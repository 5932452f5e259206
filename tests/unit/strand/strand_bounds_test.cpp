// Strand bending-stiffness bounds (MODEL.md section 7): closed forms, the
// no-slip stiffness cross-checked against wire-by-wire parallel-axis sums,
// monotonicity in the lay length, and validation messages.

#include <gtest/gtest.h>

#include "support/error_message.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/strand_file.hpp"
#include "stockbridge/strand/strand_bounds.hpp"

namespace stockbridge::strand {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 210e9;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// A lay length so long that tan alpha underflows: cos alpha == 1 exactly (straight wires).
constexpr double kStraight = std::numeric_limits<double>::max();

/// The 19-wire strand of examples/strand_19wire.toml: 1 + 6 + 12 wires of radius 1 mm
/// on pitch radii 2 mm and 4 mm, lay lengths 60 mm and 100 mm.
Strand nineteen_wire(double lay1 = 0.060, double lay2 = 0.100) {
  return Strand{0.001, kE, {{6, 0.001, 0.002, lay1}, {12, 0.001, 0.004, lay2}}};
}

using testing::invalid_parameter_message;

void expect_relative(double actual, double expected, double tolerance) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected))
      << "actual " << actual << ", expected " << expected;
}

TEST(StrandBounds, MinimumOfNineteenWiresIsNineteenFreeWires) {
  // 19 E pi r^4 / 4 with r = 1 mm, E = 210 GPa: 3.1337 N m^2, whatever the lay.
  const double expected = 19.0 * kE * kPi * std::pow(0.001, 4) / 4.0;
  expect_relative(strand_bounds(nineteen_wire()).ei_min, expected, 1e-9);
  expect_relative(strand_bounds(nineteen_wire(0.03, 0.06)).ei_min, expected, 1e-9);  // lay angles 23 degrees
}

TEST(StrandBounds, MaximumOfStraightLayerMatchesParallelAxisFormula) {
  // cos alpha = 1: EI_max = E (pi rc^4/4 + N (pi r^4/4 + pi r^2 R^2 / 2)).
  const double rc = 0.0012;
  const double r = 0.0009;
  const double R = 0.0021;
  const Strand strand{rc, kE, {{6, r, R, kStraight}}};
  const double hand = kE * (kPi * std::pow(rc, 4) / 4.0 + 6.0 * (kPi * std::pow(r, 4) / 4.0 + kPi * r * r * R * R / 2.0));
  expect_relative(strand_bounds(strand).ei_max, hand, 1e-12);
  EXPECT_LT(lay_angle(strand.layers[0]), 1e-300);  // tan alpha underflows to a denormal
}

TEST(StrandBounds, StraightMaximumEqualsWireByWireSteinerSum) {
  // Two ways to the same number: for straight wires the no-slip stiffness is the
  // sum over the wires of E (pi r^4/4 + A y_i^2), y_i the wire's distance from the
  // bending axis, for any orientation theta of the strand (N >= 3 wires per layer).
  const Strand strand{0.001, kE, {{6, 0.001, 0.002, kStraight}, {12, 0.001, 0.004, kStraight}}};
  const double formula = strand_bounds(strand).ei_max;
  for (const double theta : {0.0, 0.1, 0.7, 2.0}) {
    double sum = kPi * std::pow(strand.core_radius, 4) / 4.0;
    for (const StrandLayer& layer : strand.layers) {
      for (int i = 0; i < layer.count; ++i) {
        const double y = layer.pitch_radius * std::sin(theta + 2.0 * kPi * i / layer.count);
        sum += kPi * std::pow(layer.wire_radius, 4) / 4.0 + kPi * layer.wire_radius * layer.wire_radius * y * y;
      }
    }
    expect_relative(formula, kE * sum, 1e-12);
  }
}

// Lay lengths chosen for exact lay angles: lambda = 2 pi R sqrt(3) gives tan alpha =
// 1/sqrt(3), alpha = 30 degrees, cos^3 alpha = 3 sqrt(3) / 8; lambda = 2 pi R 4/3 gives
// tan alpha = 3/4, cos alpha = 4/5, cos^3 alpha = 64/125. Each layer adds its straight
// share E N (pi r^4/4 + pi r^2 R^2 / 2) (the parallel-axis sum above) times cos^3 alpha.
TEST(StrandBounds, MaximumOfHelicalLayersCarriesCosCubedOfTheLayAngle) {
  const double lay1 = 2.0 * kPi * 0.002 * std::sqrt(3.0), lay2 = 2.0 * kPi * 0.004 * 4.0 / 3.0;
  const Strand helical = nineteen_wire(lay1, lay2);
  EXPECT_NEAR(lay_angle(helical.layers[0]), kPi / 6.0, 1e-15);
  EXPECT_NEAR(lay_angle(helical.layers[1]), std::atan2(3.0, 4.0), 1e-15);
  const double r = 0.001;
  auto straight_share = [&](int count, double pitch_radius) {
    return kE * count * (kPi * std::pow(r, 4) / 4.0 + kPi * r * r * pitch_radius * pitch_radius / 2.0);
  };
  const double core = kE * kPi * std::pow(r, 4) / 4.0;
  const double inner = straight_share(6, 0.002) * 3.0 * std::sqrt(3.0) / 8.0;
  const double outer = straight_share(12, 0.004) * 64.0 / 125.0;
  expect_relative(strand_bounds(Strand{r, kE, {{6, r, 0.002, lay1}}}).ei_max, core + inner, 1e-12);
  expect_relative(strand_bounds(helical).ei_max, core + inner + outer, 1e-12);
  expect_relative(strand_bounds(helical).ei_min, 19.0 * core, 1e-12);  // the minimum does not see the lay
}

TEST(StrandBounds, MaximumExceedsMinimum) {
  const StrandBounds bounds = strand_bounds(nineteen_wire());
  EXPECT_GT(bounds.ei_max, bounds.ei_min);
  EXPECT_GT(bounds.ei_max, 10.0 * bounds.ei_min);  // the dissertation's cable: 66.28 vs 3.19
}

TEST(StrandBounds, MaximumDecreasesAsTheLayLengthShortens) {
  double previous = strand_bounds(nineteen_wire(kStraight, kStraight)).ei_max;
  for (double lay = 10.0; lay >= 0.026; lay *= 0.8) {  // down to 44 degrees in the outer layer
    const double current = strand_bounds(nineteen_wire(lay, lay)).ei_max;
    EXPECT_LT(current, previous) << "lay length " << lay << " m";
    previous = current;
  }
  // and tends to the straight-wire value as the lay length grows
  expect_relative(strand_bounds(nineteen_wire(1e6, 1e6)).ei_max,
                  strand_bounds(nineteen_wire(kStraight, kStraight)).ei_max, 1e-9);
}

TEST(StrandBounds, SingleWireHasEqualBoundsAndScalesWithE) {
  const StrandBounds steel = strand_bounds(Strand{0.002, kE, {}});
  EXPECT_DOUBLE_EQ(steel.ei_min, kE * kPi * std::pow(0.002, 4) / 4.0);
  EXPECT_DOUBLE_EQ(steel.ei_max, steel.ei_min);
  const StrandBounds aluminium = strand_bounds(Strand{0.002, 70e9, {}});
  EXPECT_DOUBLE_EQ(aluminium.ei_min, steel.ei_min / 3.0);
  EXPECT_EQ(Strand{}.youngs_modulus, 210e9);
}

// Sizes a double cannot hold the stiffness of: r^4 overflows (a 1e100 m core), or
// underflows to zero (1e-300 m: 0 < ei_min failed, a fuzzing finding) or to
// subnormals (1e-80 m: ei of order 1e-310, a few digits left). A NumericalError,
// not bounds that break 0 < ei_min <= ei_max.
TEST(StrandBounds, SizesOutsideADoublesRangeAreANumericalError) {
  for (const double radius : {1e100, 1e-300, 1e-80}) {
    EXPECT_THROW(strand_bounds(Strand{radius, kE, {}}), NumericalError) << radius;
  }
  EXPECT_GT(strand_bounds(Strand{1e-70, kE, {}}).ei_min, 0.0);  // 1.6e-269 N m^2: still normal
}

TEST(StrandValidation, NamesTheFieldTheValueAndTheExpectation) {
  auto with = [](const std::function<void(Strand&)>& change) {
    Strand strand = nineteen_wire();
    change(strand);
    return invalid_parameter_message([&] { strand_bounds(strand); });
  };
  EXPECT_EQ(with([](Strand& s) { s.layers[1].lay_length = -0.05; }),
            "layer[1].lay_length = -0.05: expected a finite value > 0 (m)");
  EXPECT_EQ(with([](Strand& s) { s.layers[1].lay_length = kInf; }),
            "layer[1].lay_length = inf: expected a finite value > 0 (m)");
  EXPECT_EQ(with([](Strand& s) { s.layers[0].wire_radius = 0.0; }),
            "layer[0].wire_radius = 0: expected a finite value > 0 (m)");
  EXPECT_EQ(with([](Strand& s) { s.layers[0].pitch_radius = kNaN; }),
            "layer[0].pitch_radius = nan: expected a finite value > 0 (m)");
  EXPECT_EQ(with([](Strand& s) { s.layers[1].count = 0; }), "layer[1].count = 0: expected an integer from 1 to 1000");
  EXPECT_EQ(with([](Strand& s) { s.core_radius = -0.001; }), "core_radius = -0.001: expected a finite value > 0 (m)");
  EXPECT_EQ(with([](Strand& s) { s.youngs_modulus = 0.0; }), "youngs_modulus = 0: expected a finite value > 0 (Pa)");
  EXPECT_EQ(invalid_parameter_message([] { validate(Strand{}); }), "core_radius = 0: expected a finite value > 0 (m)");
  EXPECT_NO_THROW(validate(nineteen_wire()));
}

// Impossible geometry (a fuzzing finding: wires of 5 mm radius on a 2 mm pitch radius
// gave ei_min > ei_max): each layer outside the one below, room for its wires, and a
// lay angle below 45 degrees.
TEST(StrandValidation, RejectsImpossibleGeometry) {
  auto with = [](const std::function<void(Strand&)>& change) {
    Strand strand = nineteen_wire();
    change(strand);
    return invalid_parameter_message([&] { strand_bounds(strand); });
  };
  EXPECT_EQ(with([](Strand& s) { s.layers[0].wire_radius = 0.005; }).rfind("layer[0].pitch_radius = 0.002: expected at least 0.006 m", 0), 0u);
  EXPECT_EQ(with([](Strand& s) { s.layers[1].pitch_radius = 0.0035; }).rfind("layer[1].pitch_radius = 0.0035: expected at least 0.004 m", 0), 0u);
  EXPECT_EQ(with([](Strand& s) { s.layers[0].count = 7; }).rfind("layer[0].pitch_radius = 0.002: expected room for 7 wires", 0), 0u);
  EXPECT_EQ(with([](Strand& s) { s.layers[1].lay_length = 0.025; }).rfind("layer[1].lay_length = 0.025: expected more than 2 pi", 0), 0u);
  // Hand-rounded data within 2 % passes: 1 + 6 wires of 1.25 mm written as pitch 2.5 mm - 1 %.
  EXPECT_NO_THROW(validate(Strand{0.00125, kE, {{6, 0.00125, 0.002475, 0.08}}}));
}

// Over many possible strands (radii, counts that fit, lay angles up to 45 degrees) the
// no-slip bound is never below the free-wire bound.
TEST(StrandBounds, MaximumIsNeverBelowMinimumForPossibleGeometry) {
  std::uint64_t state = 12345;
  auto uniform = [&state](double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int trial = 0; trial < 2000; ++trial) {
    Strand strand{uniform(1e-5, 2e-3), kE, {}};
    double inner = strand.core_radius;
    for (int j = 0; j < 3; ++j) {
      const double r = uniform(1e-5, 2e-3);
      const double R = (inner + r) * uniform(1.0, 1.5);
      const int count = std::clamp(static_cast<int>(std::floor(kPi / std::asin(std::min(1.0, r / R)))), 1, 1000);
      strand.layers.push_back({count, r, R, 2.0 * kPi * R * uniform(1.0001, 20.0)});
      inner = R + r;
    }
    try {
      validate(strand);
    } catch (const InvalidParameter& e) {
      FAIL() << "trial " << trial << ": " << e.what();
    }
    const StrandBounds b = strand_bounds(strand);
    ASSERT_LE(b.ei_min, b.ei_max) << "trial " << trial;
  }
}

TEST(StrandFile, ReadsTheShippedExample) {
  const Strand strand = io::read_strand_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/strand_19wire.toml");
  EXPECT_EQ(strand.youngs_modulus, 210e9);
  EXPECT_EQ(strand.core_radius, 0.001);
  ASSERT_EQ(strand.layers.size(), 2u);
  EXPECT_EQ(strand.layers[0].count, 6);
  EXPECT_EQ(strand.layers[1].count, 12);
  EXPECT_EQ(strand.layers[1].pitch_radius, 0.004);
  EXPECT_EQ(strand.layers[0].lay_length, 0.060);
  EXPECT_EQ(strand.layers[1].lay_length, 0.100);
  EXPECT_THROW(io::read_strand_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/no-such-strand.toml"), InputError);
}

}  // namespace
}  // namespace stockbridge::strand
