// stockbridge fatigue-tests: a conductor's fatigue tests (MODEL.md section 14): each
// test's Poffenberger-Swart stress and its place against the Safe Border Line, the
// censored Basquin fit and its design curve, written as an S-N curve file a span's
// [fatigue] curve can name.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "report_output.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/report/fatigue_tests_report.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/fatigue_tests_request.hpp"

namespace stockbridge::cli {

namespace {

struct FatigueTestsOptions {
  std::string tests_file;
  std::optional<std::string> conductor;
  std::optional<std::string> curve;
  std::optional<std::string> report;
  bool json = false;
  bool allow_unusual = false;
  std::string output;
};

int run_fatigue_tests_command(const FatigueTestsOptions& options, Invocation& invocation) {
  check_report_path(options.report);
  requests::FatigueTestsRequest request;
  request.file = options.tests_file;
  request.conductor = options.conductor;
  request.policy = slip_policy(options.allow_unusual);
  const requests::FatigueTestsOutcome outcome = requests::run_fatigue_tests(request);
  std::vector<CommandFile> inputs;
  for (const auto& path : outcome.inputs) inputs.push_back({"an input", path.string()});
  require_outputs_apart({{"-o", options.output}, {"--report", options.report.value_or("")},
                         {"--curve", options.curve.value_or("")}},
                        inputs);
  // Everything written is made before anything is: a refusal (a slope >= 0 gives no
  // curve) leaves every file as it was.
  const std::string csv = requests::fatigue_tests_values(outcome.result).csv();
  const std::string curve = options.curve ? requests::fatigue_tests_curve_toml(outcome) : std::string();
  print_warnings(invocation, outcome.warnings);
  const std::string report =
      options.report ? report::fatigue_tests_report(outcome, invocation.report_context()) : std::string();
  io::write_file_atomically(options.output, csv);
  if (options.curve) io::write_file_atomically(*options.curve, curve);
  if (options.report) io::write_file_atomically(*options.report, report);

  const measurements::FatigueTestsResult& r = outcome.result;
  const measurements::BasquinFit& f = r.fit;
  if (options.json) {
    io::JsonObject json = requests::fatigue_tests_summary(outcome);
    if (options.curve) json.add("curve", *options.curve);
    fmt::print("{}\n", json.str());
    return kSuccess;
  }
  fmt::print("{} tests: {} failures, {} runouts (censored)\n", r.tests.size(), f.failures, f.runouts);
  fmt::print("Basquin fit: log10 N = {:.5g} (± {:.2g}) {:+.5g} (± {:.2g}) log10 sigma_MPa, scatter s = {:.4g} (± {:.2g})\n",
             f.a, f.a_standard_error, f.b, f.b_standard_error, f.scatter, f.scatter_standard_error);
  fmt::print("design curve (mean - 2 s): log10 N = {:.5g} {:+.5g} log10 sigma_MPa\n", f.design_a(), f.b);
  fmt::print("failures below the CIGRE Safe Border Line: {} of {} ({:.3g} %)\n", r.below_sbl.size(), f.failures,
             100.0 * r.below_sbl_fraction());
  for (std::size_t i : r.below_sbl) {
    fmt::print("  {}: {:.4g} cycles at {:.4g} MPa (the line's: {:.4g})\n", r.tests[i].test, r.tests[i].cycles,
               requests::megapascal_of(r.points[i].stress), r.points[i].sbl_cycles);
  }
  if (options.curve) fmt::print("design curve written to {}\n", *options.curve);
  return kSuccess;
}

}  // namespace

void add_fatigue_tests_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<FatigueTestsOptions>();
  CLI::App* sub = app.add_subcommand(
      "fatigue-tests", "A conductor's fatigue tests: stresses, the Safe Border Line, a censored Basquin fit and its "
                       "design curve (an S-N curve file for a span's [fatigue] curve)");
  sub->add_option("tests", options->tests_file,
                  "Fatigue-test CSV: test, conductor, tension_n, yb_pp_mm, cycles, failed (docs/measurements.md)")
      ->required();
  sub->add_option("--conductor", options->conductor, "Keep only this conductor's rows (a catalogue type or the file's name)");
  sub->add_option("--curve", options->curve, "Write the fitted design curve (mean - 2 s) as an S-N curve file (TOML)");
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout instead of the text");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file: the tests with their stresses")->required();
  add_report_option(*sub, options->report, "the S-N plot, the fit and its design curve, the tests against the Safe Border Line");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_fatigue_tests_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
