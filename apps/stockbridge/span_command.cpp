// stockbridge span: the energy balance of a span with its dampers over the wind
// band (span/balance.hpp): amplitudes, powers, stresses against the endurance
// limit, the undamped span beside it, the life when the span file gives the
// climate, and optionally the dampers' best position.

#include <algorithm>
#include <chrono>
#include <cmath>
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
#include "span_modes_command.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/requests/time_check.hpp"
#include "stockbridge/span/tension_figures.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

struct SpanOptions {
  std::string span_file;
  std::optional<std::string> frequencies;
  int points = requests::SpanRequest{}.points;
  bool no_dampers = false;
  bool no_attachments = false;
  std::optional<std::string> damper_model;
  std::optional<std::string> optimize_position;
  double spacing_min = requests::SpanRequest{}.spacing_min;
  std::string objective = requests::SpanRequest{}.objective;
  int threads = requests::SpanRequest{}.threads;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
  std::string output;
  std::optional<std::string> report;
  std::optional<std::string> profile;
  std::optional<std::string> check_time;         ///< frequencies, Hz
  std::optional<std::string> check_time_output;  ///< the checks' CSV
};

requests::CheckedSpanRequest span_request_of(const SpanOptions& options) {
  requests::SpanRequest request;
  if (options.frequencies) request.frequencies = parse_number_list(*options.frequencies, "--frequencies");
  request.points = options.points;
  request.no_dampers = options.no_dampers;
  request.no_attachments = options.no_attachments;
  request.damper_model = options.damper_model;
  if (options.optimize_position) {
    const std::string& text = *options.optimize_position;
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) {
      throw InvalidParameter(fmt::format("--optimize-position = '{}': expected AMIN:AMAX (m from the span end's clamp), "
                                         "e.g. 0.5:3",
                                         printable(text)));
    }
    request.position_min = parse_number(text.substr(0, colon), "--optimize-position AMIN");
    request.position_max = parse_number(text.substr(colon + 1), "--optimize-position AMAX");
  }
  request.spacing_min = options.spacing_min;
  request.objective = options.objective;
  request.threads = options.threads;
  return requests::check_span_request(request);
}

std::string span_megapascal(double pascal) { return fmt::format("{:.3g} MPa", requests::megapascal_of(pascal)); }

std::string span_years(const span::LifeEstimate& life) {
  return std::isfinite(life.life_years) ? fmt::format("{:.3g} years", life.life_years) : "unlimited (no damage)";
}

/// A life, or why there is none.
std::string span_life(const std::optional<span::LifeEstimate>& life, int missing) {
  return life ? span_years(*life) : fmt::format("unknown ({} points missing)", missing);
}

/// "118, 122" (m).
std::string span_places(const std::vector<double>& x) {
  std::string out;
  for (const double p : x) out += fmt::format("{}{:.4g}", out.empty() ? "" : ", ", p);
  return out;
}

std::string span_damper_place(const span::SpanDamper& d) {
  if (d.in_span()) return fmt::format("at {} m from end 1", span_places(d.along));
  return fmt::format("{:.4g} m from the clamp, {}", d.position, d.both_ends ? "both ends" : "one end");
}

void print_span_report(const requests::SpanResult& result) {
  const span::SpanAnalysis& a = result.analysis;
  const span::Span& s = a.span;
  const span::BalanceSummary& summary = a.balance.summary;
  const std::vector<double>& f = a.frequencies;
  if (!summary.all_converged()) {
    fmt::print("converged {} of {} frequencies: the largest stresses below are of those {} only; the verdict and the "
               "life need every point\n",
               summary.converged, summary.points, summary.converged);
  }
  fmt::print("span: {}{} m at {:.6g} N, {} frequencies from {:.4g} to {:.4g} Hz\n",
             s.conductor().name.empty() ? "" : s.conductor().name + ", ", format_value(s.length()), s.tension(),
             f.size(), f.front(), f.back());
  const span::TensionFigures t = span::tension_figures(s);
  fmt::print("tension: {:.4g} kN, {:.3g} % RTS, H/w = {:.4g} m; span parameter L D / m = {:.4g} m^3/kg\n",
             t.tension / 1e3, 100.0 * t.fraction_of_rts, t.catenary_parameter, t.span_parameter);
  if (const std::optional<span::SafeDesignTension> safe = span::safe_design_tension(s)) {
    fmt::print("CIGRE TB 273, terrain category {}: H/w {:.4g} m is {} the {:.4g} m an undamped single conductor "
               "allows{}\n",
               safe->terrain.category, safe->catenary_parameter, safe->within ? "within" : "above",
               safe->terrain.catenary_parameter_limit, safe->within ? "" : " (dampers needed)");
  }
  if (s.dampers().empty()) {
    fmt::print("dampers: none\n");
  } else {
    for (const span::SpanDamper& d : s.dampers()) {
      fmt::print("damper {}: {} ({} model{}{})\n", d.name, span_damper_place(d), span::damper_model_name(result.damper_model),
                 d.measured() ? ", Z from its measured sheet" : "", d.fit ? "; " + d.fit->summary() : std::string());
    }
  }
  for (const span::SpanMass& m : s.masses()) {
    fmt::print("mass {}: {:.4g} kg at {} m from end 1\n", m.name, m.mass, span_places(m.positions));
  }
  if (a.position) {
    std::string positions;
    for (const double x : a.position->positions) positions += fmt::format("{}{:.4g}", positions.empty() ? "" : ", ", x);
    fmt::print("positions: {} m minimise the {} ({} balances on the tables)\n", positions,
               a.position->criterion == span::PositionObjective::life ? "damage per year" : "largest fymax stress", a.position->balances);
  }
  if (summary.converged > 0) {
    fmt::print("largest fymax stress: {} at {:.4g} Hz (undamped {} at {:.4g} Hz)\n",
               span_megapascal(summary.max_stress_fymax), summary.max_stress_frequency_hz,
               span_megapascal(summary.undamped_max_stress_fymax), summary.undamped_max_stress_frequency_hz);
    if (!s.dampers().empty()) {
      fmt::print("largest stress at a damper clamp: {}\n", span_megapascal(summary.max_damper_clamp_stress));
    }
    if (s.has_attachments() || summary.max_judged_stress_place != "span clamp 1") {
      fmt::print("governing place: {}, {} at {:.4g} Hz\n", summary.max_judged_stress_place,
                 span_megapascal(summary.max_judged_stress), summary.max_judged_stress_frequency_hz);
    }
    fmt::print("largest Yb ({:.3g} mm from the clamp): {:.3g} mm peak-to-peak, {:.4g} microstrain (undamped {:.3g} "
               "mm, {:.4g} microstrain)\n",
               1e3 * s.fatigue().yb_distance, 1e3 * summary.max_bending_amplitude,
               span::bending_strain_pp_microstrain(s.conductor(), summary.max_stress_poffenberger_swart),
               1e3 * summary.undamped_max_bending_amplitude,
               span::bending_strain_pp_microstrain(s.conductor(), summary.undamped_max_stress_poffenberger_swart));
  }
  if (std::isfinite(a.sheet_error_estimate)) {
    fmt::print("measured sheets: leaving out every other curve moves the fymax stress by up to {:.3g} % (the band: "
               "CSV stress_fymax_low_mpa, stress_fymax_high_mpa){}\n",
               100.0 * a.sheet_error_estimate,
               std::isfinite(summary.max_judged_stress_high)
                   ? fmt::format("; the band's top reaches {}, {:.3g} % of the endurance limit",
                                 span_megapascal(summary.max_judged_stress_high),
                                 100.0 * summary.max_judged_stress_high / summary.endurance_limit)
                   : std::string());
  }
  fmt::print("criterion {}: {}, {} ({:.4g} microstrain peak-to-peak) against the largest {}: {} (undamped: {})\n",
             span::fatigue_criterion_name(s.fatigue().criterion), s.criterion_description(),
             span_megapascal(summary.endurance_limit),
             span::bending_strain_pp_microstrain(s.conductor(), summary.endurance_limit),
             s.judges_poffenberger_swart() ? "bending strain from Yb" : "fymax stress",
             span::verdict_name(summary.verdict), span::verdict_name(summary.undamped_verdict));
  if (s.fatigue().life) {
    fmt::print("life: {} (undamped {}); lives are comparative: they rest on the assumed wind climate\n",
               span_life(summary.life, summary.life_missing_points),
               span_life(summary.undamped_life, summary.undamped_life_missing_points));
  }
  if (summary.several_states > 0) {
    fmt::print("several self-consistent states at {} frequencies (the state continued from the band's low end is "
               "reported; CSV column several_states)\n",
               summary.several_states);
  }
}

void print_time_checks(const std::vector<requests::TimeCheck>& checks, bool poffenberger_swart) {
  fmt::print("checked in time (the simulation's over the balance's; docs/time-domain.md):\n");
  for (const requests::TimeCheck& c : checks) {
    if (!c.compared()) {
      fmt::print("  {:.4g} Hz: nothing compared ({})\n", c.asked_frequency_hz,
                 !c.result ? "no run" : !c.result->history.settled ? "not settled" : "the balance did not converge");
      continue;
    }
    const requests::ComparedFigure& stress = requests::judged_stress(c.figures, poffenberger_swart);
    fmt::print("  {:.4g} Hz (simulated at {:.6g} Hz, {:.3g} s): antinode amplitude {:.3f}, {} stress {:.3f}{}\n",
               c.asked_frequency_hz, c.result->history.frequency_hz, c.result->history.time_s,
               c.figures.antinode_amplitude_m.ratio, poffenberger_swart ? "Poffenberger-Swart" : "fymax", stress.ratio,
               c.agrees() ? "" : fmt::format(" (more than {:.0f} % apart)", 100.0 * requests::kTimeCheckTolerance));
  }
}

/// The simulations of --check-time beside the balance; none without it. Ctrl-C while
/// they run ends them (`interrupted`).
std::vector<requests::TimeCheck> span_time_checks(const SpanOptions& options, const io::SpanFile& file,
                                                  const requests::CheckedSpanRequest& request,
                                                  const requests::SpanResult& result, Invocation& invocation,
                                                  bool& interrupted) {
  if (!options.check_time) return {};
  const InterruptRequest interrupt;
  const std::vector<double> frequencies = parse_number_list(*options.check_time, "--check-time");
  if (!options.quiet) {
    fmt::print(stderr, "span: checking {} {} in time\n", frequencies.size(),
               frequencies.size() == 1 ? "frequency" : "frequencies");
  }
  std::vector<requests::TimeCheck> checks = requests::check_span_in_time(
      requests::span_file_as_balanced(file, request, result), frequencies, options.threads, &InterruptRequest::flag());
  interrupted = InterruptRequest::requested();
  if (interrupted) return checks;
  print_warnings(invocation, requests::time_check_warnings(checks, result.analysis.span.judges_poffenberger_swart()));
  return checks;
}

int run_span_command(const SpanOptions& options, Invocation& invocation) {
  const requests::CheckedSpanRequest request = span_request_of(options);
  check_report_path(options.report);
  const io::SpanFile file = read_span_input(
      invocation, options.span_file,
      {{"-o", options.output},
       {"--report", options.report.value_or("")},
       {"--profile", options.profile.value_or("")},
       {"--check-time-output", options.check_time_output.value_or("")}},
      slip_policy(options.allow_unusual));
  requests::check_against_span(request, file.span);  // refusals before the progress starts
  if (options.check_time) {
    requests::validate_check_frequencies(parse_number_list(*options.check_time, "--check-time"));
    if (!options.no_dampers && !options.no_attachments) span::check_in_time(file.span);
  }
  const auto start = std::chrono::steady_clock::now();
  ProgressReport progress(invocation, "span: impedance tables", options.quiet);
  // The rows go to the CSV as the points are balanced (none held, but for the HTML
  // report, which draws them all), and what the summary and the notes need of them
  // is tallied on the way; the file appears at the end, whole, or not at all. From
  // the first row on, Ctrl-C stops the balance at the next point and removes it.
  std::optional<requests::Table<span::BalancePoint>> table;
  std::optional<requests::CsvFile<span::BalancePoint>> csv;
  std::optional<InterruptRequest> interrupt;
  requests::SpanPointTally tally;
  std::function<void(const span::Span&, span::BalancePoint&&)> take_point;
  if (!options.report) {
    take_point = [&](const span::Span& balanced, span::BalancePoint&& p) {
      if (!csv) {
        interrupt.emplace();
        csv.emplace(options.output, table.emplace(requests::span_table(balanced)));
      }
      if (InterruptRequest::requested()) throw Interrupted("the span was stopped");
      csv->add(p);
      tally.add(balanced, p);
    };
  }
  std::optional<requests::SpanResult> balanced;
  try {
    balanced.emplace(requests::run_span(file.span, file.balance, request, std::ref(progress), std::move(take_point)));
    if (interrupt && InterruptRequest::requested()) throw Interrupted("the span was stopped");  // after the last point
  } catch (const Interrupted&) {
    fmt::print(stderr, "span: interrupted; nothing written\n");
    return kInterrupted;
  }
  interrupt.reset();
  const requests::SpanResult& result = *balanced;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const span::SpanAnalysis& a = result.analysis;
  if (options.report) tally = requests::SpanPointTally::of(result);
  print_warnings(invocation, a.warnings);
  bool interrupted = false;
  const std::vector<requests::TimeCheck> checks =
      span_time_checks(options, file, request, result, invocation, interrupted);
  if (interrupted) {
    fmt::print(stderr, "span: interrupted while checking in time; nothing written\n");
    return kInterrupted;
  }
  const bool poffenberger_swart = a.span.judges_poffenberger_swart();
  const std::string report =
      options.report ? report::span_report(result, invocation.report_context(), checks) : std::string();
  const std::string profile =
      options.profile
          ? requests::span_profile_table().values(requests::span_profile_rows(requests::governing_profile(a.span, tally))).csv()
          : std::string();
  if (csv) {
    csv->commit();
  } else {
    requests::write_csv_file(options.output, requests::span_table(a.span), a.balance.points);
  }
  if (options.report) io::write_file_atomically(*options.report, report);
  if (options.profile) io::write_file_atomically(*options.profile, profile);
  if (options.check_time_output) {
    requests::write_csv_file(*options.check_time_output, requests::time_check_table(poffenberger_swart), checks);
  }

  const span::BalanceSummary& summary = a.balance.summary;
  if (options.json) {
    io::JsonObject json = requests::span_summary(result, tally).add("seconds", seconds);
    if (options.check_time) json.add("check_time", requests::time_check_rows(checks, poffenberger_swart));
    fmt::print("{}\n", json.str());
  } else if (!options.quiet) {
    print_span_report(result);
    if (options.check_time) print_time_checks(checks, poffenberger_swart);
  }
  if (!options.quiet) {
    fmt::print(stderr, "span: {} points in {:.2f} s, {} converged\n", summary.points, seconds, summary.converged);
  }
  for (const auto& [frequency, note] : tally.several_states) fmt::print(stderr, "  note: f = {:.4g} Hz: {}\n", frequency, note);
  const int failed = summary.points - summary.converged;
  const bool checks_compared =
      std::all_of(checks.begin(), checks.end(), [](const requests::TimeCheck& c) { return c.compared(); });
  if (failed == 0) return checks_compared ? kSuccess : kNotConverged;
  fmt::print(stderr, "span: {} points did not converge (converged = 0, numbers left empty in {}):\n", failed,
             options.output);
  int shown = 0;
  for (const auto& [frequency, why] : tally.failed) {
    if (++shown > 10) break;
    fmt::print(stderr, "  f = {:.4g} Hz: {}\n", frequency, brief_report(why));
  }
  if (failed > 10) fmt::print(stderr, "  ... and {} more\n", failed - 10);
  return kNotConverged;
}

}  // namespace

void add_span_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<SpanOptions>();
  CLI::App* sub = app.add_subcommand(
      "span", "Energy balance of a span with its dampers over the wind band: amplitudes, stresses, endurance, life");
  sub->add_option("span", options->span_file, "Span description (TOML)")->required();
  CLI::Option* frequencies = sub->add_option(
      "--frequencies", options->frequencies, "Frequencies, Hz, comma-separated, increasing (instead of --points)");
  sub->add_option("--points", options->points, "Frequencies log-spaced over the wind band St U / D")
      ->capture_default_str()
      ->excludes(frequencies);
  sub->add_flag("--no-dampers", options->no_dampers, "Balance the span without its dampers");
  sub->add_flag("--no-attachments", options->no_attachments,
                "Balance the span without its masses ([[mass]]) and the dampers along it (positions = [..]); the "
                "dampers at its ends kept");
  sub->add_option("--damper-model", options->damper_model,
                  "travelling (the dampers' standing wave, MODEL.md 9) or weak (|Z| << Z0); default: the span "
                  "file's [balance] damper_model, travelling");
  sub->add_option("--optimize-position", options->optimize_position,
                  "AMIN:AMAX, m: search every damper's position (each its own) minimising --objective, then "
                  "balance there");
  sub->add_option("--spacing-min", options->spacing_min, "With --optimize-position: m between two dampers at least")
      ->capture_default_str();
  sub->add_option("--objective", options->objective,
                  "With --optimize-position: max_stress (the largest fymax stress over the endurance limit) or life "
                  "(needs the span file's climate)")
      ->capture_default_str();
  sub->add_option("--threads", options->threads, "Parallel runs for the dampers' impedance tables")->capture_default_str();
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout instead of the report");
  sub->add_flag("--quiet", options->quiet,
                "No report on stdout and no progress on stderr (warnings, errors and --json still print)");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  add_report_option(*sub, options->report, "the inputs, the verdict, the stress, amplitude and power curves, the life");
  sub->add_option("--profile", options->profile,
                  "Also write the standing wave along the span at the governing frequency (CSV: attachment, x_m, displacement_m, "
                  "envelope_m)");
  CLI::Option* check_time = sub->add_option(
      "--check-time", options->check_time,
      "Frequencies, Hz, comma-separated: the span also simulated in time at each (as `stockbridge simulate`, the span "
      "file's [span] ends and [time]), its steady figures over the balance's, a warning where they part by more than "
      "10 %");
  sub->add_option("--check-time-output", options->check_time_output,
                  "With --check-time: write the checks' figures and ratios (CSV)")
      ->needs(check_time);
  auto modes = std::make_shared<SpanModesFlags>();
  add_span_modes_options(*sub, *modes);
  sub->callback([options, modes, &invocation] {
    invocation.set_exit_code(modes->modes ? run_span_modes_command(*modes,
                                                                   {options->span_file, options->output, options->json,
                                                                    options->quiet, options->allow_unusual},
                                                                   invocation)
                                          : run_span_command(*options, invocation));
  });
}

}  // namespace stockbridge::cli
