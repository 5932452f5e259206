#pragma once
// The dissertation's two standard hysteresis experiments on a cable (4.1.1, 4.1.2):
//   (a) tip deflection x = A sin(2 pi k / points) prescribed, no tip moment: output F;
//   (b) tip rotation phi = A sin(2 pi k / points) prescribed, tip guided (x = 0): output T.
// k = 0 .. cycles * points, from the cantilever's current (usually virgin) state.

#include <string_view>
#include <vector>

#include "stockbridge/cable/cantilever.hpp"

namespace stockbridge::cable {

enum class Experiment { a, b };

/// "a" or "b"; throws InvalidParameter otherwise.
Experiment parse_experiment(std::string_view name);

struct ExperimentDrive {
  Experiment experiment = Experiment::a;
  double amplitude = 0.0;  ///< m for (a), rad for (b); finite, >= 0
  int cycles = 2;          ///< >= 1
  int points = 400;        ///< samples per cycle, >= 4

  void validate() const;
  /// The prescribed x (a) or phi (b) at sample k.
  double prescribed(int k) const;
};

/// One sample of the experiment.
struct ExperimentSample {
  double deflection = 0.0;    ///< x, m
  double rotation = 0.0;      ///< phi, rad
  double tip_force = 0.0;     ///< F, N
  double clamp_moment = 0.0;  ///< T, N m
  double tip_moment = 0.0;    ///< Q = T - F l, N m
  double dissipated = 0.0;    ///< by the sliders since virgin, J
  StateDetermination solve;   ///< how the state was found; numbers are trusted only if converged
};

struct ExperimentSummary {
  /// Over the last cycle: the sliders' dissipation, and the work of the tip loads
  /// around the loop (trapezoid rule over the samples): int F dx + Q dphi. The two
  /// agree to the accuracy of the loop's quadrature. NaN (all three) when a sample of
  /// the last cycle did not converge.
  double slider_dissipation = 0.0;  ///< J
  double loop_work = 0.0;           ///< J
  /// Area of the (phi, T) loop (b) or of the (x, F) loop (a), the measured loop.
  double measured_loop_area = 0.0;  ///< J
  double max_tip_force = 0.0, min_tip_force = 0.0;
  double max_clamp_moment = 0.0, min_clamp_moment = 0.0;
  double max_deflection = 0.0, min_deflection = 0.0;
  double max_rotation = 0.0, min_rotation = 0.0;
  int max_iterations = 0;
  double mean_iterations = 0.0;
  int failed_samples = 0;  ///< samples whose state determination did not converge
};

struct ExperimentRecord {
  std::vector<ExperimentSample> samples;
  ExperimentSummary summary;
};

/// Runs the experiment, committing every converged sample. A sample that does not
/// converge is reverted (the next one starts from the last converged state) and
/// flagged; the summary's extremes then cover only what converged, and its energies
/// are NaN if the failure lies in the last cycle.
ExperimentRecord run_experiment(Cantilever& cantilever, const ExperimentDrive& drive);

/// The samples of an experiment along any path of the prescribed quantity (x for
/// (a), phi for (b)), e.g. a measured one, from the cantilever's current state.
std::vector<ExperimentSample> run_path(Cantilever& cantilever, Experiment experiment,
                                       const std::vector<double>& prescribed);

}  // namespace stockbridge::cable
