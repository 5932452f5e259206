#include "stockbridge/requests/identify_request.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/cable_file.hpp"

namespace stockbridge::requests {

identification::LocalIdentificationOptions local_options(const LocalRequest& request) {
  identification::LocalIdentificationOptions options;
  options.law = &cable::section_law(request.law);
  options.elements = request.elements;
  options.optimizer = identification::parse_optimizer(request.optimizer);
  options.validate();
  return options;
}

LocalResult run_local(identification::MomentCurvatureRecord record, const LocalRequest& request) {
  LocalResult out;
  out.record = std::move(record);
  out.fit = identification::identify_local(out.record, local_options(request));
  out.model = identification::model_moments(out.fit, out.record);
  return out;
}

std::vector<FittedSample> fitted_samples(const std::vector<double>& prescribed, const std::vector<double>& measured,
                                         const std::vector<double>& model) {
  std::vector<FittedSample> rows;
  for (std::size_t k = 0; k < model.size(); ++k) rows.push_back({&prescribed, &measured, &model, k});
  return rows;
}

namespace {

Table<FittedSample> fitted_table(std::string prescribed, std::string prescribed_unit, std::string measured,
                                 std::string measured_unit, std::string what) {
  return Table<FittedSample>({
      {std::move(prescribed), prescribed_unit, "the record's prescribed quantity", ColumnKind::number,
       [](const FittedSample& s, std::size_t) { return (*s.prescribed)[s.k]; }, {}},
      {measured, measured_unit, "the record's measured " + what, ColumnKind::number,
       [](const FittedSample& s, std::size_t) { return (*s.measured)[s.k]; }, {}},
      {"model_" + measured, measured_unit, "the fitted model's " + what + " there", ColumnKind::number,
       [](const FittedSample& s, std::size_t) { return (*s.model)[s.k]; }, {}},
  });
}

std::vector<io::JsonObject> jenkin_json(const std::vector<std::pair<double, double>>& c_h) {
  std::vector<io::JsonObject> out;
  for (const auto& [c, h] : c_h) out.push_back(io::JsonObject().add("c", c).add("h", h));
  return out;
}

}  // namespace

io::JsonObject& add_law_numbers(io::JsonObject& json, const cable::LawValues& numbers) {
  json.add("law", std::string(numbers.law->name()));
  const auto keys = numbers.law->numbers();
  for (std::size_t k = 0; k < keys.size(); ++k) json.add(std::string(keys[k].key), numbers[k]);
  return json;
}

std::string law_numbers_text(const cable::LawValues& numbers) {
  std::string text;
  const auto keys = numbers.law->numbers();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    text += fmt::format("{}{} = {:.6g}{}{}", k ? ", " : "", keys[k].key, numbers[k], keys[k].unit.empty() ? "" : " ",
                        keys[k].unit);
  }
  return text;
}

std::string law_numbers_toml(const cable::LawValues& numbers) {
  std::string text = fmt::format("law = \"{}\"\n", numbers.law->name());
  const auto keys = numbers.law->numbers();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    text += fmt::format("{} = {}   # {}\n", keys[k].key, numbers[k], keys[k].unit.empty() ? "-" : keys[k].unit);
  }
  return text;
}

Table<FittedSample> local_fitted_table() {
  return fitted_table("curvature_per_m", "1/m", "moment_n_m", "N m", "moment");
}

io::JsonObject local_summary(const LocalResult& result) {
  const identification::LocalIdentification& fit = result.fit;
  io::JsonObject json;
  if (fit.numbers) {
    add_law_numbers(json, *fit.numbers);
  } else {
    std::vector<std::pair<double, double>> c_h;
    for (const section::Jenkin& e : fit.parameters.jenkin) c_h.emplace_back(e.c, e.h);
    json.add("ei", fit.parameters.ei).add("jenkin", jenkin_json(c_h));
  }
  return json.add("error", fit.error)
      .add("moment_offset_n_m", fit.moment_offset)
      .add("cycle_errors", fit.cycle_errors)
      .add("evaluations", fit.evaluations)
      .add("termination", termination_name(fit.termination));
}

std::string local_parameters_toml(const LocalResult& result, std::string_view source) {
  const identification::LocalIdentification& fit = result.fit;
  std::string text = fmt::format(
      "# Identified by stockbridge identify local from {}: relative L1 error {:.4g}, moment offset {} N m.\n"
      "# The keys of a [cable] table: paste them into a cable or damper file.\n",
      source, fit.error, fit.moment_offset);
  if (fit.numbers) return text + law_numbers_toml(*fit.numbers);
  text += fmt::format("ei = {}                 # N m^2\njenkin = [", fit.parameters.ei);
  for (std::size_t j = 0; j < fit.parameters.jenkin.size(); ++j) {
    text += fmt::format("{} {{ c = {}, h = {} }}", j ? "," : "", fit.parameters.jenkin[j].c, fit.parameters.jenkin[j].h);
  }
  return text + " ]   # N m^2, N m\n";
}

identification::GlobalIdentificationOptions global_options(const GlobalRequest& request) {
  identification::GlobalIdentificationOptions options;
  options.law = &cable::section_law(request.law);
  if (!options.law->jenkin_elements() && request.method == "four-step") {
    throw InvalidParameter("method", fmt::format(" = 'four-step': the four steps identify the Masing law; the {} law is "
                                                 "fitted (--method fit)",
                                                 options.law->title()));
  }
  options.length = request.length;
  options.sections = request.sections;
  options.elements = request.elements;
  options.optimizer = identification::parse_optimizer(request.optimizer);
  options.validate();
  (void)cable::parse_experiment(request.experiment);
  if (request.method != "fit" && request.method != "four-step") {
    throw InvalidParameter("method", fmt::format(" = '{}': expected four-step or fit", request.method));
  }
  return options;
}

std::vector<std::string> global_record_columns(const GlobalRequest& request) {
  return cable::parse_experiment(request.experiment) == cable::Experiment::a
             ? std::vector<std::string>{"x_m", "force_n"}
             : std::vector<std::string>{"phi_rad", "clamp_moment_n_m"};
}

namespace {

/// The length and the record outside their typical ranges, and a large error.
std::vector<Warning> global_warnings(const GlobalRequest& request, const GlobalResult& r, std::string_view source) {
  std::vector<UnusualValue> settings;
  check_typical(settings, "length", request.length, typical::cable_length);
  std::vector<Warning> out = setting_warnings(settings);
  double largest = 0.0;
  for (const double p : r.measurement.prescribed) largest = std::max(largest, std::abs(p));
  if (r.measurement.experiment == cable::Experiment::a && !typical::tip_deflection_ratio.contains(largest / request.length)) {
    out.push_back({fmt::format("{}: x_m reaches {} m, more than {} of the length {} m: beyond the small deflections the "
                               "model assumes (deflections in mm under an x_m header?)",
                               source, format_value(largest), typical::tip_deflection_ratio.max,
                               format_value(request.length)),
                   false});
  }
  if (r.measurement.experiment == cable::Experiment::b && !typical::tip_rotation.contains(largest)) {
    out.push_back({fmt::format("{}: phi_rad reaches {} rad, outside the typical 0 to {} rad (degrees under a phi_rad "
                               "header?)",
                               source, format_value(largest), typical::tip_rotation.max),
                   false});
  }
  if (r.fit.error > large_fit_error) {
    out.push_back({request.method == "four-step"
                       ? fmt::format("the four-step result's relative L1 error {:.3g} is large (above {}): its "
                                     "formulas are biased where the cable never slips all along "
                                     "(docs/identification.md); --method fit fits the model to the whole record",
                                     r.fit.error, large_fit_error)
                       : fmt::format("the fit's relative L1 error {:.3g} is large (above {}): the model does not "
                                     "follow the record (check its units, the experiment and --length)",
                                     r.fit.error, large_fit_error),
                   false});
  }
  return out;
}

}  // namespace

GlobalResult run_global(const GlobalRequest& request, std::vector<double> prescribed, std::vector<double> measured,
                        std::string_view source) {
  const identification::GlobalIdentificationOptions options = global_options(request);
  GlobalResult out;
  out.measurement = {cable::parse_experiment(request.experiment), std::move(prescribed), std::move(measured)};
  out.fit = request.method == "four-step" ? identification::identify_four_step(out.measurement, options)
                                          : identification::identify_fit(out.measurement, options);
  out.model = identification::model_output(out.fit.cable, out.fit.output_offset, out.measurement);
  out.warnings = global_warnings(request, out, source);
  return out;
}

Table<FittedSample> global_fitted_table(const GlobalRequest& request) {
  return cable::parse_experiment(request.experiment) == cable::Experiment::a
             ? fitted_table("x_m", "m", "force_n", "N", "tip force")
             : fitted_table("phi_rad", "rad", "clamp_moment_n_m", "N m", "clamp moment");
}

io::JsonObject global_summary(const GlobalRequest& request, const GlobalResult& result) {
  const cable::CableDescription& c = result.fit.cable;
  io::JsonObject json;
  if (!c.law->jenkin_elements()) {
    add_law_numbers(json, c.values());
  } else {
    std::vector<std::pair<double, double>> c_h;
    for (const cable::JenkinProfile& e : c.jenkin) c_h.emplace_back(e.c.at(0.0), e.h.at(0.0));
    json.add("ei", c.ei.at(0.0)).add("jenkin", jenkin_json(c_h));
  }
  return json.add("error", result.fit.error)
      .add("method", request.method)
      .add("output_offset", result.fit.output_offset)
      .add("evaluations", result.fit.evaluations)
      .add("termination", termination_name(result.fit.termination))
      .add("warnings", warning_messages(result.warnings));
}

std::string global_cable_toml(const GlobalRequest& request, const GlobalResult& result, std::string_view source) {
  return io::cable_file_toml(result.fit.cable,
                             fmt::format("Identified by stockbridge identify global ({}) from experiment ({}) in {}:\n"
                                         "relative L1 error {:.4g}, output offset {}.",
                                         request.method, request.experiment, source, result.fit.error,
                                         result.fit.output_offset));
}

}  // namespace stockbridge::requests
