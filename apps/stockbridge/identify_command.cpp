// stockbridge identify local: cable section parameters from a measured
// moment-curvature record.

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/io/json_writer.hpp"

namespace stockbridge::cli {

namespace {

struct LocalOptions {
  std::string input;
  int elements = 1;
  std::string optimizer = "subplex";
  std::string output;
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
                           .str());
  }
  std::string summary = fmt::format("identify local: ei = {:.6g} N m^2", fit.parameters.ei);
  for (const section::Jenkin& e : fit.parameters.jenkin) summary += fmt::format(", c = {:.6g} N m^2, h = {:.6g} N m", e.c, e.h);
  fmt::print(stderr, "{}; relative L1 error {:.3g} ({} cycles, worst {:.3g}), {} model runs\n", summary, fit.error,
             fit.cycle_errors.size(), *std::max_element(fit.cycle_errors.begin(), fit.cycle_errors.end()),
             fit.evaluations);
  return kSuccess;
}

}  // namespace

void add_identify_command(CLI::App& app, int& exit_code) {
  CLI::App* identify = app.add_subcommand("identify", "Identify cable parameters from measured hysteresis");
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
  sub->add_flag("--json", local->json, "Print {\"ei\": ..., \"jenkin\": [{\"c\": ..., \"h\": ...}], \"error\": ...} on stdout");
  sub->callback([local, &exit_code] { exit_code = run_local(*local); });
}

}  // namespace stockbridge::cli
