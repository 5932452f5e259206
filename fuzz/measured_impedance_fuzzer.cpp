// libFuzzer target: measured impedance sheets (identify impedance's input, a span's
// [[damper]] impedance = ...), read and then used as the program uses them. The
// reader either refuses with one InputError line naming the file, or gives a
// measurement; a sheet refused as unusual (UnusualValueError) is read again as
// --allow-unusual reads it (SlipPolicy::warn), so that values outside a shaker
// test's ranges reach the computations too. An accepted measurement then:
//   * becomes a span::ImpedanceSheet (or a typed refusal of one line) whose
//     interpolated Z is finite wherever the sheet gives it;
//   * damps an ACSR Drake span, balanced at three frequencies of the sheet's band;
//   * starts a bounded identification of the one-arm damper's cable (8 sections,
//     one element, one Jacobian per start, a coarse time integration) from sheets
//     of at most kIdentifiedRows rows whose frequencies and amplitudes lie within a
//     shaker test's (read without --allow-unusual; Z may be anything the reader
//     admits), a few seconds at most (identification's own tests cover the
//     unusual values: a |Z| of 1e-310 that made every residual infinite).
// Typed errors (stockbridge::Error) of one line are fine anywhere; anything else (a
// crash, another exception, a sanitizer report, a hang) is a finding.

#include <cmath>
#include <memory>
#include <optional>

#include "beside_files.hpp"
#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/impedance_sheet.hpp"

namespace {

using namespace stockbridge;

/// Sheets of more rows than this are not identified: under the sanitizers and the
/// fuzzer's instrumentation a fit (identify) costs up to a second per row.
constexpr std::size_t kIdentifiedRows = 4;

constexpr std::string_view kSpan =
    "[conductor]\ntype = \"ACSR Drake\"\n[span]\nlength = 300\ntension_fraction = 0.2\n"
    "[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n";

/// A sheet as read, and whether only --allow-unusual reads it.
struct ReadSheet {
  io::MeasuredImpedanceFile file;
  bool unusual = false;
};

/// Reads the sheet; a refusal as unusual is read again under SlipPolicy::warn.
std::optional<ReadSheet> read_sheet(const std::filesystem::path& path) {
  try {
    return ReadSheet{io::load_measured_impedance(path), false};
  } catch (const UnusualValueError& e) {
    fuzz::require_one_line_naming(e.what(), path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return std::nullopt;
  }
  try {
    return ReadSheet{io::load_measured_impedance(path, SlipPolicy::warn), true};
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return std::nullopt;
  }
}

/// The sheet's Z where it gives one, and a short balance of a span it damps.
void use_in_a_span(const identification::ImpedanceMeasurement& measurement) {
  std::shared_ptr<const span::ImpedanceSheet> sheet;
  try {
    sheet = std::make_shared<const span::ImpedanceSheet>(measurement, "sheet");
  } catch (const Error& e) {
    fuzz::require_one_line(e.what());
    return;
  }
  const span::Interval range = sheet->frequency_range();
  fuzz::require(range.lo > 0.0 && range.lo <= range.hi, "a sheet's frequencies in order");
  std::vector<double> frequencies;
  for (const double t : {0.0, 0.37, 1.0}) {
    const double f = range.lo * std::pow(range.hi / range.lo, t);
    for (const span::SheetNode& node : sheet->nodes_at(f)) {
      fuzz::require(std::isfinite(node.velocity) && std::isfinite(std::abs(node.impedance)), "finite nodes");
    }
    if (frequencies.empty() || f > frequencies.back()) frequencies.push_back(f);
  }
  static const span::Span undamped = io::load_span_text(kSpan, "span.toml").span;
  try {
    const span::Span damped = undamped.with_dampers({span::SpanDamper{std::nullopt, 1.0, true, "sheet", sheet, std::nullopt}});
    const span::SpanAnalysis a = span::analyse_span(damped, frequencies, {});
    fuzz::require(a.balance.points.size() == frequencies.size(), "a balance point per frequency");
    for (const span::BalancePoint& p : a.balance.points) {
      fuzz::require(!p.converged() || (std::isfinite(p.stress_fymax) && p.stress_fymax >= 0.0),
                    "a converged point's stress is finite");
    }
  } catch (const Error& e) {
    fuzz::require_one_line(e.what());
  }
}

/// A bounded identification of the one-arm damper's cable (8 sections) from the
/// measurement: one Jacobian per start, the model by time integration of at most 40
/// periods of 16 steps (a coarse model, loosely trusted). A fit makes some 45 model
/// runs of every point; harmonic balance's continuation and lead-in make a run's
/// cost depend on the parameters the fit tries (from 10 ms to 1 s under the
/// sanitizers), time integration's is bounded by its periods.
void identify(const identification::ImpedanceMeasurement& measurement) {
  static const damper::Damper start = io::read_damper_text(fuzz::kDamperFile, "d.toml");
  identification::ImpedanceIdentificationOptions options;
  options.elements = 1;
  options.max_jacobians = 1;
  options.solver.method = damper::Method::time_integration;
  damper::TimeIntegrationOptions& time = options.solver.time_integration;
  time.steps_per_period = 16;
  time.max_periods = 40;
  time.max_newton = 10;
  time.periodicity_tolerance = 1e-2;
  options.solver.energy_tolerance = 0.3;
  try {
    const identification::ImpedanceIdentification fit = identification::identify_impedance(start.description(), measurement, options);
    fuzz::require(fit.fitted.size() == measurement.points.size(), "a fitted point per measured point");
    fuzz::require(!(fit.misfit < 0.0), "a misfit >= 0");
  } catch (const Error& e) {
    fuzz::require_one_line(e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = fuzz::as_file(data, size, "sheet.csv");
  const std::optional<ReadSheet> read = read_sheet(path);
  if (!read) return 0;
  const identification::ImpedanceMeasurement& measurement = read->file.measurement;
  for (const std::string& w : read->file.warnings) fuzz::require_one_line(w);
  use_in_a_span(measurement);
  if (!read->unusual && measurement.points.size() <= kIdentifiedRows) identify(measurement);
  return 0;
}
