// Sweeps that once failed, kept so they never fail again. Each note says what went wrong.

#include <gtest/gtest.h>

#include "stockbridge/damper/sweep.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

int converged_points(const Damper& damper, std::vector<double> frequencies, double velocity) {
  SweepSpec spec;
  spec.frequencies = std::move(frequencies);
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
  EXPECT_EQ(converged_points(stiff_low_friction(100.0, 0.2), log_spaced(1.0, 100.0, 300), 0.05), 300);
}

// c = 200, h = 0.05 at 0.01 m/s: five points near 44 Hz needed more than the 40
// Newton iterations then allowed (the default is now 100). Still open: started cold
// at 35 Hz, the point at 38.8 Hz stalls at a residual of 3e-7 (reported, not used).
TEST(SweepRobustness, TinyAmplitudeNearTheStickResonance) {
  EXPECT_EQ(converged_points(stiff_low_friction(200.0, 0.05), log_spaced(1.0, 100.0, 200), 0.01), 200);
}

// ei = 0.5 (c/ei = 40) at 0.1 m/s: natural continuation, the retry from the virgin
// state and the eight smaller steps all failed at 40.55 Hz (line search); arclength
// continuation from the last converged point follows the branch there.
TEST(SweepRobustness, ArclengthRescuesAPointNaturalContinuationMisses) {
  damper::ArmDescription arm = testing::sauter_arm();
  arm.cable = cable::CableDescription::uniform(0.1875, 40, 0.5, {{20.0, 0.7}});
  EXPECT_EQ(converged_points(testing::damper_of({arm, arm}), log_spaced(1.0, 100.0, 200), 0.1), 200);
}

}  // namespace
}  // namespace stockbridge::damper
