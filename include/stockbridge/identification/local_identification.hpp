#pragma once
// Local identification (MODEL.md section 8, dissertation 3.5 and 4.3.3): the Masing
// parameters of one cable cross-section from a measured moment-curvature record.
//
// The model section is driven from the virgin state with the measured curvature
// kappa_k; its moment is compared with the measured one from the first extreme on,
// where every element has slipped so that model and specimen share their state:
//     e = int |M_model + m0 - M_measured| |d kappa|,
// relative to int |M_measured| |d kappa| (the trapezoid rule over the samples). The
// integral runs along the curvature path rather than over the sample index, so that
// uneven sampling does not weight parts of the loop. m0 is a constant moment offset
// (a drift-free offset of either signal: after the first extreme a curvature offset
// kappa0 acts as the moment offset ei kappa0). The parameters are optimised in
// logarithms (so they stay positive) with NLopt, from several starts derived from
// the record: the stiffness just after the reversals (ei + sum c), at the extremes
// (ei), and the loop's half-height at the extremes (sum h).
// The Bouc-Wen law (MODEL.md section 13) is fitted the same way: ei_min, ei_max - ei_min
// and chi0 in logarithms, from the slopes at the extremes (EI_min) and after the
// reversals (EI_max) and the half-height over EI_max - EI_min (chi0: the hysteretic
// moment swings by (EI_max - EI_min) chi0 tanh(chi_a / chi0)).

#include <string>
#include <vector>

#include <optional>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/section/masing_law.hpp"

namespace stockbridge::identification {

struct MomentCurvatureRecord {
  std::vector<double> curvature;  ///< kappa, 1/m, in time order
  std::vector<double> moment;     ///< M, N m
};

enum class Optimizer { subplex, nelder_mead };

/// "subplex" or "nelder-mead"; throws InvalidParameter otherwise.
Optimizer parse_optimizer(std::string_view name);

struct LocalIdentificationOptions {
  const cable::SectionLawDescriptor* law = &cable::default_section_law();  ///< the law to fit
  int elements = 1;                  ///< Jenkin elements to fit, 1..6 (the Masing law; 1 under a law of numbers)
  Optimizer optimizer = Optimizer::subplex;  ///< NLopt's Subplex (default) or Nelder-Mead (the dissertation's)
  int max_evaluations = 40000;       ///< per start
  double tolerance = 1e-12;          ///< relative change of the parameters at which a start stops
  void validate() const;
};

struct LocalIdentification {
  section::MasingParameters parameters;  ///< elements sorted by slip curvature h / c (the Masing law)
  std::optional<cable::LawValues> numbers;  ///< the numbers of a law of numbers (Bouc-Wen), when one was fitted
  double moment_offset = 0.0;        ///< m0, N m
  double error = 0.0;                ///< relative L1 error from the first extreme on
  std::vector<double> cycle_errors;  ///< the same, per cycle (between every second reversal)
  int evaluations = 0;               ///< model runs in all starts
  int starts = 0;
  /// How the optimiser's run that reached these parameters ended (converged,
  /// max_iterations, no_progress; SearchSettings' tolerance and evaluations).
  Termination termination = Termination::not_run;
};

/// The relative L1 error of `parameters` (and offset m0) on the record, from the first extreme.
double relative_l1_error(const section::MasingParameters& parameters, double moment_offset,
                         const MomentCurvatureRecord& record);

/// The model's moment (plus the offset) along the record's curvature, from the virgin state.
std::vector<double> model_moments(const section::MasingParameters& parameters, double moment_offset,
                                  const MomentCurvatureRecord& record);
std::vector<double> model_moments(const cable::LawValues& numbers, double moment_offset,
                                  const MomentCurvatureRecord& record);
/// The fit's model along the record, whichever law it fitted.
std::vector<double> model_moments(const LocalIdentification& fit, const MomentCurvatureRecord& record);

/// Throws InvalidParameter for a record that cannot be identified (fewer than one
/// full cycle after the first extreme: two reversals; sizes that differ).
LocalIdentification identify_local(const MomentCurvatureRecord& record, const LocalIdentificationOptions& options);

/// Indices where the curvature reverses (the last sample before the direction changes).
std::vector<std::size_t> reversals(const std::vector<double>& curvature);

}  // namespace stockbridge::identification
