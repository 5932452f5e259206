// stockbridge cycle: experiment (a) or (b) on a cable described by a TOML file.

#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/cycle_request.hpp"

namespace stockbridge::cli {

namespace {

struct CycleOptions {
  std::string cable_file;
  requests::CycleRequest request;
  bool json = false;
  bool allow_unusual = false;
  std::string output;
};

int run_cycle_command(const CycleOptions& options, Invocation& invocation) {
  (void)requests::experiment_drive(options.request);  // the options checked before the file is read
  const cable::Cable cable =
      read_cable_input(invocation, options.cable_file, {{"-o", options.output}}, slip_policy(options.allow_unusual));
  const requests::CycleResult result = requests::run_cycle(cable, options.request);
  print_warnings(invocation, result.warnings);
  io::write_file_atomically(options.output,
                            requests::cycle_table().values(requests::cycle_samples(result)).csv());
  const cable::ExperimentSummary& s = result.record.summary;
  if (options.json) fmt::print("{}\n", requests::cycle_summary(options.request, result).str());
  if (s.failed_samples > 0) {
    fmt::print(stderr,
               "cycle: {} of {} points did not converge (converged = 0 in {}); {}\n", s.failed_samples,
               result.record.samples.size(), options.output,
               std::isnan(s.loop_work) ? "the last cycle's energies are not given (null in --json)"
                                       : "the last cycle converged, its energies are given");
    return kNotConverged;
  }
  fmt::print(stderr, "cycle: experiment ({}), last cycle dissipates {} J (sliders), {} J (loop work); Newton iterations max {}, mean {:.2f}\n",
             options.request.experiment, s.slider_dissipation, s.loop_work, s.max_iterations, s.mean_iterations);
  return kSuccess;
}

}  // namespace

void add_cycle_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<CycleOptions>();
  CLI::App* sub = app.add_subcommand("cycle", "Run hysteresis experiment (a) tip force or (b) tip rotation on a cable");
  sub->add_option("cable", options->cable_file, "Cable description (TOML)")->required();
  sub->add_option("--experiment", options->request.experiment, "a: x = A sin(2 pi k/points), Q = 0;  b: phi = A sin(...), x = 0")
      ->check(CLI::IsMember({"a", "b"}))
      ->capture_default_str();
  sub->add_option("--amplitude", options->request.amplitude, "Amplitude A: m for (a), rad for (b)")->required();
  sub->add_option("--cycles", options->request.cycles, "Number of cycles")->capture_default_str();
  sub->add_option("--points", options->request.points, "Samples per cycle")->capture_default_str();
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &invocation] { invocation.set_exit_code(run_cycle_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
