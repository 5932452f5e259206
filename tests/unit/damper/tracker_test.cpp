// The damper tracker: along the frequencies it is the sweep (the sweep is built on
// it); along the velocity at one frequency its warm-started solves agree with cold
// lone points; from a checkpoint a solve is a function of the excitation.

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/damper/tracker.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

Damper tracked_damper() {
  const ArmDescription arm = stockbridge::testing::sauter_arm();
  return stockbridge::testing::damper_of({arm, arm});
}

ImpedancePoint lone_point(const Damper& damper, double f, double v) {
  SweepSpec lone;
  lone.frequencies = {f};
  lone.amplitudes = {v};
  return run_sweep(damper, lone).front().points.front();
}

TEST(DamperTracker, AlongTheFrequenciesItIsTheSweep) {
  const Damper damper = tracked_damper();
  SweepSpec spec;
  spec.frequencies = log_spaced(5.0, 40.0, 30);
  spec.amplitudes = {0.1};
  const SweepRun run = run_sweep(damper, spec).front();
  DamperTracker tracker(damper, spec.solver);
  for (std::size_t i = 0; i < spec.frequencies.size(); ++i) {
    const ImpedancePoint p = tracker.solve(Excitation::from_velocity(spec.frequencies[i], 0.1));
    ASSERT_TRUE(p.converged()) << p.failure;
    EXPECT_EQ(p.impedance, run.points[i].impedance) << spec.frequencies[i] << " Hz";
  }
  EXPECT_EQ(tracker.solves(), 30);
}

// Up and down a decade and a half of velocity at the damper's slipping resonance,
// each solve from the last: Z as a cold lone point gives it.
TEST(DamperTracker, AlongTheVelocityItAgreesWithColdSolves) {
  const Damper damper = tracked_damper();
  DamperTracker tracker(damper, SolverOptions{});
  for (const double v : {0.01, 0.02, 0.05, 0.1, 0.3, 0.1, 0.03}) {
    SCOPED_TRACE(v);
    const ImpedancePoint tracked = tracker.solve(Excitation::from_velocity(12.0, v));
    const ImpedancePoint cold = lone_point(damper, 12.0, v);
    ASSERT_TRUE(tracked.converged() && cold.converged()) << tracked.failure << cold.failure;
    EXPECT_LE(std::abs(tracked.impedance - cold.impedance), 1e-6 * std::abs(cold.impedance));
  }
}

TEST(DamperTracker, FromACheckpointASolveIsAFunctionOfTheExcitation) {
  const Damper damper = tracked_damper();
  DamperTracker tracker(damper, SolverOptions{});
  ASSERT_TRUE(tracker.solve(Excitation::from_velocity(20.0, 0.05)).converged());
  const DamperTracker::Checkpoint start = tracker.checkpoint();
  const ImpedancePoint first = tracker.solve(Excitation::from_velocity(20.0, 0.08));
  tracker.solve(Excitation::from_velocity(20.0, 0.2));
  tracker.restore(start);
  const ImpedancePoint again = tracker.solve(Excitation::from_velocity(20.0, 0.08));
  ASSERT_TRUE(first.converged() && again.converged());
  EXPECT_EQ(first.impedance, again.impedance);

  DamperTracker other(stockbridge::testing::damper_of({stockbridge::testing::sauter_arm(),
                                                       stockbridge::testing::sauter_arm(20)}),
                      SolverOptions{});
  EXPECT_THROW(other.restore(start), std::invalid_argument);  // one distinct arm's checkpoint, two arms
}

}  // namespace
}  // namespace stockbridge::damper
