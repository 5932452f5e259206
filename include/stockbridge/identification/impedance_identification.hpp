#pragma once
// Identification from a measured damper impedance (dissertation 4.3.1; the damper
// characteristic test of IEC 61897): the cable parameters (constant along the cable:
// under the Masing law ei and the Jenkin elements' c_j, h_j; under the Bouc-Wen law,
// when the start's cables have law = "bouc-wen", ei_min, ei_max and chi0) and optionally numbers of the damper
// itself (the clamp mass, arm masses, inertias, offsets, cable lengths: a vendor's
// sheet of a damper whose geometry is not known exactly, MODEL.md 11) that make the
// model's impedance match a measured Z(f, V), the damper's other numbers being known.
//
// Misfit: the relative complex one, every point weighted by its own magnitude,
//     S = sum_i |Z_model,i - Z_i|^2 / |Z_i|^2,
// so that a curve's small values (off resonance, at the higher velocity) count as
// much as its peaks. A point the model does not converge at counts as the model's
// Z = 0 there (|r_i|^2 = 1), never as a failure of the fit.
//
// Method: the model is followed along each measured curve in frequency order
// (damper::DamperTracker, the sweep's warm starts); the parameters are fitted in
// logarithms (they stay positive, as do the masses, inertias and cable lengths fitted
// with them; offsets linearly; the clamp mass linearly, it enters Z as i W m_c)
// by Levenberg-Marquardt (Eigen's MINPACK port) on the 2N real residuals, with a
// forward-difference Jacobian (the clamp mass's column analytic), from several
// starts; the best start is polished to convergence. The Jacobian at the optimum
// gives each parameter's standard error, its correlations, and which parameters (or
// combinations) the data do not determine.
//
// Lack of fit: the misfit is tested against the measurement's stated scatter
// (chi-square, LackOfFit). Where the model cannot reach the data within it, the
// numbers of the damper the fit kept fixed are ranked by how much of the misfit
// freeing each would remove (their Jacobian columns at the optimum, one Gauss-Newton
// step), the standard errors carry the residuals' own scatter, and the estimates a
// plausible error of such a number would move beyond them say so (confounded_by).
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/damper/impedance.hpp"
#include "stockbridge/damper/measured_impedance.hpp"
#include "stockbridge/damper/tracker.hpp"
#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"
#include "stockbridge/section/masing_law.hpp"

namespace stockbridge::identification {

// What a measured impedance is sits below the identification and the span, which
// both read it (damper/measured_impedance.hpp); here by its names of before.
using damper::ImpedanceMeasurement;
using damper::measured_curves;
using damper::MeasuredImpedance;

/// Arms that share one cable type (the fit gives them the same parameters): those
/// whose cables have the same law and numbers (ei and Jenkin elements, or ei_min,
/// ei_max and chi0) in the damper description
/// (lengths and sections may differ). Per arm, the index of its type; types are
/// numbered in the order of their first arm.
std::vector<std::size_t> cable_types(const damper::DamperDescription& damper);

/// The numbers of the damper `free` may name (damper::damper_number's paths):
/// clamp.mass, and per arm mass, inertia, offset, cable.length.
inline constexpr const char* free_damper_numbers =
    "clamp.mass, or arm.<name or [index]>. followed by mass, inertia, offset or cable.length";

/// The scatter assumed where the measurement states none: a shaker test's, about 1 %
/// of Z (docs/identification.md: the model's own error on cables of 12 sections or
/// more is 0.35 % or less, so that a correct model is not flagged).
inline constexpr double default_scatter = 0.01;
/// The lack-of-fit test's level: significant where p < 1 % (the 99 % quantile).
inline constexpr double lack_of_fit_level = 0.01;
/// A fixed number of the damper whose freeing would remove at least this share of a
/// significant lack of fit explains it: the warning names it, and the estimates its
/// suggested change would move beyond their standard errors are confounded by it.
inline constexpr double explaining_share = 0.1;

struct ImpedanceIdentificationOptions {
  int elements = 1;              ///< Jenkin elements per cable type, 1..6 (1 under the Bouc-Wen law, which has none)
  bool fit_clamp_mass = false;   ///< also fit m_c (otherwise the description's); the same as "clamp.mass" in `free`
  /// Numbers of the damper fitted with the cables, by the paths damper::damper_number
  /// reads ("arm.left.mass", "arm[1].cable.length", "clamp.mass"; free_damper_numbers),
  /// each at most once; the start's values start them. Masses, inertias and lengths
  /// are fitted in logarithms, offsets linearly.
  std::vector<std::string> free;
  /// An RMS relative error of Z above this is a poor fit (ImpedanceIdentification::poor_fit):
  /// the model does not follow the measurement. 10 %: ten times a shaker test's
  /// scatter of about 1 %, and what a damper whose masses or lengths are 15-20 % off
  /// gives (docs/identification.md).
  double rms_limit = 0.1;
  /// The measurement's stated relative scatter of Z: the RMS of |Z_measured - Z| / |Z|
  /// it expects from the test alone (0.01 for 1 %; each of Re and Im then scatters by
  /// scatter / sqrt(2) of |Z|). The lack-of-fit test compares the fit's residuals with
  /// it, and the standard errors are never below what it gives. Unset: default_scatter,
  /// assumed (ImpedanceIdentification::lack_of_fit says so).
  std::optional<double> scatter;
  damper::SolverOptions solver;  ///< the model's periodic solver
  int max_jacobians = 30;        ///< per start: Levenberg-Marquardt iterations at most
  int threads = 1;               ///< Jacobian columns evaluated at once, >= 1
  /// Throws InvalidParameter naming the option; the paths of `free` are checked
  /// against the damper by identify_impedance ("free = arm.middle.mass: no arm is named ...").
  void validate() const;
};

/// One fitted parameter.
struct ParameterEstimate {
  /// As a cable file names it ("ei", "jenkin[0].c"; "arm[1].cable.ei" with several
  /// cable types); a number of the damper by its path ("clamp.mass", "arm.long.mass",
  /// "arm.long.cable.length", "arm[0].offset" for an unnamed arm).
  std::string name;
  std::string unit;  ///< "N m^2", "N m", "kg", "kg m^2", "m"
  double value = 0.0;
  /// A number of the damper (options.free or the clamp mass), not a cable parameter.
  bool geometry = false;
  /// From the Jacobian at the optimum and the scatter of Z, in the value's unit:
  /// the stated one's (options.scatter) or, where larger, the residuals' own
  /// (LackOfFit::error_inflation); infinity where not determined.
  double standard_error = 0.0;
  /// RMS relative change of Z per relative change of the parameter (per kg of
  /// clamp mass, per m of offset): how strongly the data see it.
  double sensitivity = 0.0;
  /// The relative standard error a 1 % scatter of Z would give it (of the clamp mass:
  /// relative to the damper's whole mass; of an offset: to the start's |offset| or
  /// 1 cm, the larger); infinity where not determined.
  double resolution_at_1_percent = 0.0;
  /// False where the data leave it free (its Jacobian column in the span of the
  /// others, or a 1 % scatter of Z moving it by more than half its value).
  bool determined = true;
  /// Where the lack of fit is significant: the fixed number of the damper (a
  /// LackOfFit::suspects entry) whose change to its suggested value would move this
  /// estimate by more than its standard error (the most by that measure); empty if
  /// none. Its standard error does not cover that number's error: a note says so.
  std::string confounded_by;
  /// That move, in the value's unit (0 where confounded_by is empty).
  double confounded_shift = 0.0;
};

/// A number of the damper the fit kept fixed (not in `free`) that may be wrong: what
/// freeing it would do, from its Jacobian column at the optimum (the same forward
/// difference as the fit's; analytic for the clamp mass) and one Gauss-Newton step of
/// the fit with it added (the fitted parameters moving with it).
struct FixedNumberSuspect {
  std::string name;   ///< its path, as `free` names it ("arm.long.inertia", "clamp.mass")
  std::string unit;
  double value = 0.0;  ///< the damper's (the start's)
  /// The fraction of the misfit S that step removes, 0..1: how much of the lack of
  /// fit an error in this number explains.
  double misfit_reduction = 0.0;
  /// The value the step moves it to (masses, inertias and lengths in logarithms,
  /// offsets and the clamp mass linearly, as the fit would free them).
  double suggested_value = 0.0;
};

/// The lack-of-fit test: the residuals against the measurement's stated scatter.
/// With the scatter s of Z (options.scatter) each of the 2N real residuals has the
/// standard deviation s / sqrt(2), so where the model is right
///     statistic = S / (s^2 / 2) = 2 N (rms / s)^2
/// follows the chi-square distribution with 2N - k degrees of freedom (k: the
/// parameters the data determine, the Jacobian's rank).
struct LackOfFit {
  double scatter = default_scatter;  ///< s used (options.scatter or default_scatter)
  bool assumed = true;               ///< options.scatter unset: the default
  double ratio = 0.0;                ///< rms_relative_error / scatter
  double statistic = 0.0;
  int degrees_of_freedom = 0;
  double p_value = 1.0;              ///< P(chi2 >= statistic); NaN without degrees of freedom
  double critical = 0.0;             ///< the chi2 quantile at 1 - level (the 99 % one)
  double level = lack_of_fit_level;
  bool significant = false;          ///< p_value < level: the model cannot reach the data within their scatter
  /// The factor the standard errors carry over what the stated scatter gives:
  /// max(1, sqrt(S / (2N - k)) / (s / sqrt(2))) (the residuals' own scatter where larger).
  double error_inflation = 1.0;
  /// Where significant: every number of the damper not fitted (clamp.mass, each arm's
  /// mass, inertia, offset and cable.length), the most explaining first; else empty.
  std::vector<FixedNumberSuspect> suspects;
  /// One sentence per suspect explaining at least explaining_share of the misfit
  /// whose suggested change would move estimates beyond their standard errors
  /// (ParameterEstimate::confounded_by), naming them and by how much.
  std::vector<std::string> notes;
};

struct ImpedanceIdentification {
  damper::DamperDescription damper;                ///< the start's damper with the fitted parameters (and numbers)
  std::vector<std::size_t> cable_type;             ///< per arm (cable_types())
  const cable::SectionLawDescriptor* law = &cable::default_section_law();  ///< the start's cables' law (one for every arm)
  std::vector<section::MasingParameters> cables;   ///< per type under the Masing law, elements sorted by slip curvature h / c
  std::vector<cable::LawValues> law_cables;        ///< per type under a law of numbers (Bouc-Wen)
  /// Cable types fitted (of any law).
  std::size_t types() const { return cables.size() + law_cables.size(); }
  double clamp_mass = 0.0;                         ///< kg (fitted, or the description's)
  double misfit = 0.0;             ///< S at the optimum
  double rms_relative_error = 0.0; ///< sqrt(S / N)
  double rms_limit = 0.1;          ///< options.rms_limit
  bool poor_fit = false;           ///< rms_relative_error > rms_limit
  LackOfFit lack_of_fit;           ///< the residuals against the stated scatter
  /// In the order of the cables, then the numbers of options.free (in its order),
  /// then the clamp mass.
  std::vector<ParameterEstimate> parameters;
  /// Correlations of the parameters' estimates (NaN for a parameter not determined).
  Eigen::MatrixXd correlation;
  /// The stick stiffness ei + sum c of each Masing type, which data that never reach slip
  /// still determine (named "ei_plus_c", "arm[1].cable.ei_plus_c"; none under the
  /// Bouc-Wen law, whose stick stiffness is the parameter ei_max).
  std::vector<ParameterEstimate> stick_stiffness;
  /// What the data do not determine, one sentence each.
  std::vector<std::string> notes;
  std::vector<damper::ImpedancePoint> fitted;      ///< the model at each measured point, in the measurement's order
  int not_converged = 0;           ///< measured points the fitted model does not converge at
  int model_evaluations = 0;       ///< model runs over all points (Jacobian columns included)
  /// How the final Levenberg-Marquardt run ended: converged, max_iterations
  /// (max_jacobians used up: the estimates are the best point reached, and a note
  /// says so), no_progress; residual |r| there, jacobians (iterations).
  SolverSummary fit;
  int starts = 0;
};

/// Fits the cable parameters (and the numbers of options.free) of `start` (its values
/// the starting values) to the measurement. Throws InvalidParameter for a start
/// whose cables are profiles, use the modified Masing model with another element
/// count, differ in law ("arm[1].cable.law"), or have a law of numbers with a start
/// it cannot fit from (Bouc-Wen's ei_max <= ei_min) or elements != 1 (field "elements"), for bad options (a path of `free` named: field "free") or measurements.
ImpedanceIdentification identify_impedance(const damper::DamperDescription& start, const ImpedanceMeasurement& measurement,
                                           const ImpedanceIdentificationOptions& options);

/// The model's impedance at every measured point (in the measurement's order),
/// followed along each curve; points that do not converge say so.
std::vector<damper::ImpedancePoint> model_impedance(const damper::Damper& damper, const ImpedanceMeasurement& measurement,
                                                    const damper::SolverOptions& solver);

}  // namespace stockbridge::identification
