// Harmonic balance at its defaults (17 harmonics, 144 samples a period, half-wave
// symmetry) on the README's main job, the shipped example's sweep (200 frequencies
// over 1-100 Hz at 0.05 and 0.2 m/s), against a converged reference (41 harmonics,
// 1024 samples): every point within 0.1 % of |Z| (measured: 0.067 % at worst; the
// defaults before issue 18, 9 harmonics and 128 samples, were 0.44 % off, and 15
// harmonics with 128 samples 0.138 %). The reference is converged: 21 harmonics and
// 512 samples are within 1.0e-4 of it, a tenth of the tolerance.
//
// The bound holds on this grid, not at every frequency: on 1000 frequencies the
// defaults are off by more than 0.1 % at 3 of 2000 points (0.155 % at 7.57 Hz,
// 0.2 m/s, where the harmonics limit; 0.140 % at 21.5 Hz, 0.05 m/s, where the
// samples do). docs/damper.md says so.
//
// Under STOCKBRIDGE_TEST_SCALE=short every eighth frequency of the same grid.

#include <algorithm>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::damper {
namespace {

std::vector<double> example_frequencies() {
  const std::vector<double> all = log_spaced(1.0, 100.0, 200);
  const std::size_t stride = testing::scaled<std::size_t>(1, 8);
  std::vector<double> frequencies;
  for (std::size_t i = 0; i < all.size(); i += stride) frequencies.push_back(all[i]);
  return frequencies;
}

/// Z of every point of the example sweep (both amplitudes in turn), each converged.
std::vector<std::complex<double>> example_sweep(int harmonics, int samples) {
  static const Damper damper =
      io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml");
  SweepSpec spec;
  spec.frequencies = example_frequencies();
  spec.amplitudes = {0.2, 0.05};
  if (harmonics > 0) {
    spec.solver.harmonic_balance.harmonics = harmonics;
    spec.solver.harmonic_balance.samples = samples;
  }
  std::vector<std::complex<double>> z;
  for (const SweepRun& run : run_sweep(damper, spec)) {
    for (const ImpedancePoint& p : run.points) {
      EXPECT_TRUE(p.converged()) << p.frequency_hz << " Hz, " << run.amplitude << " m/s: " << p.failure;
      z.push_back(p.impedance);
    }
  }
  return z;
}

/// The largest |z - reference| / |reference| over the points.
double largest_relative_error(const std::vector<std::complex<double>>& z,
                              const std::vector<std::complex<double>>& reference) {
  double largest = 0.0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    largest = std::max(largest, std::abs(z[i] - reference[i]) / std::abs(reference[i]));
  }
  return largest;
}

TEST(DefaultAccuracy, TheExampleSweepIsWithinATenthOfAPercentOfAConvergedReference) {
  const std::vector<std::complex<double>> reference = example_sweep(41, 1024);
  const std::vector<std::complex<double>> refined = example_sweep(21, 512);
  const std::vector<std::complex<double>> defaults = example_sweep(0, 0);
  ASSERT_EQ(defaults.size(), reference.size());
  ASSERT_EQ(refined.size(), reference.size());
  EXPECT_LT(largest_relative_error(refined, reference), 2e-4) << "the reference is not converged";
  EXPECT_LT(largest_relative_error(defaults, reference), 1e-3);
}

}  // namespace
}  // namespace stockbridge::damper
