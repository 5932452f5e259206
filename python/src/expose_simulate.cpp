// The span in time beside the energy balance (stockbridge.simulate wraps it).
#include "binding_support.hpp"

#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/simulate_request.hpp"

namespace stockbridge::python {

namespace {

/// The history CSV's columns as arrays (one value per row), 'columns', the --json
/// summary as JSON text and, with report, the HTML page's text.
py::dict simulate_arrays(const std::optional<std::string>& path, const std::optional<std::string>& text,
                         const std::optional<std::string>& base, double frequency, std::optional<double> duration,
                         const std::optional<std::string>& ends, std::optional<int> elements_per_wavelength,
                         std::optional<int> steps_per_period, const std::string& wind,
                         const std::vector<double>& probes, std::optional<double> start_amplitude, int every,
                         bool report, bool allow_unusual) {
  if (path.has_value() == text.has_value()) {
    throw InvalidParameter("give either file (a span file's path) or text (a span file's contents), one of the two");
  }
  requests::SimulateRequest request;
  request.frequency_hz = frequency;
  request.duration_s = duration;
  request.ends = ends;
  request.elements_per_wavelength = elements_per_wavelength;
  request.steps_per_period = steps_per_period;
  request.wind = wind;
  request.probes = probes;
  request.start_amplitude_m = start_amplitude;
  request.every = every;
  requests::validate(request);
  io::SpanFile file =
      path ? io::load_span_file(*path, slip_policy(allow_unusual))
           : io::load_span_text(*text, "simulate(text=...)", base.value_or(std::string()), slip_policy(allow_unusual));
  warn(file.warnings);
  std::vector<requests::SimulationRow> rows;
  std::optional<requests::SimulateResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_simulate(file, request,
                                          [&](const requests::SimulationRow& row) { rows.push_back(row); }));
  }
  const requests::TableValues columns =
      requests::simulation_table(result->probe_columns, requests::simulation_dampers(file.span)).values(rows);
  py::dict out = table_arrays(columns, {rows.size()});
  out["columns"] = columns.names();
  out["summary_json"] = requests::simulate_summary(file.span, *result).str();
  if (report) {
    out["report_html"] =
        report::simulate_report(file.span, file.balance.damper_model, *result, {report::utc_now(), "", file.warnings});
  }
  return out;
}

}  // namespace

void expose_simulate(py::module_& m) {
  const requests::SimulateRequest defaults;  // the time settings: the span file's where None
  m.def("_simulate", &simulate_arrays, py::arg("file") = py::none(), py::arg("text") = py::none(),
        py::arg("base") = py::none(), py::arg("frequency"), py::arg("duration") = py::none(),
        py::arg("ends") = py::none(), py::arg("elements_per_wavelength") = py::none(),
        py::arg("steps_per_period") = py::none(), py::arg("wind") = defaults.wind, py::arg("probes") = std::vector<double>{},
        py::arg("start_amplitude") = py::none(), py::arg("every") = defaults.every, py::arg("report") = false,
        py::arg("allow_unusual") = false,
        "The span in time beside the energy balance (stockbridge.simulate wraps it): the history CSV's columns as "
        "arrays, 'columns', and the --json summary as 'summary_json'.");
}

}  // namespace stockbridge::python
