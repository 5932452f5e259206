// A span's natural frequencies with its attachments (stockbridge.span_modes wraps it).
#include "binding_support.hpp"

#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/requests/span_modes_request.hpp"

namespace stockbridge::python {

namespace {

/// rows x columns of `value(row, column)`.
template <class Value>
py::array_t<double> modes_matrix(std::size_t rows, std::size_t columns, Value value) {
  py::array_t<double> out({rows, columns});
  auto cells = out.mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns; ++c) cells(r, c) = value(r, c);
  }
  return out;
}

/// The modes CSV's columns as arrays (one value per mode), the samples 'x_m', the
/// shapes (modes x samples), the attachments' deflections (modes x attachments) and
/// the --json summary as JSON text.
py::dict span_modes_arrays(const std::optional<std::string>& path, const std::optional<std::string>& text,
                    const std::optional<std::string>& base, std::optional<double> fmax, const std::string& dampers,
                    bool shapes, bool allow_unusual) {
  if (path.has_value() == text.has_value()) {
    throw InvalidParameter("give either file (a span file's path) or text (a span file's contents), one of the two");
  }
  requests::SpanModesRequest request;
  request.fmax = fmax;
  request.dampers = dampers;
  request.shapes = shapes;
  requests::validate(request);
  io::SpanFile file =
      path ? io::load_span_file(*path, slip_policy(allow_unusual))
           : io::load_span_text(*text, "span_modes(text=...)", base.value_or(std::string()), slip_policy(allow_unusual));
  warn(file.warnings);
  std::optional<requests::SpanModesResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_span_modes(file.span, request));
  }
  const span::SpanModes& m = result->modes;
  const requests::TableValues columns = requests::span_modes_table(*result).values(m.modes);
  py::dict out = table_arrays(columns, {m.modes.size()});
  out["columns"] = columns.names();
  out["x_m"] = array(m.x);
  out["shapes"] = modes_matrix(m.modes.size(), shapes ? m.x.size() : 0,
                         [&](std::size_t r, std::size_t c) { return m.modes[r].shape[c]; });
  out["attachment_deflection"] = modes_matrix(m.modes.size(), m.attachments.size(), [&](std::size_t r, std::size_t c) {
    return m.modes[r].attachment_deflection[c];
  });
  out["summary_json"] = requests::span_modes_summary(*result).str();
  return out;
}

}  // namespace

void expose_span_modes(py::module_& m) {
  m.def("_span_modes", &span_modes_arrays, py::arg("file") = py::none(), py::arg("text") = py::none(),
        py::arg("base") = py::none(), py::arg("fmax") = py::none(), py::arg("dampers") = requests::SpanModesRequest{}.dampers,
        py::arg("shapes") = true, py::arg("allow_unusual") = false,
        "The span's natural frequencies with its attachments (stockbridge.span_modes wraps it): the modes CSV's "
        "columns as arrays, 'columns', 'x_m', 'shapes' (modes x samples), 'attachment_deflection' (modes x "
        "attachments) and the --json summary as 'summary_json'.");
}

}  // namespace stockbridge::python
