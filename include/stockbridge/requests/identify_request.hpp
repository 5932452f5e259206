#pragma once
// The request layer for the cable identifications from hysteresis records
// (`stockbridge identify local` and `identify global`, Python's identify_local and
// identify_global): the settings by the commands' names with their defaults, the
// fit run (global: the four-step formulas or the model fit), the model along the
// record as the --fitted table, the --json summary, the parameter or cable file,
// and the warnings (inputs outside their typical ranges, a large misfit).

#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/core/warning.hpp"
#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

/// A fit whose relative L1 error exceeds this does not model its record: a warning.
inline constexpr double large_fit_error = 0.1;

/// A fitted law of numbers as every identification's summaries give it: the JSON keys
/// law = "bouc-wen", ei_min, ei_max, chi0 (the law's name and numbers; added to
/// `json`, which is returned) ...
io::JsonObject& add_law_numbers(io::JsonObject& json, const cable::LawValues& numbers);
/// ... the text "ei_min = 2.5 N m^2, ei_max = 25 N m^2, chi0 = 0.03 1/m" ...
std::string law_numbers_text(const cable::LawValues& numbers);
/// ... and the keys of a [cable] table, one a line with its unit in a comment.
std::string law_numbers_toml(const cable::LawValues& numbers);

struct LocalRequest {
  std::string law = "masing";       ///< a section law's name (cable::section_law_names())
  int elements = 1;                 ///< Jenkin elements to fit (the Masing law)
  std::string optimizer = "subplex";  ///< subplex | nelder-mead
};

/// The validated options (InvalidParameter naming "law", "elements" or "optimizer").
identification::LocalIdentificationOptions local_options(const LocalRequest& request);

struct LocalResult {
  identification::MomentCurvatureRecord record;
  identification::LocalIdentification fit;
  std::vector<double> model;  ///< the fitted moment along the record, N m
};

/// Fits the record (InvalidParameter for a record that cannot be identified).
LocalResult run_local(identification::MomentCurvatureRecord record, const LocalRequest& request);

/// One sample of a record with the model's output there.
struct FittedSample {
  const std::vector<double>* prescribed = nullptr;
  const std::vector<double>* measured = nullptr;
  const std::vector<double>* model = nullptr;
  std::size_t k = 0;
};
std::vector<FittedSample> fitted_samples(const std::vector<double>& prescribed, const std::vector<double>& measured,
                                         const std::vector<double>& model);

/// The --fitted CSV of identify local: curvature_per_m, moment_n_m, model_moment_n_m.
Table<FittedSample> local_fitted_table();
/// The --json summary: ei, jenkin (the Masing law) or law = "bouc-wen", ei_min, ei_max,
/// chi0; then error, moment_offset_n_m, cycle_errors, evaluations, termination.
io::JsonObject local_summary(const LocalResult& result);
/// The -o file: the keys of a [cable] table with the fit's figures in comments.
std::string local_parameters_toml(const LocalResult& result, std::string_view source);

struct GlobalRequest {
  std::string law = "masing";    ///< a section law's name (cable::section_law_names()) (the fit only)
  std::string experiment = "a";  ///< a: columns x_m, force_n; b: phi_rad, clamp_moment_n_m
  double length = 0.0;           ///< of the measured cable, m
  std::string method = "fit";    ///< fit | four-step
  int sections = 40;
  int elements = 1;
  std::string optimizer = "subplex";
};

/// The validated options (InvalidParameter naming "length", "method", ...).
identification::GlobalIdentificationOptions global_options(const GlobalRequest& request);
/// The CSV columns a record of the request's experiment needs: (x_m, force_n) or (phi_rad, clamp_moment_n_m).
std::vector<std::string> global_record_columns(const GlobalRequest& request);

struct GlobalResult {
  identification::ExperimentMeasurement measurement;
  identification::GlobalIdentification fit;
  std::vector<double> model;      ///< the fitted output along the record, N or N m
  std::vector<Warning> warnings;  ///< the length and the record outside their typical ranges, a large error
};

/// Identifies the cable from the record (`source` names it in warnings: a file's
/// path, or "the record"): the four-step formulas or the fit, as the request says.
GlobalResult run_global(const GlobalRequest& request, std::vector<double> prescribed, std::vector<double> measured,
                        std::string_view source);

/// The --fitted CSV of identify global: the prescribed and measured columns and the model's output.
Table<FittedSample> global_fitted_table(const GlobalRequest& request);
/// The --json summary: ei, jenkin, error, method, output_offset, evaluations, termination, warnings.
io::JsonObject global_summary(const GlobalRequest& request, const GlobalResult& result);
/// The -o cable file.
std::string global_cable_toml(const GlobalRequest& request, const GlobalResult& result, std::string_view source);

}  // namespace stockbridge::requests
