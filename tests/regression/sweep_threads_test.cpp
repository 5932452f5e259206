// The sweep on several threads (sweep.hpp: the continuation blocks, amplitudes x
// stretches of frequencies x distinct arms, go to parallel threads) gives exactly
// what it gives on one: each block is computed alone, in the same order, whichever
// thread takes it; and blocks give what one continuation per amplitude gives. The
// ThreadSanitizer preset (`ctest --preset tsan`) runs the tests here with "Threads"
// in their names.

#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/damper/sweep.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::damper {
namespace {

/// Three arms, two of them identical (one run serves both) and one different in
/// every respect: two distinct arms, so amplitudes x 2 runs.
Damper two_kinds_of_arm() {
  const ArmDescription left = testing::sauter_arm(20);
  ArmDescription right = left;
  right.name = "right";
  right.mass = 0.6;
  right.inertia = 0.0011;
  right.offset = 0.025;
  right.cable = cable::CableDescription::uniform(0.15, 20, 3.5, {{25.0, 0.5}});
  ArmDescription twin = left;
  twin.name = "twin";
  return testing::damper_of({left, right, twin});
}

SweepSpec spec_with_threads(int threads) {
  SweepSpec spec;
  spec.frequencies = log_spaced(5.0, 60.0, stockbridge::testing::scaled(24, 8));
  spec.amplitudes = {0.02, 0.1, 0.2};
  spec.threads = threads;
  spec.block_points = stockbridge::testing::scaled(6, 4);  // two to four continuation blocks per amplitude
  return spec;
}

void expect_same_points(const ImpedancePoint& a, const ImpedancePoint& b) {
  EXPECT_EQ(a.frequency_hz, b.frequency_hz);
  EXPECT_EQ(a.velocity_amplitude, b.velocity_amplitude);
  EXPECT_EQ(a.displacement_amplitude, b.displacement_amplitude);
  EXPECT_EQ(a.termination, b.termination);
  EXPECT_EQ(a.impedance, b.impedance);
  EXPECT_EQ(a.power, b.power);
  EXPECT_EQ(a.dissipated_power, b.dissipated_power);
  EXPECT_EQ(a.energy_error, b.energy_error);
  EXPECT_EQ(a.residual, b.residual);
  EXPECT_EQ(a.newton_iterations, b.newton_iterations);
  EXPECT_EQ(a.periods, b.periods);
  EXPECT_EQ(a.failure, b.failure);
  EXPECT_EQ(a.note, b.note);
  EXPECT_EQ(a.non_unique, b.non_unique);
}

// Two and four threads (four: more threads than the six runs can keep busy at the
// end) against one, every number bit for bit. The progress callback, whose calls the
// sweep serialises, counts in a plain int: a race there is ThreadSanitizer's to find.
TEST(SweepThreads, ThreadsGiveExactlyTheSingleThreadResult) {
  const Damper damper = two_kinds_of_arm();
  const std::vector<SweepRun> serial = run_sweep(damper, spec_with_threads(1));
  ASSERT_EQ(serial.size(), 3u);
  int converged = 0;
  for (const SweepRun& run : serial) {
    for (const ImpedancePoint& p : run.points) converged += p.converged();
  }
  EXPECT_EQ(converged, 3 * static_cast<int>(spec_with_threads(1).frequencies.size()));
  for (const int threads : {2, 4}) {
    SCOPED_TRACE(threads);
    const SweepSpec spec = spec_with_threads(threads);
    int calls = 0, last_done = 0, last_total = 0;
    const std::vector<SweepRun> parallel = run_sweep(damper, spec, [&](int done, int total) {
      ++calls;
      EXPECT_EQ(done, last_done + 1);
      last_done = done;
      last_total = total;
    });
    EXPECT_EQ(calls, 3 * static_cast<int>(spec.frequencies.size()));  // points: amplitudes x frequencies
    EXPECT_EQ(last_total, calls);
    ASSERT_EQ(parallel.size(), serial.size());
    for (std::size_t a = 0; a < serial.size(); ++a) {
      SCOPED_TRACE(serial[a].amplitude);
      EXPECT_EQ(parallel[a].amplitude, serial[a].amplitude);
      ASSERT_EQ(parallel[a].points.size(), serial[a].points.size());
      for (std::size_t i = 0; i < serial[a].points.size(); ++i) expect_same_points(parallel[a].points[i], serial[a].points[i]);
    }
  }
}

// The streamed sweep hands each point on once, in the runs' order (amplitude by
// amplitude, each frequency in turn), on several threads too, with exactly the
// gathered sweep's numbers and flags; a sink that throws stops the sweep and its
// exception comes back, no point handed on after it.
TEST(SweepThreads, StreamedPointsComeInOrderWithTheGatheredNumbers) {
  const Damper damper = two_kinds_of_arm();
  const std::vector<SweepRun> gathered = run_sweep(damper, spec_with_threads(1));
  for (const int threads : {1, 2, 4}) {
    SCOPED_TRACE(threads);
    const SweepSpec spec = spec_with_threads(threads);
    std::size_t next = 0;
    stream_sweep(damper, spec, [&](std::size_t a, std::size_t i, ImpedancePoint&& point) {
      EXPECT_EQ(a * spec.frequencies.size() + i, next++);
      expect_same_points(point, gathered.at(a).points.at(i));
    });
    EXPECT_EQ(next, spec.amplitudes.size() * spec.frequencies.size());

    int handed_on = 0;
    try {
      stream_sweep(damper, spec, [&](std::size_t, std::size_t, ImpedancePoint&&) {
        if (++handed_on == 5) throw std::runtime_error("the sink stops");
      });
      ADD_FAILURE() << "the sink's exception did not come back";
    } catch (const std::runtime_error& error) {
      EXPECT_STREQ(error.what(), "the sink stops");
    }
    EXPECT_EQ(handed_on, 5);
  }
}

// Cutting each amplitude's sweep into continuation blocks (each from a cold start
// one frequency before it) finds the same steady states as one continuation.
TEST(SweepThreads, ContinuationBlocksAgreeWithOneContinuation) {
  const Damper damper = two_kinds_of_arm();
  SweepSpec blocks = spec_with_threads(2), whole = spec_with_threads(2);
  whole.block_points = 0;
  const std::vector<SweepRun> a = run_sweep(damper, blocks), b = run_sweep(damper, whole);
  for (std::size_t r = 0; r < a.size(); ++r) {
    for (std::size_t i = 0; i < a[r].points.size(); ++i) {
      ASSERT_TRUE(a[r].points[i].converged() && b[r].points[i].converged());
      EXPECT_LT(std::abs(a[r].points[i].impedance - b[r].points[i].impedance), 1e-6 * std::abs(b[r].points[i].impedance))
          << a[r].points[i].frequency_hz << " Hz at " << a[r].amplitude;
    }
  }
}

}  // namespace
}  // namespace stockbridge::damper
