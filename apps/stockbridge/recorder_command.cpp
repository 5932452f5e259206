// stockbridge recorder: a vibration recorder's counts turned into a fatigue
// judgement (measurements/recorder.hpp): per bin the stress at its upper Yb edge,
// the cycles to failure and Miner's damage; the same record as the span's balance
// and climate predict it; and a parameter of the span calibrated on the record.

#include <cmath>
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
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/recorder_request.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

struct RecorderCommandOptions {
  std::string span_file;
  std::string counts_file;
  double days = 0.0;
  std::optional<std::string> calibrate;
  std::optional<std::string> calibrated_span;
  int points_per_band = requests::RecorderRequest{}.points_per_band;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
  std::string output;
  std::optional<std::string> report;
};

std::string recorder_years(double years) {
  return std::isfinite(years) ? fmt::format("{:.3g} years", years) : "unlimited (no damage)";
}

void print_recorder_figures(const char* what, const measurements::DamageFigures& f) {
  fmt::print("{}: damage {:.4g} over {:.4g} days, {:.4g} per year, life {}; largest Yb {:.3g} mm, stress {:.3g} MPa; "
             "{:.4g} cycles, {:.3g} % above the endurance limit\n",
             what, f.damage, f.days, f.damage_per_year, recorder_years(f.life_years), 1e3 * f.max_yb,
             requests::megapascal_of(f.max_stress), f.cycles, 100.0 * f.fraction_above_endurance);
}

void print_recorder_report(const measurements::RecorderResult& r) {
  print_recorder_figures("measured", r.measured);
  print_recorder_figures("predicted", r.predicted.figures);
  if (r.calibration) {
    const measurements::RecorderCalibration& c = *r.calibration;
    for (const measurements::CalibratedValue& v : c.values) {
      fmt::print("calibrated {}: {:.4g} +- {:.2g} (was {:.4g})\n", v.key, v.value, v.standard_error, v.start);
    }
    fmt::print("residual in ln Yb: {:.3g} before, {:.3g} after ({}, {} balances)\n", c.residual_before,
               c.residual_after, c.message, c.balances);
    print_recorder_figures("calibrated prediction", c.prediction.figures);
  }
  fmt::print("band (Hz)      recorded cycles  predicted cycles  recorded Yb (mm)  predicted Yb (mm)\n");
  const auto yb = [](double ln) { return std::isfinite(ln) ? fmt::format("{:.3g}", std::exp(ln)) : std::string("-"); };
  for (const measurements::RecorderBand& b : r.predicted.bands) {
    fmt::print("{:>5.4g}-{:<7.4g} {:>16.4g} {:>17.4g} {:>17} {:>18}{}\n", b.frequency_low, b.frequency_high,
               b.recorded_cycles, b.predicted_cycles, yb(b.recorded_mean_ln_yb), yb(b.predicted_mean_ln_yb),
               b.converged ? "" : "  (not converged)");
  }
}

int run_recorder_command(const RecorderCommandOptions& options, Invocation& invocation) {
  requests::RecorderRequest request;
  request.days = options.days;
  if (options.calibrate) request.calibrate = split_list(*options.calibrate);
  request.points_per_band = options.points_per_band;
  try {
    requests::recorder_options(request);
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(fmt::format("--{}", e.field() == "points_per_band" ? "points-per-band" : e.field()),
                           e.detail());
  }
  check_report_path(options.report);
  const std::vector<CommandFile> outputs{{"-o", options.output},
                                         {"--report", options.report.value_or("")},
                                         {"--calibrated-span", options.calibrated_span.value_or("")}};
  require_outputs_apart(outputs, {{"the counts file", options.counts_file}});
  if (options.calibrated_span && request.calibrate.empty()) {
    throw InvalidParameter("--calibrated-span", ": given without --calibrate; expected the keys to calibrate");
  }
  const io::SpanFile file =
      read_span_input(invocation, options.span_file, outputs, slip_policy(options.allow_unusual));
  measurements::RecorderCounts counts;
  try {
    counts = requests::read_recorder_input(options.counts_file, file, request, slip_policy(options.allow_unusual));
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}: {}", options.span_file, e.what()));
  }
  print_warnings(invocation, file.warnings);
  print_warnings(invocation, counts.warnings);
  const measurements::RecorderResult result = requests::run_recorder(counts, file, request);
  std::string calibrated_text;
  const bool calibrated = result.calibration && result.calibration->converged;
  if (options.calibrated_span && calibrated) {
    calibrated_text = measurements::calibrated_span_text(options.span_file, result.calibration->values);
  }
  const std::string report =
      options.report ? report::recorder_report({&result, &file.span, options.counts_file}, invocation.report_context())
                     : std::string();
  io::write_file_atomically(options.output, requests::recorder_bins_table().values(result.bins).csv());
  if (options.report) io::write_file_atomically(*options.report, report);
  // A calibration that did not converge writes no span file: its values are not a fit.
  if (options.calibrated_span && calibrated) io::write_file_atomically(*options.calibrated_span, calibrated_text);
  if (options.json) {
    fmt::print("{}\n", requests::recorder_summary(result).str());
  } else if (!options.quiet) {
    print_recorder_report(result);
  }
  const int failed = result.predicted.failed_points + (result.calibration ? result.calibration->prediction.failed_points : 0);
  if (result.calibration && !result.calibration->converged) {
    fmt::print(stderr, "recorder: the calibration did not converge: {}{}\n", result.calibration->message,
               options.calibrated_span ? fmt::format("; {} not written", *options.calibrated_span) : "");
  }
  if (failed > 0) {
    fmt::print(stderr, "recorder: {} balance points did not converge; their bands are flagged and left out of the sums\n",
               failed);
  }
  return failed == 0 && (!result.calibration || result.calibration->converged) ? kSuccess : kNotConverged;
}

}  // namespace

void add_recorder_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<RecorderCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "recorder", "A vibration recorder's counts: damage and life measured, predicted by the span's balance and "
                  "climate, and the span calibrated on the record");
  sub->add_option("span", options->span_file, "Span description (TOML) with [fatigue] wind_weibull and aeolian_fraction")
      ->required();
  sub->add_option("counts", options->counts_file,
                  "The recorder's counts (CSV): one row per bin (yb_pp_mm_low, yb_pp_mm_high, frequency_hz_low, "
                  "frequency_hz_high, cycles) or the matrix form (yb_pp_mm, 'low-high hz' columns)")
      ->required();
  sub->add_option("--days", options->days, "The record's length, days (> 0)")->required();
  sub->add_option("--calibrate", options->calibrate,
                  "KEY[,KEY]: wind.turbulence_intensity (law foti), wind.power_scale (any law), self_damping.k");
  sub->add_option("--calibrated-span", options->calibrated_span,
                  "With --calibrate: write the span file with the fitted values (TOML)");
  sub->add_option("--points-per-band", options->points_per_band, "Balance frequencies per frequency band of the record")
      ->capture_default_str();
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout instead of the report");
  sub->add_flag("--quiet", options->quiet, "No report on stdout (warnings, errors and --json still print)");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file: one row per bin")->required();
  add_report_option(*sub, options->report,
                    "the recorded matrix with the predicted Yb(f), the damage table, the verdict");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_recorder_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
