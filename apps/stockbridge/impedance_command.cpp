// stockbridge impedance: Z(f, amplitude) of a damper over a frequency sweep.

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "journal_file.hpp"
#include "option_parsing.hpp"
#include "progress.hpp"
#include "report_output.hpp"
#include "solver_options.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/plausibility.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::cli {

namespace {

struct ImpedanceOptions {
  std::string damper_file;
  std::optional<std::string> velocity;  // lists as typed: given but empty is an error
  std::optional<std::string> displacement;
  double fmin = requests::FrequencyGrid{}.fmin;
  double fmax = requests::FrequencyGrid{}.fmax;
  int points = requests::FrequencyGrid{}.points;
  std::optional<std::string> frequencies;
  SolverFlags solver;
  int threads = requests::SweepRequest{}.threads;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
  std::string output;
  std::optional<std::string> report;
};

requests::SweepRequest sweep_request(const ImpedanceOptions& options) {
  requests::SweepRequest request;
  if (options.velocity.has_value() == options.displacement.has_value()) {  // named by the flags
    throw InvalidParameter("give either --velocity V[,V...] (m/s) or --displacement X[,X...] (m)");
  }
  if (options.velocity) request.velocities = parse_number_list(*options.velocity, "--velocity");
  if (options.displacement) request.displacements = parse_number_list(*options.displacement, "--displacement");
  if (options.frequencies) request.frequencies = parse_number_list(*options.frequencies, "--frequencies");
  request.grid = {options.fmin, options.fmax, options.points};
  request.solver = options.solver.settings();
  request.threads = options.threads;
  return request;
}

/// The sweep's rows written to `output` as they are final (a temporary file renamed
/// at the end), its summary figures running; the points themselves kept only for a
/// report. Throws Interrupted at Ctrl-C (the temporary file removed).
struct StreamedSweep {
  requests::SweepSummary summary;
  std::vector<damper::SweepRun> runs;  ///< empty unless kept for the report
};
StreamedSweep stream_to_csv(const damper::Damper& damper, const damper::SweepSpec& spec, const std::string& output,
                            bool keep_points, ProgressReport& progress) {
  StreamedSweep sweep;
  if (keep_points) {
    for (const double amplitude : spec.amplitudes) sweep.runs.push_back({amplitude, {}});
  }
  const requests::Table<damper::ImpedancePoint> table = requests::impedance_table(damper);
  requests::CsvFile<damper::ImpedancePoint> file(output, table);
  const InterruptRequest interrupt;
  damper::stream_sweep(
      damper, spec,
      [&](std::size_t a, std::size_t, damper::ImpedancePoint&& point) {
        if (InterruptRequest::requested()) throw Interrupted("the sweep was stopped");
        file.add(point);
        sweep.summary.add(spec.amplitudes[a], point);
        if (keep_points) sweep.runs[a].points.push_back(std::move(point));
      },
      std::ref(progress));
  file.commit();
  return sweep;
}

int run_impedance_command(const ImpedanceOptions& options, Invocation& invocation) {
  const requests::SweepRequest request = sweep_request(options);
  const damper::SweepSpec spec = requests::sweep_spec(request);
  check_report_path(options.report);
  const damper::Damper damper = read_damper_input(
      invocation, options.damper_file, {{"-o", options.output}, {"--report", options.report.value_or("")}},
      slip_policy(options.allow_unusual));
  warn_unusual_options(invocation, requests::unusual_values(request), slip_policy(options.allow_unusual));
  const auto start = std::chrono::steady_clock::now();
  ProgressReport progress(invocation, "impedance", options.quiet);
  std::optional<StreamedSweep> streamed;
  try {
    streamed.emplace(stream_to_csv(damper, spec, options.output, options.report.has_value(), progress));
  } catch (const Interrupted&) {
    fmt::print(stderr, "impedance: interrupted; nothing written\n");
    return kInterrupted;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.report) {
    const requests::ModesResult modes = requests::run_modes(damper);
    io::write_file_atomically(
        *options.report, report::impedance_report({std::filesystem::path(options.damper_file).stem().string(), &damper,
                                                   &streamed->runs, spec.constant_displacement, &modes},
                                                  invocation.report_context()));
  }

  const requests::SweepTally& tally = streamed->summary.tally();
  const int failed = tally.points - tally.converged;
  if (options.json) fmt::print("{}\n", streamed->summary.json(options.solver.method(), seconds).str());
  fmt::print(stderr, "impedance: {} points ({} method) in {:.2f} s, {} converged, largest energy error {}{}\n", tally.points,
             options.solver.method(), seconds, tally.converged,
             tally.max_energy_error ? fmt::format("{:.2g}", *tally.max_energy_error) : "none (no point converged)",
             tally.non_unique ? fmt::format("; {} points flagged non_unique (several steady states)", tally.non_unique) : "");
  if (failed == 0) return kSuccess;
  fmt::print(stderr, "impedance: {} points did not converge (converged = 0, numbers left empty in {}):\n", failed,
             options.output);
  const std::vector<requests::SweepSummary::Failure>& failures = streamed->summary.failures();
  for (std::size_t i = 0; i < failures.size() && i < 10; ++i) {
    fmt::print(stderr, "  f = {:.4g} Hz, amplitude {}: {}\n", failures[i].frequency_hz, failures[i].amplitude,
               failures[i].reason);
  }
  if (failures.size() > 10) fmt::print(stderr, "  ... and {} more\n", failures.size() - 10);
  return kNotConverged;
}

}  // namespace

void add_impedance_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<ImpedanceOptions>();
  CLI::App* sub = app.add_subcommand("impedance", "Nonlinear impedance Z(f, amplitude) of a damper over a frequency sweep");
  sub->add_option("damper", options->damper_file, "Damper description (TOML)")->required();
  sub->add_option("--velocity", options->velocity, "Clamp velocity amplitudes V, m/s, comma-separated (constant over the sweep)");
  sub->add_option("--displacement", options->displacement, "Clamp displacement amplitudes X, m, comma-separated, instead of --velocity");
  sub->add_option("--fmin", options->fmin, "Lowest frequency, Hz")->capture_default_str();
  sub->add_option("--fmax", options->fmax, "Highest frequency, Hz")->capture_default_str();
  sub->add_option("--points", options->points, "Frequencies, log-spaced from fmin to fmax")->capture_default_str();
  sub->add_option("--frequencies", options->frequencies, "Explicit frequencies, Hz, comma-separated (replaces fmin/fmax/points)");
  options->solver.add_to(*sub);
  sub->add_option("--threads", options->threads, "Parallel runs (amplitudes x distinct arms)")->capture_default_str();
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout");
  sub->add_flag("--quiet", options->quiet, "No progress on stderr (a bar on a terminal; else a line every 10 s after 10 s)");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  add_report_option(*sub, options->report, "the damper's numbers, |Z|, phase and power per amplitude, its linear modes");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_impedance_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
