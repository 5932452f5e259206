// The damper's linear clamp impedance Z = j w M_eff(w): the closed form of uniform
// linear arms (tests/support, nothing from the library), the whole mass at 0 Hz,
// zeros at the clamp-free frequencies and poles at the clamp-held ones.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "stockbridge/damper/linear_impedance.hpp"
#include "stockbridge/damper/modes.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

constexpr double kImpedanceTwoPi = 2.0 * std::numbers::pi;

/// Sauter's arm and a shorter, lighter one: no two arms alike.
Damper two_unlike_arms() {
  ArmDescription short_arm = stockbridge::testing::sauter_arm();
  short_arm.name = "short";
  short_arm.mass = 0.6;
  short_arm.inertia = 0.0011;
  short_arm.cable.length = 0.14;
  return stockbridge::testing::damper_of({stockbridge::testing::sauter_arm(), short_arm}, 0.7);
}

TEST(LinearImpedance, StickingIsTheClosedFormOfUniformLinearArms) {
  const Damper damper = two_unlike_arms();
  const LinearImpedance stick(damper, CableLimit::stick);
  const LinearImpedance slip(damper, CableLimit::slip);
  for (const double f : {0.5, 3.0, 11.0, 27.0, 45.0, 80.0, 150.0}) {
    const std::complex<double> expected_stick = stockbridge::testing::linear_impedance(damper, {22.8, 22.8}, f);
    const std::complex<double> expected_slip = stockbridge::testing::linear_impedance(damper, {2.8, 2.8}, f);
    EXPECT_EQ(stick.impedance(kImpedanceTwoPi * f).real(), 0.0);
    EXPECT_NEAR(stick.impedance(kImpedanceTwoPi * f).imag(), expected_stick.imag(), 1e-9 * std::abs(expected_stick)) << f;
    EXPECT_NEAR(slip.impedance(kImpedanceTwoPi * f).imag(), expected_slip.imag(), 1e-9 * std::abs(expected_slip)) << f;
  }
}

TEST(LinearImpedance, AtZeroFrequencyItIsTheWholeMass) {
  const Damper damper = two_unlike_arms();
  const LinearImpedance stick(damper, CableLimit::stick);
  EXPECT_DOUBLE_EQ(stick.total_mass(), 0.7 + 0.856 + 0.6);
  EXPECT_NEAR(stick.effective_mass(1e-6), stick.total_mass(), 1e-12 * stick.total_mass());
}

TEST(LinearImpedance, ZerosAtTheClampFreeFrequenciesPolesAtTheClampHeldOnes) {
  const Damper damper = two_unlike_arms();
  const LinearImpedance stick(damper, CableLimit::stick);
  const LimitModes modes = linear_modes(damper, CableLimit::stick);
  for (const DamperMode& mode : modes.damper) {
    const double w = kImpedanceTwoPi * mode.frequency_hz;
    // A simple zero: M_eff changes sign across it and is small at it.
    EXPECT_LT(stick.effective_mass(w * (1.0 - 1e-6)) * stick.effective_mass(w * (1.0 + 1e-6)), 0.0) << mode.frequency_hz;
    EXPECT_LT(std::abs(stick.effective_mass(w)), 1e-7 * stick.total_mass()) << mode.frequency_hz;
  }
  ASSERT_EQ(stick.held_angular_frequencies().size(), 4u);
  for (std::size_t k = 0; k < modes.arms.size(); ++k) {
    for (int i = 0; i < 2; ++i) {
      const double w = kImpedanceTwoPi * modes.arms[k].frequencies_hz(i);
      EXPECT_GT(std::abs(stick.effective_mass(w * (1.0 + 1e-9))), 1e6 * stick.total_mass());
    }
  }
  EXPECT_EQ(stick.held_modes_below(0.5 * stick.held_angular_frequencies()[0]), 0);
  EXPECT_EQ(stick.held_modes_below(stick.held_angular_frequencies()[1] * (1.0 + 1e-12)), 2);
  EXPECT_EQ(stick.held_modes_below(1e9), 4);
}

}  // namespace
}  // namespace stockbridge::damper
