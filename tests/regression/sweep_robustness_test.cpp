// Sweeps that once failed, kept so they never fail again. Each note says what went wrong.
// Under STOCKBRIDGE_TEST_SCALE=short (the sanitizer presets) each sweep covers the same
// band on a fifth of the points: the same solvers, retries and continuation, checked
// for memory and undefined behaviour; the full grids are the regressions proper.

#include <cmath>

#include <gtest/gtest.h>

#include "stockbridge/damper/sweep.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::damper {
namespace {

using stockbridge::testing::scaled;

/// Log-spaced frequencies from 1 to 100 Hz: `points` of them, a fifth under the short scale.
std::vector<double> band(int points) { return log_spaced(1.0, 100.0, scaled(points, points / 5)); }

int converged_points(const Damper& damper, const std::vector<double>& frequencies, double velocity) {
  SweepSpec spec;
  spec.frequencies = frequencies;
  spec.amplitudes = {velocity};
  int converged = 0;
  const std::vector<SweepRun> runs = run_sweep(damper, spec);
  for (const ImpedancePoint& p : runs.front().points) {
    converged += p.converged();
    EXPECT_TRUE(p.converged()) << p.frequency_hz << " Hz: " << p.failure;
  }
  return converged;
}

Damper stiff_low_friction(double c, double h) {
  damper::ArmDescription arm = testing::sauter_arm();
  arm.cable = cable::CableDescription::uniform(0.1875, 40, 2.8, {{c, h}});
  return testing::damper_of({arm, arm});
}

// c = 100, h = 0.2 at 0.05 m/s: near-stick states whose cable memory settles slowly.
// Newton steps taken while the memory was still settling kept disturbing it, and a
// residual tolerance of 1e-9 sat at the level of that disturbance: three points
// failed (29-30 Hz, 36 Hz). Now: settling periods without steps, tolerance 1e-8.
// A line-search failure at 5 Hz needed the sweep's smaller steps from the last
// converged frequency.
TEST(SweepRobustness, SlowlySettlingNearStickStates) {
  const std::vector<double> frequencies = band(300);
  EXPECT_EQ(converged_points(stiff_low_friction(100.0, 0.2), frequencies, 0.05), static_cast<int>(frequencies.size()));
}

// c = 200, h = 0.05 at 0.01 m/s: five points near 44 Hz needed more than the 40
// Newton iterations then allowed (the default is now 100). Still open: started cold
// at 35 Hz, the point at 38.8 Hz stalls at a residual of 3e-7 (reported, not used).
TEST(SweepRobustness, TinyAmplitudeNearTheStickResonance) {
  const std::vector<double> frequencies = band(200);
  EXPECT_EQ(converged_points(stiff_low_friction(200.0, 0.05), frequencies, 0.01), static_cast<int>(frequencies.size()));
}

// ei = 0.5 (c/ei = 40) at 0.1 m/s: natural continuation, the retry from the virgin
// state and the eight smaller steps all failed at 40.55 Hz (line search); arclength
// continuation from the last converged point follows the branch there.
TEST(SweepRobustness, ArclengthRescuesAPointNaturalContinuationMisses) {
  damper::ArmDescription arm = testing::sauter_arm();
  arm.cable = cable::CableDescription::uniform(0.1875, 40, 0.5, {{20.0, 0.7}});
  const std::vector<double> frequencies = band(200);
  EXPECT_EQ(converged_points(testing::damper_of({arm, arm}), frequencies, 0.1), static_cast<int>(frequencies.size()));
}

// The dissertation's damper asked at one frequency, 20 Hz at 0.1 m/s (a new user's
// first command): from a cold start, just below the stick resonance, Newton's line
// search failed at iteration 22. Now a first point that fails cold is approached
// from a decade below along the branch, and agrees with a sweep that reaches it.
TEST(SweepRobustness, ALonePointNearAResonanceIsReachedAsASweepReachesIt) {
  const Damper damper = testing::damper_of({testing::sauter_arm(), testing::sauter_arm()});
  // Under the short scale (sanitizers) the two points that failed cold, on a shorter sweep.
  const std::vector<double> frequencies =
      testing::short_tests() ? std::vector<double>{20.0, 68.0} : std::vector<double>{15.0, 20.0, 21.0, 22.0, 60.0, 68.0};
  for (const double f : frequencies) {
    SCOPED_TRACE(f);
    SweepSpec alone;
    alone.frequencies = {f};
    alone.amplitudes = {0.1};
    const ImpedancePoint lone = run_sweep(damper, alone).front().points.front();
    ASSERT_TRUE(lone.converged()) << lone.failure;
    SweepSpec sweep = alone;
    sweep.frequencies = log_spaced(f / 4.0, f, scaled(40, 10));
    const ImpedancePoint swept = run_sweep(damper, sweep).front().points.back();
    ASSERT_TRUE(swept.converged()) << swept.failure;
    EXPECT_NEAR(std::abs(lone.impedance - swept.impedance), 0.0, 1e-6 * std::abs(swept.impedance));
  }
}

// The design figures at 30 Hz, 0.02 m/s of the long arm of examples/asymmetric_damper.toml,
// reached cold and along sweeps from 5, 10 and 15 Hz: friction locks a different
// static offset into the cable each time (the largest |x - b phi| is 0.096 mm cold,
// up to 0.141 mm swept; the largest |curvature| 0.0051 and up to 0.014 1/m), but not
// into the oscillation, whose amplitudes the figures are.
TEST(SweepRobustness, DesignFiguresDoNotDependOnHowThePointWasReached) {
  ArmDescription arm = testing::sauter_arm();
  arm.mass = 1.4;
  arm.inertia = 0.0035;
  arm.offset = 0.04;
  arm.cable = cable::CableDescription::uniform(0.22, 40, 2.8, {{20.0, 0.7}});
  const Damper damper = testing::damper_of({arm}, 0.6);
  std::vector<ImpedancePoint> points;
  for (const double start : {30.0, 5.0, 10.0, 15.0}) {
    SweepSpec spec;
    spec.frequencies = start < 30.0 ? log_spaced(start, 30.0, 5) : std::vector<double>{30.0};
    spec.amplitudes = {0.02};
    points.push_back(run_sweep(damper, spec).front().points.back());
    ASSERT_TRUE(points.back().converged()) << "from " << start << " Hz: " << points.back().failure;
  }
  for (std::size_t i = 1; i < points.size(); ++i) {
    const ArmFigures &cold = points.front().arms[0], &swept = points[i].arms[0];
    EXPECT_NEAR(swept.mass_amplitude, cold.mass_amplitude, 1e-6 * cold.mass_amplitude) << "path " << i;
    EXPECT_NEAR(swept.clamp_curvature_amplitude, cold.clamp_curvature_amplitude, 1e-6 * cold.clamp_curvature_amplitude)
        << "path " << i;
    // The arm sticks at 30 Hz (the offset was locked in where it slipped, lower down): no power but round-off.
    EXPECT_NEAR(swept.power, cold.power, 1e-12 * 0.5 * 0.02 * 0.02 * std::abs(cold.impedance)) << "path " << i;
  }
}

}  // namespace
}  // namespace stockbridge::damper
