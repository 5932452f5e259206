// stockbridge identify local: cable section parameters from a measured
// moment-curvature record.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/io/csv_writer.hpp"
#include "stockbridge/io/json_writer.hpp"

namespace stockbridge::cli {

namespace {

/// What the summary line adds where the optimiser's run did not meet its tolerance.
std::string optimiser_note(Termination termination) {
  if (termination == Termination::converged || termination == Termination::not_run) return "";
  return fmt::format("; the optimiser stopped short of its tolerance ({}): the best point reached", termination_name(termination));
}

struct LocalOptions {
  std::string input;
  int elements = 1;
  std::string optimizer = "subplex";
  std::string output;
  std::string fitted;
  bool json = false;
};

std::string parameters_toml(const identification::LocalIdentification& fit, const std::string& source) {
  std::string text = fmt::format(
      "# Identified by stockbridge identify local from {}: relative L1 error {:.4g}, moment offset {} N m.\n"
      "# The keys of a [cable] table: paste them into a cable or damper file.\n",
      source, fit.error, fit.moment_offset);
  text += fmt::format("ei = {}                 # N m^2\njenkin = [", fit.parameters.ei);
  for (std::size_t j = 0; j < fit.parameters.jenkin.size(); ++j) {
    text += fmt::format("{} {{ c = {}, h = {} }}", j ? "," : "", fit.parameters.jenkin[j].c, fit.parameters.jenkin[j].h);
  }
  return text + " ]   # N m^2, N m\n";
}

int run_local(const LocalOptions& options) {
  require_outputs_apart({{"-o", options.output}, {"--fitted", options.fitted}}, {{"the --input record", options.input}});
  identification::LocalIdentificationOptions fit_options;
  fit_options.elements = options.elements;
  fit_options.optimizer = identification::parse_optimizer(options.optimizer);
  fit_options.validate();
  const std::vector<std::vector<double>> columns =
      io::read_csv_columns(options.input, {"curvature_per_m", "moment_n_m"}, 8);
  const identification::MomentCurvatureRecord record{columns[0], columns[1]};
  identification::LocalIdentification fit;
  try {
    fit = identification::identify_local(record, fit_options);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}: {}", options.input, e.what()));
  }
  if (!options.output.empty()) io::write_file_atomically(options.output, parameters_toml(fit, options.input));
  if (!options.fitted.empty()) {
    const std::vector<double> model = identification::model_moments(fit.parameters, fit.moment_offset, record);
    io::CsvWriter csv({"curvature_per_m", "moment_n_m", "model_moment_n_m"});
    for (std::size_t k = 0; k < model.size(); ++k) csv.add_row({record.curvature[k], record.moment[k], model[k]});
    io::write_file_atomically(options.fitted, csv.text());
  }
  if (options.json) {
    std::vector<io::JsonObject> jenkin;
    for (const section::Jenkin& e : fit.parameters.jenkin) jenkin.push_back(io::JsonObject().add("c", e.c).add("h", e.h));
    fmt::print("{}\n", io::JsonObject()
                           .add("ei", fit.parameters.ei)
                           .add("jenkin", jenkin)
                           .add("error", fit.error)
                           .add("moment_offset_n_m", fit.moment_offset)
                           .add("cycle_errors", fit.cycle_errors)
                           .add("evaluations", fit.evaluations)
                           .add("termination", termination_name(fit.termination))
                           .str());
  }
  std::string summary = fmt::format("identify local: ei = {:.6g} N m^2", fit.parameters.ei);
  for (const section::Jenkin& e : fit.parameters.jenkin) summary += fmt::format(", c = {:.6g} N m^2, h = {:.6g} N m", e.c, e.h);
  fmt::print(stderr, "{}; relative L1 error {:.3g} ({} cycles, worst {:.3g}), {} model runs{}\n", summary, fit.error,
             fit.cycle_errors.size(), *std::max_element(fit.cycle_errors.begin(), fit.cycle_errors.end()),
             fit.evaluations, optimiser_note(fit.termination));
  return kSuccess;
}

struct GlobalOptions {
  std::string experiment = "a";
  double length = 0.0;
  std::string input;
  std::string method = "fit";
  int sections = 40;
  int elements = 1;
  std::string optimizer = "subplex";
  std::string output;
  std::string fitted;
  bool json = false;
};

std::string cable_toml(const identification::GlobalIdentification& fit, const GlobalOptions& options) {
  return io::cable_file_toml(fit.cable, fmt::format("Identified by stockbridge identify global ({}) from experiment ({}) in {}:\n"
                                                    "relative L1 error {:.4g}, output offset {}.",
                                                    options.method, options.experiment, options.input, fit.error,
                                                    fit.output_offset));
}

/// A fit error above this is not a model of the record: worth a warning.
constexpr double kLargeFitError = 0.1;

/// Warnings for a global identification's inputs outside the typical ranges (the
/// length, the record's deflections or rotations) and for a large fit error.
void warn_global(const GlobalOptions& options, const identification::ExperimentMeasurement& measurement,
                 const identification::GlobalIdentification& fit) {
  std::vector<UnusualValue> options_found;
  check_typical(options_found, "length", options.length, typical::cable_length);
  warn_unusual_options(options_found);
  double largest = 0.0;
  for (const double p : measurement.prescribed) largest = std::max(largest, std::abs(p));
  if (measurement.experiment == cable::Experiment::a && !typical::tip_deflection_ratio.contains(largest / options.length)) {
    print_warnings({fmt::format("{}: x_m reaches {} m, more than {} of --length {} m: beyond the small deflections the "
                                "model assumes (deflections in mm under an x_m header?)",
                                options.input, format_value(largest), typical::tip_deflection_ratio.max,
                                format_value(options.length))});
  }
  if (measurement.experiment == cable::Experiment::b && !typical::tip_rotation.contains(largest)) {
    print_warnings({fmt::format("{}: phi_rad reaches {} rad, outside the typical 0 to {} rad (degrees under a phi_rad "
                                "header?)",
                                options.input, format_value(largest), typical::tip_rotation.max)});
  }
  if (fit.error > kLargeFitError) {
    print_warnings({options.method == "four-step"
                        ? fmt::format("the four-step result's relative L1 error {:.3g} is large (above {}): its "
                                      "formulas are biased where the cable never slips all along "
                                      "(docs/identification.md); --method fit fits the model to the whole record",
                                      fit.error, kLargeFitError)
                        : fmt::format("the fit's relative L1 error {:.3g} is large (above {}): the model does not "
                                      "follow the record (check its units, the experiment and --length)",
                                      fit.error, kLargeFitError)});
  }
}

int run_global(const GlobalOptions& options) {
  require_outputs_apart({{"-o", options.output}, {"--fitted", options.fitted}}, {{"the --input record", options.input}});
  identification::GlobalIdentificationOptions fit_options;
  fit_options.length = options.length;
  fit_options.sections = options.sections;
  fit_options.elements = options.elements;
  fit_options.optimizer = identification::parse_optimizer(options.optimizer);
  fit_options.validate();
  identification::ExperimentMeasurement measurement;
  measurement.experiment = cable::parse_experiment(options.experiment);
  const bool a = measurement.experiment == cable::Experiment::a;
  std::vector<std::vector<double>> columns = io::read_csv_columns(
      options.input, a ? std::vector<std::string>{"x_m", "force_n"} : std::vector<std::string>{"phi_rad", "clamp_moment_n_m"}, 8);
  measurement.prescribed = std::move(columns[0]);
  measurement.measured = std::move(columns[1]);
  identification::GlobalIdentification fit;
  try {
    fit = options.method == "four-step" ? identification::identify_four_step(measurement, fit_options)
                                        : identification::identify_fit(measurement, fit_options);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}: {}", options.input, e.what()));
  }
  warn_global(options, measurement, fit);
  if (!options.output.empty()) io::write_file_atomically(options.output, cable_toml(fit, options));
  if (!options.fitted.empty()) {
    const std::vector<double> model = identification::model_output(fit.cable, fit.output_offset, measurement);
    io::CsvWriter csv(a ? std::vector<std::string>{"x_m", "force_n", "model_force_n"}
                        : std::vector<std::string>{"phi_rad", "clamp_moment_n_m", "model_clamp_moment_n_m"});
    for (std::size_t k = 0; k < model.size(); ++k) csv.add_row({measurement.prescribed[k], measurement.measured[k], model[k]});
    io::write_file_atomically(options.fitted, csv.text());
  }
  const cable::CableDescription& c = fit.cable;
  if (options.json) {
    std::vector<io::JsonObject> jenkin;
    for (const cable::JenkinProfile& e : c.jenkin) jenkin.push_back(io::JsonObject().add("c", e.c.at(0.0)).add("h", e.h.at(0.0)));
    fmt::print("{}\n", io::JsonObject()
                           .add("ei", c.ei.at(0.0))
                           .add("jenkin", jenkin)
                           .add("error", fit.error)
                           .add("method", options.method)
                           .add("output_offset", fit.output_offset)
                           .add("evaluations", fit.evaluations)
                           .add("termination", termination_name(fit.termination))
                           .str());
  }
  std::string summary = fmt::format("identify global ({}): ei = {:.6g} N m^2", options.method, c.ei.at(0.0));
  for (const cable::JenkinProfile& e : c.jenkin) summary += fmt::format(", c = {:.6g} N m^2, h = {:.6g} N m", e.c.at(0.0), e.h.at(0.0));
  fmt::print(stderr, "{}; relative L1 error {:.3g}{}{}\n", summary, fit.error,
             fit.evaluations ? fmt::format(", {} cable simulations", fit.evaluations) : "", optimiser_note(fit.termination));
  return kSuccess;
}

}  // namespace

void add_identify_command(CLI::App& app, int& exit_code) {
  CLI::App* identify = app.add_subcommand("identify", "Identify cable parameters from measured hysteresis or impedance");
  identify->require_subcommand(1);
  auto local = std::make_shared<LocalOptions>();
  CLI::App* sub = identify->add_subcommand(
      "local", "Masing parameters of a cross-section from a moment-curvature record (curvature_per_m, moment_n_m)");
  sub->add_option("--input", local->input, "Measured record (CSV with curvature_per_m and moment_n_m, time order)")->required();
  sub->add_option("--elements", local->elements, "Jenkin elements to fit")->capture_default_str();
  sub->add_option("--optimizer", local->optimizer, "NLopt algorithm: subplex or nelder-mead (the dissertation's)")
      ->check(CLI::IsMember({"subplex", "nelder-mead"}))
      ->capture_default_str();
  sub->add_option("-o,--output", local->output, "Write the parameters as [cable] keys (TOML)");
  sub->add_option("--fitted", local->fitted, "Write measured and model moment along the record (CSV, for plotting)");
  sub->add_flag("--json", local->json, "Print {\"ei\": ..., \"jenkin\": [{\"c\": ..., \"h\": ...}], \"error\": ...} on stdout");
  sub->callback([local, &exit_code] { exit_code = run_local(*local); });

  auto global = std::make_shared<GlobalOptions>();
  CLI::App* g = identify->add_subcommand(
      "global", "Constant cable parameters from a cycle of experiment (a) or (b) (CSV as written by stockbridge cycle)");
  g->add_option("--experiment", global->experiment, "a: columns x_m, force_n;  b: columns phi_rad, clamp_moment_n_m")
      ->check(CLI::IsMember({"a", "b"}))
      ->required();
  g->add_option("--length", global->length, "Length of the measured cable, m")->required();
  g->add_option("--input", global->input, "Measured cycle (CSV)")->required();
  g->add_option("--method", global->method, "four-step (the dissertation's formulas) or fit (model-based, from four-step)")
      ->check(CLI::IsMember({"four-step", "fit"}))
      ->capture_default_str();
  g->add_option("--sections", global->sections, "Sections of the model cable")->capture_default_str();
  g->add_option("--elements", global->elements, "Jenkin elements (fit)")->capture_default_str();
  g->add_option("--optimizer", global->optimizer, "NLopt algorithm for fit: subplex or nelder-mead")
      ->check(CLI::IsMember({"subplex", "nelder-mead"}))
      ->capture_default_str();
  g->add_option("-o,--output", global->output, "Write a cable file (TOML) that cycle and damper files accept");
  g->add_option("--fitted", global->fitted, "Write measured and model output along the record (CSV, for plotting)");
  g->add_flag("--json", global->json, "Print {\"ei\": ..., \"jenkin\": [{\"c\": ..., \"h\": ...}], \"error\": ...} on stdout");
  g->callback([global, &exit_code] { exit_code = run_global(*global); });

  add_identify_impedance_command(*identify, exit_code);
}

}  // namespace stockbridge::cli
