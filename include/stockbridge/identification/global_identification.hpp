#pragma once
// Global identification (MODEL.md section 8, dissertation 4.3): constant cable
// parameters from a measured cycle of experiment (a) (x prescribed, tip force F
// measured) or (b) (phi prescribed with x = 0, clamp moment T measured) on a cable
// of known length l.
//
// * four-step (4.3.4): (1) ei + c from the steepest slope just after a reversal
//   ((a): l^3/3 dF/dx, (b): l/2 (-dT/dphi)); (2) ei from the flattest slope at the
//   extremes; (3) h from the offset at the extremes ((a): h = 2l/3 (F - 3 ei x/l^3),
//   (b): h = -T - 2 ei phi/l, MODEL.md's corrected form of (4.79)); (4) c from (1) - (2).
//   Biased: near the tip (a), and around s = l/3 (b), the moment is small and the
//   cable sticks, so the loop never reaches the all-slip asymptotes (docs/identification.md).
// * fit: the experiment simulated with the cable model along the measured path, its
//   output compared with the measured one (L1 along the path from the first extreme,
//   plus a constant offset), parameters optimised in logarithms with NLopt from the
//   four-step result. Removes the four-step bias.

#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/cable/experiment.hpp"
#include "stockbridge/identification/local_identification.hpp"

namespace stockbridge::identification {

struct ExperimentMeasurement {
  cable::Experiment experiment = cable::Experiment::a;
  std::vector<double> prescribed;  ///< x (m) for (a), phi (rad) for (b), in time order
  std::vector<double> measured;    ///< F (N) for (a), T (N m) for (b)
};

struct GlobalIdentificationOptions {
  const cable::SectionLawDescriptor* law = &cable::default_section_law();  ///< the law to fit (a law of numbers: the fit only)
  double length = 0.0;    ///< l of the measured cable, m
  int sections = 40;      ///< of the model cable
  int elements = 1;       ///< Jenkin elements (fit; four-step has one; 1 under a law of numbers)
  Optimizer optimizer = Optimizer::subplex;
  int max_evaluations = 4000;
  double tolerance = 1e-10;
  void validate() const;
};

struct GlobalIdentification {
  cable::CableDescription cable;  ///< constant profiles, the options' length and sections
  double output_offset = 0.0;     ///< constant offset of the measured output (fit), N or N m
  double error = 0.0;             ///< relative L1 error of the model's output, from the first extreme
  int evaluations = 0;            ///< cable simulations (fit)
  /// How the fit's last optimiser run ended (converged, max_iterations,
  /// no_progress); not_run for the four-step method (no optimiser).
  Termination termination = Termination::not_run;
};

/// The dissertation's four steps; error computed with the model for comparison.
GlobalIdentification identify_four_step(const ExperimentMeasurement& measurement, const GlobalIdentificationOptions& options);

/// Model-based fit, started from the four-step result.
GlobalIdentification identify_fit(const ExperimentMeasurement& measurement, const GlobalIdentificationOptions& options);

/// The model's output (F for (a), T for (b), plus the offset) along the measured
/// path, from the virgin state; NaN where a state determination did not converge.
std::vector<double> model_output(const cable::CableDescription& cable, double output_offset,
                                 const ExperimentMeasurement& measurement);

/// The relative L1 error of a cable (and output offset) on the measurement.
double relative_l1_error(const cable::CableDescription& cable, double output_offset,
                         const ExperimentMeasurement& measurement);

}  // namespace stockbridge::identification
