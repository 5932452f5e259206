#pragma once
// The request layer for the identification from a measured impedance (`stockbridge
// identify impedance`, Python's identify_impedance): the fit's settings as the
// front ends name them, the summary (the --json keys), the fitted model at the
// measured points (the --fitted CSV's columns) and the identified cables as cable
// files.
#include <complex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/core/warning.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

struct ImpedanceFitRequest {
  int elements = 1;             ///< Jenkin elements per cable type
  bool fit_clamp_mass = false;  ///< also fit the clamp mass
  int threads = 1;              ///< model runs at once (the Jacobian's columns)
  /// Numbers of the damper fitted too, by their paths ("arm.left.mass", "clamp.mass";
  /// identification::ImpedanceIdentificationOptions::free).
  std::vector<std::string> free;
  /// An RMS relative error of Z above this is a poor fit (warned of; the command exits 3).
  double rms_limit = identification::ImpedanceIdentificationOptions{}.rms_limit;
  /// The measurement's stated relative scatter of Z (0.01 for 1 %); unset: 1 %,
  /// assumed. A significant lack of fit against it is warned of; the command exits 3.
  std::optional<double> scatter;
};

/// The fit's options; InvalidParameter naming "elements", "threads", "rms_limit" or
/// "scatter" (the command's --elements, --threads, --rms-limit and --scatter, Python's
/// keywords). The
/// paths of `free` are checked against the damper by the fit (field "free").
identification::ImpedanceIdentificationOptions fit_options(const ImpedanceFitRequest& request);

/// A measured impedance from arrays (Python's identify_impedance; the CSV reader
/// builds it from a file): frequencies (Hz), one amplitude per point (a velocity in
/// m/s where `velocity`, else a displacement in m) and complex Z (N s/m), each within
/// the magnitudes a description may hold (1e-12 to 1e12: core/error.hpp);
/// InvalidParameter naming the array and index ("frequency[2]", "z[3]") otherwise.
identification::ImpedanceMeasurement measurement_from_arrays(const std::vector<double>& frequency,
                                                             const std::vector<double>& amplitude, bool velocity,
                                                             const std::vector<std::complex<double>>& z);

/// One measured point with the fitted model's at it.
struct FittedPoint {
  const identification::MeasuredImpedance* measured = nullptr;
  const damper::ImpedancePoint* model = nullptr;
};
std::vector<FittedPoint> fitted_points(const identification::ImpedanceMeasurement& measurement,
                                       const identification::ImpedanceIdentification& fit);
/// The --fitted CSV's quantities: the measured point (frequency_hz, velocity_m_s,
/// displacement_m, re_z_n_s_m, im_z_n_s_m), the fitted model's Z there
/// (model_re_z_n_s_m, model_im_z_n_s_m; NaN where it did not converge) and converged.
Table<FittedPoint> fitted_table();

/// The fit's notes (parameters the data do not determine, points the model does
/// not converge at, a fit stopped short, estimates a suspect fixed number moves), a
/// poor fit (an RMS error above the fit's rms_limit) and a significant lack of fit
/// (the residuals beyond the stated scatter; then a second line naming the fixed
/// numbers that explain most of it), as warnings; `source` names the measurement.
std::vector<Warning> fit_warnings(const identification::ImpedanceIdentification& fit, std::string_view source);

/// The summary, as `identify impedance --json` prints it and Python returns it:
/// ei and jenkin [{c, h}] (the first cable type's, as identify global prints them;
/// under the Bouc-Wen law law = "bouc-wen", ei_min, ei_max, chi0),
/// clamp_mass_kg, misfit, rms_relative_error, rms_limit, poor_fit, lack_of_fit
/// {scatter, scatter_assumed, ratio, statistic, degrees_of_freedom, p_value,
/// critical_statistic, level, significant, error_inflation, suspects [{name, unit,
/// value, misfit_reduction, suggested_value}], notes}, points, curves,
/// not_converged, parameters [{name, unit, value, standard_error,
/// resolution_at_1_percent, sensitivity, determined, geometry, confounded_by (null
/// if none), confounded_shift}], geometry {path:
/// value} (the fitted numbers of the damper), correlation (rows in the parameters' order, null for
/// a parameter not determined), stick_stiffness [the same for each type's
/// ei_plus_c; none under the Bouc-Wen law], undetermined [names], notes, cables
/// [{arms, ei, jenkin} or {arms, law, ei_min, ei_max, chi0}] (every
/// type), model_runs, starts, termination, iterations, warnings (`input_warnings`,
/// the measured file's, then fit_warnings).
io::JsonObject fit_summary(const identification::ImpedanceMeasurement& measurement,
                           const identification::ImpedanceIdentification& fit, const damper::Damper& start,
                           std::string_view source, const std::vector<std::string>& input_warnings = {});

/// One line for the terminal: the parameters with their standard errors, the error and the work.
std::string fit_summary_line(const identification::ImpedanceMeasurement& measurement,
                             const identification::ImpedanceIdentification& fit);

/// The fitted damper as a damper file (`identify impedance --fitted-damper`): the
/// start with the fitted cables and numbers, every cable written out, the fit's
/// figures and `source` in comments, the numbers it did not determine named.
std::string fitted_damper_file(const identification::ImpedanceIdentification& fit, std::string_view source);

/// The cable file of cable type `type`: the fitted parameters on the cable of the
/// type's first arm (its length, sections, mirror length and lever-arm cap), the
/// fit's figures and `source` in comments. Damper files reference it and cut it to
/// each arm's length.
std::string fitted_cable_file(const identification::ImpedanceIdentification& fit, std::size_t type,
                              std::string_view source);

}  // namespace stockbridge::requests
