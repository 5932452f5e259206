// The end's nonlinear fixed point: every damper's velocity is w |Y_j| of the
// response its own impedance (at that velocity) produces.

#include <cmath>
#include <complex>
#include <numbers>

#include <gtest/gtest.h>

#include "stockbridge/span/end_fixed_point.hpp"

namespace stockbridge::span {
namespace {

using namespace std::complex_literals;

StringWave wave_at(double f) {
  const double tension = 27795.0, m = 1.571, w = 2.0 * std::numbers::pi * f;
  return {w, w / std::sqrt(tension / m), std::sqrt(tension * m)};
}

/// A softening, more damping impedance as the clamp moves faster (the shape of a
/// Stockbridge damper's Z past its stick resonance), of the order of Z0.
std::complex<double> softening(double v) { return (60.0 + 200.0 * v / (v + 0.05)) + (150.0 - 120.0 * v / (v + 0.05)) * 1i; }

TEST(EndFixedPoint, ALinearDamperIsSolvedAtOnce) {
  const StringWave wave = wave_at(20.0);
  const auto constant = [](std::size_t, double) { return std::optional<std::complex<double>>(120.0 + 30.0i); };
  const EndSolution s = solve_end(wave, {1.0}, constant, 0.01, {});
  ASSERT_TRUE(s.converged()) << brief_report(s.summary);
  const EndResponse direct = end_response(wave, {1.0}, {120.0 + 30.0i}, 0.01);
  EXPECT_NEAR(s.velocities[0], wave.angular_frequency * std::abs(direct.damper_displacement[0]), 1e-12);
}

TEST(EndFixedPoint, EachDampersVelocityIsThatOfItsOwnResponse) {
  for (const double f : {8.0, 20.0, 45.0}) {
    const StringWave wave = wave_at(f);
    const std::vector<double> positions{0.8, 1.6, 2.9};
    const auto z = [](std::size_t j, double v) { return std::optional<std::complex<double>>(softening(v) * (1.0 + 0.3 * j)); };
    for (const double antinode : {1e-4, 3e-3, 2e-2}) {
      const EndSolution s = solve_end(wave, positions, z, antinode, {});
      ASSERT_TRUE(s.converged()) << brief_report(s.summary);
      for (std::size_t j = 0; j < positions.size(); ++j) {
        EXPECT_NEAR(s.velocities[j], wave.angular_frequency * std::abs(s.response.damper_displacement[j]),
                    1e-9 * s.velocities[j]);
        EXPECT_NEAR(std::abs(s.impedances[j] - *z(j, s.velocities[j])), 0.0, 1e-12);
      }
      EXPECT_NEAR(s.response.absorbed_power, s.response.damper_power, 1e-10 * s.response.damper_power);
    }
  }
}

// The polish's balance rests on this (span/balance.cpp): with every impedance held
// fixed the end is linear, its fixed point is the response itself, and the power
// absorbed grows as the antinode amplitude squared.
TEST(EndFixedPoint, ConstantImpedancesGiveTheResponseItselfAndPowerAsTheSquare) {
  const StringWave wave = wave_at(20.0);
  const std::vector<double> positions{0.8, 1.6, 2.9};
  const std::vector<std::complex<double>> z{120.0 + 30.0i, 80.0 - 20.0i, 40.0 + 90.0i};
  const auto constant = [&](std::size_t j, double) { return std::optional<std::complex<double>>(z[j]); };
  const double per_square = end_response(wave, positions, z, 1.0).absorbed_power;
  for (const double antinode : {1e-4, 3e-3, 2e-2}) {
    const EndSolution s = solve_end(wave, positions, constant, antinode, {});
    ASSERT_TRUE(s.converged()) << brief_report(s.summary);
    const EndResponse direct = end_response(wave, positions, z, antinode);
    for (std::size_t j = 0; j < positions.size(); ++j) {
      const double v = wave.angular_frequency * std::abs(direct.damper_displacement[j]);
      EXPECT_NEAR(s.velocities[j], v, 1e-12 * v);
    }
    EXPECT_NEAR(direct.absorbed_power, per_square * antinode * antinode, 1e-12 * direct.absorbed_power);
  }
}

TEST(EndFixedPoint, AnUnknownImpedanceIsAFailureNotANumber) {
  const auto none = [](std::size_t, double v) {
    return v < 0.01 ? std::optional<std::complex<double>>(100.0) : std::nullopt;
  };
  const EndSolution s = solve_end(wave_at(20.0), {1.0}, none, 0.01, {});
  EXPECT_FALSE(s.converged());
  EXPECT_EQ(s.summary.termination, Termination::inner_failure);
  EXPECT_NE(brief_report(s.summary).find("damper 1"), std::string::npos) << brief_report(s.summary);
}

// The balance hands the fixed point the impedances' slopes (the table's own): the
// velocities are those found with central differences of Z, and Newton's steps on
// the exact Jacobian close on them in a few evaluations of the response.
TEST(EndFixedPoint, GivenSlopesTheSameVelocitiesInAFewSteps) {
  const std::vector<double> positions{0.8, 1.6, 2.9};
  const ClampImpedance z = [](std::size_t j, double v) { return std::optional<std::complex<double>>(softening(v) * (1.0 + 0.3 * j)); };
  const ClampImpedanceSlope slope = [](std::size_t j, double v) {
    // d softening / d ln v = v d softening / dv
    const double d = v * 0.05 / ((v + 0.05) * (v + 0.05));
    return std::optional<TableImpedance>(TableImpedance{softening(v) * (1.0 + 0.3 * j), (200.0 * d - 120.0 * d * 1i) * (1.0 + 0.3 * j)});
  };
  for (const double f : {8.0, 20.0, 45.0}) {
    const EndChain chain(wave_at(f), positions);
    for (const double antinode : {1e-4, 3e-3, 2e-2}) {
      const EndSolution exact = solve_end(chain, z, slope, antinode, {});
      const EndSolution differenced = solve_end(chain, z, {}, antinode, {});
      ASSERT_TRUE(exact.converged() && differenced.converged());
      EXPECT_LE(exact.summary.evaluations, 8) << f << " Hz, " << antinode << " m";
      for (std::size_t j = 0; j < positions.size(); ++j) {
        EXPECT_NEAR(exact.velocities[j], differenced.velocities[j], 1e-9 * exact.velocities[j]);
      }
    }
  }
}

}  // namespace
}  // namespace stockbridge::span
