// stockbridge identify local: cable section parameters from a measured
// moment-curvature record.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/identify_request.hpp"

namespace stockbridge::cli {

namespace {

/// The section laws' names, for --law.
std::vector<std::string> law_names() {
  std::vector<std::string> names;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) names.push_back(std::string(law->name()));
  return names;
}

/// "masing (ei and jenkin), bouc-wen (ei_min, ei_max and chi0)".
std::string laws_taking() {
  std::string text;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    text += fmt::format("{}{} ({})", text.empty() ? "" : ", ", law->name(), law->takes());
  }
  return text;
}

/// What the summary line adds where the optimiser's run did not meet its tolerance.
std::string optimiser_note(Termination termination) {
  if (termination == Termination::converged || termination == Termination::not_run) return "";
  return fmt::format("; the optimiser stopped short of its tolerance ({}): the best point reached", termination_name(termination));
}

struct LocalOptions {
  std::string input;
  requests::LocalRequest request;
  std::string output;
  std::string fitted;
  bool json = false;
};

int run_local(const LocalOptions& options) {
  require_outputs_apart({{"-o", options.output}, {"--fitted", options.fitted}}, {{"the --input record", options.input}});
  (void)requests::local_options(options.request);
  std::vector<std::vector<double>> columns = io::read_csv_columns(options.input, {"curvature_per_m", "moment_n_m"}, 8);
  requests::LocalResult result;
  try {
    result = requests::run_local({std::move(columns[0]), std::move(columns[1])}, options.request);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}: {}", options.input, e.what()));
  }
  const identification::LocalIdentification& fit = result.fit;
  if (!options.output.empty()) {
    io::write_file_atomically(options.output, requests::local_parameters_toml(result, options.input));
  }
  if (!options.fitted.empty()) {
    const auto rows = requests::fitted_samples(result.record.curvature, result.record.moment, result.model);
    io::write_file_atomically(options.fitted, requests::local_fitted_table().values(rows).csv());
  }
  if (options.json) fmt::print("{}\n", requests::local_summary(result).str());
  std::string summary;
  if (fit.numbers) {
    summary = fmt::format("identify local ({}): {}", fit.numbers->law->title(), requests::law_numbers_text(*fit.numbers));
  } else {
    summary = fmt::format("identify local: ei = {:.6g} N m^2", fit.parameters.ei);
    for (const section::Jenkin& e : fit.parameters.jenkin) summary += fmt::format(", c = {:.6g} N m^2, h = {:.6g} N m", e.c, e.h);
  }
  fmt::print(stderr, "{}; relative L1 error {:.3g} ({} cycles, worst {:.3g}), {} model runs{}\n", summary, fit.error,
             fit.cycle_errors.size(), *std::max_element(fit.cycle_errors.begin(), fit.cycle_errors.end()),
             fit.evaluations, optimiser_note(fit.termination));
  return kSuccess;
}

struct GlobalOptions {
  std::string input;
  requests::GlobalRequest request;
  std::string output;
  std::string fitted;
  bool json = false;
};

int run_global(const GlobalOptions& options, Invocation& invocation) {
  require_outputs_apart({{"-o", options.output}, {"--fitted", options.fitted}}, {{"the --input record", options.input}});
  const requests::GlobalRequest& request = options.request;
  (void)requests::global_options(request);
  std::vector<std::vector<double>> columns = io::read_csv_columns(options.input, requests::global_record_columns(request), 8);
  requests::GlobalResult result;
  try {
    result = requests::run_global(request, std::move(columns[0]), std::move(columns[1]), options.input);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}: {}", options.input, e.what()));
  }
  print_warnings(invocation, result.warnings);
  if (!options.output.empty()) {
    io::write_file_atomically(options.output, requests::global_cable_toml(request, result, options.input));
  }
  if (!options.fitted.empty()) {
    const auto rows = requests::fitted_samples(result.measurement.prescribed, result.measurement.measured, result.model);
    io::write_file_atomically(options.fitted, requests::global_fitted_table(request).values(rows).csv());
  }
  if (options.json) fmt::print("{}\n", requests::global_summary(request, result).str());
  const cable::CableDescription& c = result.fit.cable;
  std::string summary;
  if (!c.law->jenkin_elements()) {
    summary = fmt::format("identify global ({}, {}): {}", request.method, c.law->title(),
                          requests::law_numbers_text(c.values()));
  } else {
    summary = fmt::format("identify global ({}): ei = {:.6g} N m^2", request.method, c.ei.at(0.0));
    for (const cable::JenkinProfile& e : c.jenkin) summary += fmt::format(", c = {:.6g} N m^2, h = {:.6g} N m", e.c.at(0.0), e.h.at(0.0));
  }
  fmt::print(stderr, "{}; relative L1 error {:.3g}{}{}\n", summary, result.fit.error,
             result.fit.evaluations ? fmt::format(", {} cable simulations", result.fit.evaluations) : "",
             optimiser_note(result.fit.termination));
  return kSuccess;
}

}  // namespace

void add_identify_command(CLI::App& app, Invocation& invocation) {
  CLI::App* identify = app.add_subcommand(
      "identify",
      "Identify cable parameters from measured hysteresis or impedance, or a conductor's self-damping from its tests");
  identify->require_subcommand(1);
  auto local = std::make_shared<LocalOptions>();
  CLI::App* sub = identify->add_subcommand(
      "local",
      "Masing (or Bouc-Wen) parameters of a cross-section from a moment-curvature record (curvature_per_m, moment_n_m)");
  sub->add_option("--input", local->input, "Measured record (CSV with curvature_per_m and moment_n_m, time order)")->required();
  sub->add_option("--law", local->request.law, "Section law to fit: " + laws_taking())
      ->check(CLI::IsMember(law_names()))
      ->capture_default_str();
  sub->add_option("--elements", local->request.elements, "Jenkin elements to fit (the Masing law)")->capture_default_str();
  sub->add_option("--optimizer", local->request.optimizer, "NLopt algorithm: subplex or nelder-mead (the dissertation's)")
      ->check(CLI::IsMember({"subplex", "nelder-mead"}))
      ->capture_default_str();
  sub->add_option("-o,--output", local->output, "Write the parameters as [cable] keys (TOML)");
  sub->add_option("--fitted", local->fitted, "Write measured and model moment along the record (CSV, for plotting)");
  sub->add_flag("--json", local->json,
                "Print {\"ei\": ..., \"jenkin\": [{\"c\": ..., \"h\": ...}], \"error\": ...} on stdout (Bouc-Wen: "
                "{\"law\": \"bouc-wen\", \"ei_min\": ..., \"ei_max\": ..., \"chi0\": ..., \"error\": ...})");
  sub->callback([local, &invocation] { invocation.set_exit_code(run_local(*local)); });

  auto global = std::make_shared<GlobalOptions>();
  CLI::App* g = identify->add_subcommand(
      "global", "Constant cable parameters from a cycle of experiment (a) or (b) (CSV as written by stockbridge cycle)");
  g->add_option("--experiment", global->request.experiment, "a: columns x_m, force_n;  b: columns phi_rad, clamp_moment_n_m")
      ->check(CLI::IsMember({"a", "b"}))
      ->required();
  g->add_option("--length", global->request.length, "Length of the measured cable, m")->required();
  g->add_option("--law", global->request.law, "Section law to fit: " + cable::section_law_names() + " (the laws of numbers with --method fit)")
      ->check(CLI::IsMember(law_names()))
      ->capture_default_str();
  g->add_option("--input", global->input, "Measured cycle (CSV)")->required();
  g->add_option("--method", global->request.method, "four-step (the dissertation's formulas) or fit (model-based, from four-step)")
      ->check(CLI::IsMember({"four-step", "fit"}))
      ->capture_default_str();
  g->add_option("--sections", global->request.sections, "Sections of the model cable")->capture_default_str();
  g->add_option("--elements", global->request.elements, "Jenkin elements (fit)")->capture_default_str();
  g->add_option("--optimizer", global->request.optimizer, "NLopt algorithm for fit: subplex or nelder-mead")
      ->check(CLI::IsMember({"subplex", "nelder-mead"}))
      ->capture_default_str();
  g->add_option("-o,--output", global->output, "Write a cable file (TOML) that cycle and damper files accept");
  g->add_option("--fitted", global->fitted, "Write measured and model output along the record (CSV, for plotting)");
  g->add_flag("--json", global->json,
              "Print {\"ei\": ..., \"jenkin\": [{\"c\": ..., \"h\": ...}], \"error\": ...} on stdout (Bouc-Wen: "
              "{\"law\": \"bouc-wen\", \"ei_min\": ..., \"ei_max\": ..., \"chi0\": ..., \"error\": ...})");
  g->callback([global, &invocation] { invocation.set_exit_code(run_global(*global, invocation)); });

  add_identify_impedance_command(*identify, invocation);
  add_identify_self_damping_command(*identify, invocation);
}

}  // namespace stockbridge::cli
