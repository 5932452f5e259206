#pragma once
// The request layer for experiment (a) or (b) on a cable (`stockbridge cycle`,
// Python's cycle): the drive by the command's names, the experiment run from the
// virgin cable, its samples as the rows of the cycle table, the summary, and the
// warnings (a drive beyond the small deflections the cantilever model assumes).

#include <string>
#include <vector>

#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/experiment.hpp"
#include "stockbridge/core/warning.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

struct CycleRequest {
  std::string experiment = "a";  ///< a: tip deflection x = A sin(2 pi k / points); b: tip rotation phi
  double amplitude = 0.0;        ///< A: m for (a), rad for (b)
  int cycles = 2;
  int points = 400;              ///< samples per cycle
};

/// The drive (InvalidParameter naming "experiment", "amplitude", "cycles", "points").
cable::ExperimentDrive experiment_drive(const CycleRequest& request);

struct CycleResult {
  cable::ExperimentDrive drive;
  cable::ExperimentRecord record;
  std::vector<Warning> warnings;  ///< an amplitude beyond the small deflections (a unit mistake?)
};

/// Runs the experiment on the virgin cable.
CycleResult run_cycle(const cable::Cable& cable, const CycleRequest& request);

/// One sample of the record.
struct CycleSample {
  const cable::ExperimentSample* sample = nullptr;
  std::size_t step = 0;
};
std::vector<CycleSample> cycle_samples(const CycleResult& result);

/// The cycle CSV's quantities: step, x_m, phi_rad, force_n, clamp_moment_n_m,
/// tip_moment_n_m, dissipated_energy_j (NaN where the sample did not converge),
/// newton_iterations, residual_rad, converged.
Table<CycleSample> cycle_table();

/// The --json summary: the drive, the last cycle's energies, the extremes, the
/// Newton iterations, the failed samples and the warnings.
io::JsonObject cycle_summary(const CycleRequest& request, const CycleResult& result);

}  // namespace stockbridge::requests
