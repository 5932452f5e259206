// stockbridge identify self-damping: the power law of a conductor's self-damping
// fitted to its tests on a laboratory span (IEEE 563, IEC 62567).

#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/measurements/self_damping_tests.hpp"
#include "stockbridge/requests/self_damping_request.hpp"

namespace stockbridge::cli {

namespace {

struct SelfDampingOptions {
  std::string input;
  std::optional<double> n;
  std::string output;
  bool json = false;
  bool allow_unusual = false;
};

int run_self_damping(const SelfDampingOptions& options, Invocation& invocation) {
  require_outputs_apart({{"-o", options.output}}, {{"the test file", options.input}});
  const measurements::SelfDampingTests tests =
      measurements::load_self_damping_tests(options.input, slip_policy(options.allow_unusual));
  print_warnings(invocation, tests.warnings);
  measurements::SelfDampingFit fit;
  try {
    fit = measurements::fit_self_damping(tests.tests, options.n);
  } catch (const InvalidParameter& e) {
    if (e.field() == "n") throw InputError(fmt::format("--n{} (in {})", e.detail(), options.input));
    throw InputError(fmt::format("{}: {}", options.input, e.what()));
  }
  if (!options.output.empty()) {
    io::write_file_atomically(options.output, requests::self_damping_table(fit, options.input));
  }
  if (options.json) fmt::print("{}\n", requests::self_damping_summary(fit, tests.warnings).str());
  fmt::print(stderr, "{}\n", requests::self_damping_summary_line(fit));
  for (const std::string& note : fit.notes) fmt::print(stderr, "note: {}\n", note);
  return kSuccess;
}

}  // namespace

void add_identify_self_damping_command(CLI::App& identify, Invocation& invocation) {
  auto options = std::make_shared<SelfDampingOptions>();
  CLI::App* sub = identify.add_subcommand(
      "self-damping", "The power law P = k Y^l f^m / (T/1000)^n of a conductor's self-damping from its tests "
                      "(tension_n, frequency_hz, amplitude_m, power_w_per_m)");
  sub->add_option("tests", options->input,
                  "Self-damping tests (CSV: tension_n, frequency_hz, amplitude_m antinode single peak, power_w_per_m)")
      ->required();
  sub->add_option("--n", options->n,
                  "The tension exponent n, fixed (needed when every test is at one tension; with several, it fixes "
                  "n instead of fitting it)");
  sub->add_option("-o,--output", options->output,
                  "Write the fitted law as a span file's [self_damping] table (TOML, law = \"power\")");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_flag("--json", options->json,
                "Print {\"k\": {\"value\": ..., \"standard_error\": ...}, \"l\": ..., \"m\": ..., \"n\": ..., "
                "\"n_given\": ..., \"points\": ..., \"residual_rms_ln_p\": ..., \"r_squared\": ..., ...} on stdout");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_self_damping(*options, invocation)); });
}

}  // namespace stockbridge::cli
