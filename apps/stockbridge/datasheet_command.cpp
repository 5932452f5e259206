// stockbridge datasheet: a damper's data sheet as one self-contained HTML page: its
// numbers, its impedance and power at the velocities damper standards test, its
// linear modes, and on each span given its damped and undamped stress and life.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "progress.hpp"
#include "report_output.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/modes_request.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

struct DatasheetOptions {
  std::string damper_file;
  std::vector<std::string> spans;
  std::string velocity = "0.05,0.1,0.2";
  double fmin = 5.0;
  double fmax = 100.0;
  int points = 120;
  int span_points = requests::SpanRequest{}.points;
  int threads = 1;
  bool quiet = false;
  bool allow_unusual = false;
  std::string output;
};

/// The span of a span file with this damper in place of each of its dampers (at
/// their positions and ends); InvalidParameter where the file places none.
span::Span span_with_datasheet_damper(const io::SpanFile& file, const std::string& path, const damper::Damper& damper,
                                      const std::string& name) {
  if (file.span.dampers().empty()) {
    throw InvalidParameter(fmt::format("--spans {}: the span file places no damper: give a [[damper]] with its position "
                                       "(its file or impedance is replaced by {})",
                                       path, name));
  }
  std::vector<span::SpanDamper> dampers;
  for (const span::SpanDamper& d : file.span.dampers()) {
    dampers.push_back({damper, d.position, d.both_ends, name, nullptr, std::nullopt});
  }
  return file.span.with_dampers(std::move(dampers));
}

int run_datasheet_command(const DatasheetOptions& options, Invocation& invocation) {
  check_report_path(options.output, "-o");
  requests::SweepRequest sweep;
  sweep.velocities = parse_number_list(options.velocity, "--velocity");
  sweep.grid = {options.fmin, options.fmax, options.points};
  sweep.threads = options.threads;
  const damper::SweepSpec spec = requests::sweep_spec(sweep);
  require_in_range("span-points", options.span_points, 2, 100000);
  const damper::Damper damper =
      read_damper_input(invocation, options.damper_file, {{"-o", options.output}}, slip_policy(options.allow_unusual));
  const std::string name = std::filesystem::path(options.damper_file).stem().string();
  std::vector<io::SpanFile> span_files;
  for (const std::string& path : options.spans) {
    span_files.push_back(
        read_span_input(invocation, path, {{"-o", options.output}}, slip_policy(options.allow_unusual)));
  }

  ProgressReport progress(invocation, "datasheet: impedance", options.quiet);
  const std::vector<damper::SweepRun> runs = damper::run_sweep(damper, spec, std::ref(progress));
  const requests::ModesResult modes = requests::run_modes(damper);
  report::DatasheetInput input{name, &damper, &runs, &modes, {}, {}};
  requests::SpanRequest request;
  request.points = options.span_points;
  request.threads = options.threads;
  for (std::size_t k = 0; k < span_files.size(); ++k) {
    const span::Span s = span_with_datasheet_damper(span_files[k], options.spans[k], damper, name);
    input.span_names.push_back(std::filesystem::path(options.spans[k]).stem().string());
    input.spans.push_back(requests::run_span(s, span_files[k].balance, requests::check_span_request(request)));
    print_warnings(invocation, input.spans.back().analysis.warnings);
  }
  io::write_file_atomically(options.output, report::datasheet(input, invocation.report_context()));

  const requests::SweepTally tally = requests::tally(runs);
  int span_points = 0, span_converged = 0;
  for (const requests::SpanResult& s : input.spans) {
    span_points += s.analysis.balance.summary.points;
    span_converged += s.analysis.balance.summary.converged;
  }
  if (!options.quiet) {
    fmt::print(stderr, "datasheet: {}: {} of {} impedance points and {} of {} span points converged\n", options.output,
               tally.converged, tally.points, span_converged, span_points);
  }
  if (tally.converged == tally.points && span_converged == span_points) return kSuccess;
  fmt::print(stderr, "datasheet: {} impedance and {} span points did not converge (the sheet lists them under "
                     "Warnings; no figure rests on them)\n",
             tally.points - tally.converged, span_points - span_converged);
  return kNotConverged;
}

}  // namespace

void add_datasheet_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<DatasheetOptions>();
  CLI::App* sub = app.add_subcommand(
      "datasheet", "A damper's data sheet (self-contained HTML): its numbers, impedance and power at the test "
                   "velocities, linear modes, and its stress and life on each span given");
  sub->add_option("damper", options->damper_file, "Damper description (TOML)")->required();
  sub->add_option("--spans", options->spans,
                  "Span files (TOML): the damper replaces each file's dampers, at their positions")
      ->expected(1, -1);
  sub->add_option("--velocity", options->velocity, "Clamp velocity amplitudes, m/s, comma-separated (the test velocities)")
      ->capture_default_str();
  sub->add_option("--fmin", options->fmin, "Lowest frequency of the impedance sweep, Hz")->capture_default_str();
  sub->add_option("--fmax", options->fmax, "Highest frequency, Hz")->capture_default_str();
  sub->add_option("--points", options->points, "Frequencies of the sweep, log-spaced")->capture_default_str();
  sub->add_option("--span-points", options->span_points, "Frequencies of each span's balance over its wind band")
      ->capture_default_str();
  sub->add_option("--threads", options->threads, "Parallel runs")->capture_default_str();
  sub->add_flag("--quiet", options->quiet, "No progress on stderr");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output HTML file")->required();
  sub->callback([options, &invocation] { invocation.set_exit_code(run_datasheet_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
