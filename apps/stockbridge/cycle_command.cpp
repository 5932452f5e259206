// stockbridge cycle: experiment (a) or (b) on a cable described by a TOML file.

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "stockbridge/cable/experiment.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_writer.hpp"
#include "stockbridge/io/json_writer.hpp"

namespace stockbridge::cli {

namespace {

struct CycleOptions {
  std::string cable_file;
  std::string experiment = "a";
  double amplitude = 0.0;
  int cycles = 2;
  int points = 400;
  bool json = false;
  std::string output;
};

std::string cycle_csv(const cable::ExperimentRecord& record) {
  io::CsvWriter csv({"step", "x_m", "phi_rad", "force_n", "clamp_moment_n_m", "tip_moment_n_m",
                     "dissipated_energy_j", "newton_iterations", "residual_rad", "converged"});
  constexpr double kEmpty = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < record.samples.size(); ++k) {
    const cable::ExperimentSample& s = record.samples[k];
    const bool ok = s.solve.converged();
    csv.add_row({static_cast<double>(k), ok ? s.deflection : kEmpty, ok ? s.rotation : kEmpty,
                 ok ? s.tip_force : kEmpty, ok ? s.clamp_moment : kEmpty, ok ? s.tip_moment : kEmpty,
                 ok ? s.dissipated : kEmpty, static_cast<double>(s.solve.newton_iterations), s.solve.residual,
                 ok ? 1.0 : 0.0});
  }
  return csv.text();
}

io::JsonObject cycle_json(const cable::ExperimentSummary& s, const CycleOptions& options) {
  io::JsonObject json;
  json.add("experiment", options.experiment)
      .add("amplitude", options.amplitude)
      .add("cycles", options.cycles)
      .add("points", options.points)
      .add("last_cycle_dissipation_sliders_j", s.slider_dissipation)
      .add("last_cycle_dissipation_loop_j", s.loop_work)
      .add("last_cycle_measured_loop_area_j", s.measured_loop_area)
      .add("force_n", io::JsonObject().add("min", s.min_tip_force).add("max", s.max_tip_force))
      .add("clamp_moment_n_m", io::JsonObject().add("min", s.min_clamp_moment).add("max", s.max_clamp_moment))
      .add("x_m", io::JsonObject().add("min", s.min_deflection).add("max", s.max_deflection))
      .add("phi_rad", io::JsonObject().add("min", s.min_rotation).add("max", s.max_rotation))
      .add("newton_iterations", io::JsonObject().add("max", s.max_iterations).add("mean", s.mean_iterations))
      .add("failed_points", s.failed_samples);
  return json;
}

/// The cantilever is a small-deflection model: a tip deflection beyond 0.3 of the
/// length, or a rotation beyond 0.5 rad, is most often an amplitude in mm or degrees.
void warn_large_drive(const cable::ExperimentDrive& drive, double length) {
  if (drive.experiment == cable::Experiment::a && !typical::tip_deflection_ratio.contains(drive.amplitude / length)) {
    print_warnings({fmt::format("--amplitude = {}: more than {} of the cable's length {} m, beyond the small deflections "
                                "the model assumes (a unit mistake? the amplitude of experiment (a) is in m)",
                                format_value(drive.amplitude), typical::tip_deflection_ratio.max, format_value(length))});
  }
  if (drive.experiment == cable::Experiment::b && !typical::tip_rotation.contains(drive.amplitude)) {
    print_warnings({fmt::format("--amplitude = {}: outside the typical 0 to {} rad of a tip rotation (a unit mistake? "
                                "the amplitude of experiment (b) is in rad)",
                                format_value(drive.amplitude), typical::tip_rotation.max)});
  }
}

int run_cycle_command(const CycleOptions& options) {
  cable::ExperimentDrive drive;
  drive.experiment = cable::parse_experiment(options.experiment);
  drive.amplitude = options.amplitude;
  drive.cycles = options.cycles;
  drive.points = options.points;
  drive.validate();
  cable::Cantilever cantilever{read_cable_input(options.cable_file, {{"-o", options.output}})};
  warn_large_drive(drive, cantilever.cable().length());
  const cable::ExperimentRecord record = cable::run_experiment(cantilever, drive);
  io::write_file_atomically(options.output, cycle_csv(record));
  const cable::ExperimentSummary& s = record.summary;
  if (options.json) fmt::print("{}\n", cycle_json(s, options).str());
  if (s.failed_samples > 0) {
    fmt::print(stderr,
               "cycle: {} of {} points did not converge (converged = 0 in {}); {}\n", s.failed_samples,
               record.samples.size(), options.output,
               std::isnan(s.loop_work) ? "the last cycle's energies are not given (null in --json)"
                                       : "the last cycle converged, its energies are given");
    return kNotConverged;
  }
  fmt::print(stderr, "cycle: experiment ({}), last cycle dissipates {} J (sliders), {} J (loop work); Newton iterations max {}, mean {:.2f}\n",
             options.experiment, s.slider_dissipation, s.loop_work, s.max_iterations, s.mean_iterations);
  return kSuccess;
}

}  // namespace

void add_cycle_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<CycleOptions>();
  CLI::App* sub = app.add_subcommand("cycle", "Run hysteresis experiment (a) tip force or (b) tip rotation on a cable");
  sub->add_option("cable", options->cable_file, "Cable description (TOML)")->required();
  sub->add_option("--experiment", options->experiment, "a: x = A sin(2 pi k/points), Q = 0;  b: phi = A sin(...), x = 0")
      ->check(CLI::IsMember({"a", "b"}))
      ->capture_default_str();
  sub->add_option("--amplitude", options->amplitude, "Amplitude A: m for (a), rad for (b)")->required();
  sub->add_option("--cycles", options->cycles, "Number of cycles")->capture_default_str();
  sub->add_option("--points", options->points, "Samples per cycle")->capture_default_str();
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout");
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &exit_code] { exit_code = run_cycle_command(*options); });
}

}  // namespace stockbridge::cli
