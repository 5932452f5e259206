// A span's energy balance, a recorder's counts against it, a conductor's fatigue tests.
#include "binding_support.hpp"

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/io/span_file.hpp"
#include "stockbridge/measurements/recorder.hpp"
#include "stockbridge/report/fatigue_tests_report.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/time_check.hpp"
#include "stockbridge/requests/fatigue_tests_request.hpp"
#include "stockbridge/requests/recorder_request.hpp"
#include "stockbridge/requests/span_request.hpp"

namespace stockbridge::python {

namespace {

/// A recorder's counts against a span (stockbridge.recorder wraps it): the bins
/// CSV's columns as arrays, the --json summary as 'summary_json'.
py::dict recorder_counts(const std::string& span_path, const std::string& counts_path, double days,
                         const std::vector<std::string>& calibrate, int points_per_band, bool allow_unusual) {
  requests::RecorderRequest request;
  request.days = days;
  request.calibrate = calibrate;
  request.points_per_band = points_per_band;
  requests::recorder_options(request);
  io::SpanFile file = io::load_span_file(span_path, slip_policy(allow_unusual));
  measurements::RecorderCounts counts;
  try {
    counts = requests::read_recorder_input(counts_path, file, request, slip_policy(allow_unusual));
  } catch (const InvalidParameter& e) {
    throw InputError(span_path + ": " + e.what());
  }
  warn(file.warnings);
  warn(counts.warnings);
  std::optional<measurements::RecorderResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_recorder(counts, file, request));
  }
  const requests::TableValues columns = requests::recorder_bins_table().values(result->bins);
  py::dict out = table_arrays(columns, {result->bins.size()});
  out["columns"] = columns.names();
  out["summary_json"] = requests::recorder_summary(*result).str();
  return out;
}

/// The span command's CSV columns as arrays (one value per frequency) and its --json
/// summary as JSON text (the package's span() parses it into a dict).
py::dict span_balance(const std::optional<std::string>& path, const std::optional<std::string>& text,
                      const std::optional<std::string>& base,
                      const std::optional<std::vector<double>>& frequencies, int points, bool no_dampers,
                      bool no_attachments,
                      const std::optional<std::string>& damper_model,
                      const std::optional<std::pair<double, double>>& optimize_position, double spacing_min,
                      const std::string& objective, int threads, const std::vector<double>& check_time, bool report,
                      bool allow_unusual) {
  if (path.has_value() == text.has_value()) {
    throw InvalidParameter("give either file (a span file's path) or text (a span file's contents), one of the two");
  }
  requests::SpanRequest request;
  if (frequencies) {
    if (frequencies->empty()) throw InvalidParameter("frequencies", ": an empty list, expected at least one frequency (Hz)");
    request.frequencies = *frequencies;
  }
  request.points = points;
  request.no_dampers = no_dampers;
  request.no_attachments = no_attachments;
  request.damper_model = damper_model;
  if (optimize_position) {
    request.position_min = optimize_position->first;
    request.position_max = optimize_position->second;
  }
  request.spacing_min = spacing_min;
  request.objective = objective;
  request.threads = threads;
  const requests::CheckedSpanRequest checked = requests::check_span_request(request);
  if (!check_time.empty()) requests::validate_check_frequencies(check_time);
  io::SpanFile file =
      path ? io::load_span_file(*path, slip_policy(allow_unusual))
           : io::load_span_text(*text, "span(text=...)", base.value_or(std::string()), slip_policy(allow_unusual));
  warn(file.warnings);
  std::optional<requests::SpanResult> result;
  std::vector<requests::TimeCheck> checks;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_span(file.span, file.balance, checked));
    if (!check_time.empty()) {
      checks = requests::check_span_in_time(requests::span_file_as_balanced(file, checked, *result), check_time, threads);
    }
  }
  const span::SpanAnalysis& a = result->analysis;
  const std::vector<std::size_t> shape{a.balance.points.size()};
  const requests::TableValues columns = requests::span_table(a.span).values(a.balance.points);
  py::dict out = table_arrays(columns, shape);
  for (const auto& [name, values] : table_arrays(requests::span_point_notes_table(a.span).values(a.balance.points), shape)) {
    out[name] = values;
  }
  out["dampers"] = requests::span_damper_prefixes(a.span);  // the <damper> of the per-damper columns
  out["columns"] = columns.names();
  const bool poffenberger_swart = result->analysis.span.judges_poffenberger_swart();
  io::JsonObject summary = requests::span_summary(*result);
  std::vector<std::string> check_warnings;
  if (!check_time.empty()) {
    summary.add("check_time", requests::time_check_rows(checks, poffenberger_swart));
    check_warnings = requests::time_check_warnings(checks, poffenberger_swart);
    warn(check_warnings);
  }
  out["summary_json"] = summary.str();
  out["profile"] = py::none();
  if (a.balance.summary.converged > 0) {
    const span::SpanProfile profile = requests::governing_profile(*result);
    const std::vector<requests::SpanProfileRow> rows = requests::span_profile_rows(profile);
    py::dict arrays = table_arrays(requests::span_profile_table().values(rows), {rows.size()});
    arrays["frequency_hz"] = profile.frequency_hz;
    out["profile"] = arrays;
  }
  if (report) {
    std::vector<std::string> warnings = file.warnings;
    for (const std::string& w : a.warnings) warnings.push_back(w);
    warnings.insert(warnings.end(), check_warnings.begin(), check_warnings.end());
    out["report_html"] = report::span_report(*result, {report::utc_now(), "", warnings}, checks);
  }
  return out;
}

/// `stockbridge fatigue-tests` (stockbridge.fatigue_tests wraps it): the output CSV's
/// columns as arrays ('table'), the --json summary as 'summary_json', the design
/// curve's S-N file text ('curve_toml', None where the fit's slope gives no curve),
/// the file's 'warnings' and with report the HTML page's text.
void expose_fatigue_tests(py::module_& m) {
  m.def(
      "_fatigue_tests",
      [](const std::string& file, const std::optional<std::string>& conductor, bool allow_unusual, bool report) {
        requests::FatigueTestsRequest request;
        request.file = file;
        request.conductor = conductor;
        request.policy = slip_policy(allow_unusual);
        const requests::FatigueTestsOutcome outcome = requests::run_fatigue_tests(request);
        warn(outcome.warnings);
        py::dict out;
        out["table"] = table_arrays(requests::fatigue_tests_values(outcome.result), {outcome.result.tests.size()});
        out["summary_json"] = requests::fatigue_tests_summary(outcome).str();
        out["curve_toml"] = outcome.result.fit.b < 0.0 ? py::object(py::str(requests::fatigue_tests_curve_toml(outcome)))
                                                       : py::object(py::none());
        out["warnings"] = outcome.warnings;
        if (report) out["report_html"] = report::fatigue_tests_report(outcome, {report::utc_now(), "", outcome.warnings});
        return out;
      },
      py::arg("file"), py::arg("conductor") = py::none(), py::arg("allow_unusual") = false, py::arg("report") = false,
      "A conductor's fatigue tests (stockbridge.fatigue_tests wraps it).");
}

}  // namespace

void expose_span(py::module_& m) {
  m.def("_span", &span_balance, py::arg("file") = py::none(), py::arg("text") = py::none(),
        py::arg("base") = py::none(),
        py::arg("frequencies") = py::none(), py::arg("points") = requests::SpanRequest{}.points,
        py::arg("no_dampers") = false, py::arg("no_attachments") = false, py::arg("damper_model") = py::none(),
        py::arg("optimize_position") = py::none(), py::arg("spacing_min") = requests::SpanRequest{}.spacing_min,
        py::arg("objective") = requests::SpanRequest{}.objective, py::arg("threads") = requests::SpanRequest{}.threads,
        py::arg("check_time") = std::vector<double>{}, py::arg("report") = false, py::arg("allow_unusual") = false,
        "The span's energy balance (stockbridge.span wraps it): the span CSV's columns as arrays, "
        "'converged', 'termination', 'messages', 'dampers', 'columns', the --json summary as 'summary_json' and "
        "with report the HTML report's text as 'report_html'.");
  m.def("_recorder", &recorder_counts, py::arg("span"), py::arg("counts"), py::arg("days"),
        py::arg("calibrate") = std::vector<std::string>{},
        py::arg("points_per_band") = measurements::RecorderOptions{}.points_per_band, py::arg("allow_unusual") = false,
        "A vibration recorder's counts against a span (stockbridge.recorder wraps it): the bins CSV's columns "
        "as arrays, 'columns', and the --json summary as 'summary_json'.");
  expose_fatigue_tests(m);
}

}  // namespace stockbridge::python
