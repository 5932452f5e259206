// stockbridge simulate SPAN.toml --frequency F: the span in time under the energy
// balance's own wind, with its dampers each by its own model in time
// (requests/simulate_request.hpp): the history CSV (-o) written row by row, the
// steady figures beside the balance's on stdout (or --json).

#include <chrono>
#include <memory>
#include <optional>
#include <vector>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "journal_file.hpp"
#include "option_parsing.hpp"
#include "report_output.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/requests/simulate_request.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

struct SimulateOptions {
  std::string span_file;
  requests::SimulateRequest request;
  std::optional<std::string> probes;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
  std::string output;
  std::optional<std::string> report;
};

void print_simulation_report(const span::Span& span, const requests::SimulateResult& r) {
  const span::EbmWindHistory& h = r.history;
  fmt::print("simulate: {}{} m, {} ends, at {:.6g} Hz (the mode nearest {:.6g} Hz), {} elements, dt = {:.4g} s\n",
             span.conductor().name.empty() ? "" : span.conductor().name + ", ", format_value(span.length()), span::beam_ends_name(r.settings.ends),
             h.frequency_hz, r.asked_frequency_hz, h.elements, h.dt_s);
  if (r.wind == span::WindInTime::wake) {
    fmt::print("wind: the wake oscillator, shedding at {:.6g} Hz (U = {:.4g} m/s)\n", r.asked_frequency_hz,
               h.wind_speed_m_s);
  }
  fmt::print("{:.4g} s simulated ({} periods) from {:.4g} mm: {}\n", h.time_s, h.envelope_m.size(),
             r.start_amplitude_m * 1e3,
             h.settled ? "settled" : h.interrupted ? "interrupted" : "not settled (--duration longer)");
  const bool balanced = r.balance_converged();
  const span::BalancePoint* p = balanced ? &r.balance : nullptr;
  if (!h.settled) {
    fmt::print("the last period's envelope: {:.6g} mm (not a steady answer)\n", h.envelope_m.empty() ? 0.0 : h.envelope_m.back() * 1e3);
    return;
  }
  fmt::print("steady figures: means over the last {} periods ({}), the envelope fluctuating by {:.2g} % (standard deviation)\n",
             h.figure_periods, h.settled_by == span::SettledBy::mean ? "settled in the mean" : "settled",
             100.0 * h.envelope_fluctuation);
  fmt::print("antinode amplitude at mid-span: {:.6g} mm; the balance's {}\n", h.antinode_amplitude_m * 1e3,
             p ? fmt::format("{:.6g} mm (ratio {:.4f})", p->amplitude * 1e3, h.antinode_amplitude_m / p->amplitude)
               : std::string("did not converge"));
  fmt::print("wind's power {:.4g} W; the self-damping's {:.4g} W\n", h.wind_power_w, h.damping_power_w);
  fmt::print("loop amplitude next to clamp 1: {:.6g} mm; the balance's {}\n", h.end_loop_amplitude_m[0] * 1e3,
             p ? fmt::format("{:.6g} mm (ratio {:.4f})", p->clamp_loop_amplitude * 1e3,
                             h.end_loop_amplitude_m[0] / p->clamp_loop_amplitude)
               : std::string("-"));
  for (std::size_t d = 0; d < h.dampers.size(); ++d) {
    const span::DamperInTimeFigures& f = h.dampers[d];
    fmt::print("damper_{} ({} at {:.6g} m): {:.4g} W (its cables {:.4g} W), clamp {:.4g} mm/s, force harmonics",
               d + 1, f.name, f.position_m, f.power_w, f.dissipated_w, f.velocity_amplitude_m_s * 1e3);
    for (const double a : f.force_harmonics_n) fmt::print(" {:.3g}", a);
    fmt::print(" N\n");
  }
}

int run_simulate_command(SimulateOptions& options, Invocation& invocation) {
  if (options.probes) options.request.probes = parse_number_list(*options.probes, "--probe");
  requests::validate(options.request);
  check_report_path(options.report);
  const io::SpanFile file = read_span_input(invocation, options.span_file,
                                            {{"-o", options.output}, {"--report", options.report.value_or("")}},
                                            slip_policy(options.allow_unusual));
  invocation.flush_warnings();
  span::check_in_time(file.span);
  const requests::Table<requests::SimulationRow> table = requests::simulation_table(
      requests::probe_columns(requests::simulation_probes(file.span, options.request)),
      requests::simulation_dampers(file.span));
  requests::CsvFile<requests::SimulationRow> csv(options.output, table);
  const InterruptRequest interrupt;
  const auto start = std::chrono::steady_clock::now();
  double last_line = 0.0;
  auto progress = [&](double simulated, double duration) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.quiet || seconds - last_line < 10.0) return;
    last_line = seconds;
    fmt::print(stderr, "simulate: {:.0f} of {:.0f} s simulated in {:.0f} s\n", simulated, duration, seconds);
  };
  requests::SimulateResult result;
  std::size_t rows = 0;
  try {
    result = requests::run_simulate(
        file, options.request,
        [&](const requests::SimulationRow& row) {
          csv.add(row);
          ++rows;
        },
        progress, &InterruptRequest::flag());
  } catch (const NumericalError& e) {  // the rows before it stand; with none, nothing is written
    if (rows > 0) csv.commit();
    fmt::print(stderr, "simulate: {}; {}\n", e.what(),
               rows > 0 ? fmt::format("the {} rows before it are in {}", rows, options.output) : "nothing written");
    return kNotConverged;
  }
  csv.commit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.report && !result.history.interrupted) {
    io::write_file_atomically(*options.report, report::simulate_report(file.span, file.balance.damper_model, result,
                                                                       invocation.report_context()));
  }
  if (options.json) {
    fmt::print("{}\n", requests::simulate_summary(file.span, result).str());
  } else if (!options.quiet) {
    print_simulation_report(file.span, result);
  }
  fmt::print(stderr, "simulate: {:.4g} s simulated in {:.2f} s, {} rows in {}\n", result.history.time_s, result.seconds,
             rows, options.output);
  if (result.history.interrupted) {
    fmt::print(stderr, "simulate: interrupted; the {} rows simulated are in {}\n", rows, options.output);
    return kInterrupted;
  }
  if (!result.history.settled) {
    fmt::print(stderr, "simulate: the envelope did not settle within {} s (--duration longer); no steady figure given\n",
               result.settings.duration_s);
    return kNotConverged;
  }
  return kSuccess;
}

}  // namespace

void add_simulate_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<SimulateOptions>();
  requests::SimulateRequest& r = options->request;
  CLI::App* sub = app.add_subcommand(
      "simulate", "The span in time under the energy balance's wind, with its dampers' own models: the balance's check");
  sub->add_option("span", options->span_file, "Span description (TOML)")->required();
  sub->add_option("--frequency", r.frequency_hz, "The drive, Hz (the span's natural mode nearest it is taken)")->required();
  const span::TimeSettings defaults;
  sub->add_option("--duration", r.duration_s,
                  fmt::format("Simulated time at most, s (default: the span file's [time] duration, else {})",
                              defaults.duration_s));
  sub->add_option("--ends", r.ends,
                  fmt::format("How the span clamps hold the conductor: clamped or pinned (default: the span file's "
                              "[span] ends, else {})",
                              span::beam_ends_name(defaults.ends)));
  sub->add_option("--elements-per-wavelength", r.elements_per_wavelength,
                  fmt::format("Beam elements per wavelength at the drive (default: the span file's [time] "
                              "elements_per_wavelength, else {})",
                              defaults.elements_per_wavelength));
  sub->add_option("--steps-per-period", r.steps_per_period,
                  fmt::format("Time steps per period of the drive (default: the span file's [time] steps_per_period, "
                              "else {})",
                              defaults.steps_per_period));
  sub->add_option("--wind", r.wind,
                  "ebm (the energy balance's own wind: the check) or wake (a wake oscillator per element, the span "
                  "file's [wake], shedding at --frequency)")
      ->capture_default_str();
  sub->add_option("--probe", options->probes,
                  "Where the history gives the displacement, m from end 1, comma-separated (default: the Y_b point of "
                  "clamp 1, each damper, mid-span)");
  sub->add_option("--start-amplitude", r.start_amplitude_m,
                  "The drive mode's antinode amplitude at the start, m (default: the balance's at the frequency)");
  sub->add_option("--every", r.every, "A history row every this many steps")->capture_default_str();
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout");
  sub->add_flag("--quiet", options->quiet, "No progress on stderr");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "History CSV file")->required();
  add_report_option(*sub, options->report,
                    "whether the run agrees with the balance, its settings, the figures side by side, the dampers, the "
                    "envelope and the amplitude along the span");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_simulate_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
