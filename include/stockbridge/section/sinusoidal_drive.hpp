#pragma once
// Drives a section with a sampled sinusoidal curvature and records its
// moment-curvature loop (the `loop` command):
//     kappa_k = amplitude * sin(2 pi k / points),   k = 0 .. cycles * points,
// from the state the section is in (virgin for a new section).

#include <vector>

#include "stockbridge/section/section_law.hpp"

namespace stockbridge::section {

struct SinusoidalDrive {
  double amplitude = 0.0;  ///< curvature amplitude, 1/m, finite and >= 0
  int cycles = 2;          ///< >= 1
  int points = 400;        ///< samples per cycle, >= 4

  /// Throws InvalidParameter naming the bad field.
  void validate() const;
  /// The prescribed curvature at sample k.
  double curvature(int k) const;
};

/// The recorded loop, one entry per sample k = 0 .. cycles * points.
struct LoopRecord {
  std::vector<double> curvature;   ///< 1/m
  std::vector<double> moment;      ///< N m
  std::vector<double> dissipated;  ///< cumulative slider dissipation, J/m
  /// Dissipation over the last full cycle, J/m.
  double last_cycle_dissipation() const;
  int points_per_cycle = 0;
};

/// Applies every sample as a trial and commits it (each step is a monotone increment).
LoopRecord run_loop(SectionLaw& section, const SinusoidalDrive& drive);

}  // namespace stockbridge::section
