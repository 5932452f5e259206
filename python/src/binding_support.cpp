// The conversions every binding file shares (binding_support.hpp).
#include "binding_support.hpp"

#include <algorithm>
#include <map>

#include <pybind11/stl.h>

namespace stockbridge::python {

namespace {

/// Labels as nested lists of `shape` (rows in C order): a list of str for one
/// dimension, a list of such lists for two.
py::list label_lists(const std::vector<std::string>& labels, const std::vector<std::size_t>& shape) {
  if (shape.size() < 2) return py::cast(labels);
  py::list rows;
  const std::size_t width = labels.size() / std::max<std::size_t>(shape[0], 1);
  for (std::size_t r = 0; r < shape[0]; ++r) {
    rows.append(py::cast(std::vector<std::string>(labels.begin() + static_cast<std::ptrdiff_t>(r * width),
                                                  labels.begin() + static_cast<std::ptrdiff_t>((r + 1) * width))));
  }
  return rows;
}

/// One column's values as a numpy array of `shape` (rows in C order): numbers as
/// float64, counts as int64, flags as bool; a label column as a list of str.
py::object column_array(const requests::TableValues::Column& c, const std::vector<std::size_t>& shape) {
  switch (c.kind) {
    case requests::ColumnKind::label: return label_lists(c.labels, shape);
    case requests::ColumnKind::flag: {  // true where 1 (false where masked: NaN)
      py::array_t<bool> a(shape);
      bool* out = a.mutable_data();
      for (std::size_t i = 0; i < c.numbers.size(); ++i) out[i] = c.numbers[i] == 1.0;
      return a;
    }
    case requests::ColumnKind::count: {
      py::array_t<long long> a(shape);
      long long* out = a.mutable_data();
      for (std::size_t i = 0; i < c.numbers.size(); ++i) out[i] = static_cast<long long>(c.numbers[i]);
      return a;
    }
    case requests::ColumnKind::number: break;
  }
  py::array_t<double> a(shape);
  std::copy(c.numbers.begin(), c.numbers.end(), a.mutable_data());
  return a;
}

}  // namespace

SlipPolicy slip_policy(bool allow_unusual) { return allow_unusual ? SlipPolicy::warn : SlipPolicy::refuse; }

void warn(const std::vector<std::string>& lines) {
  // Kept for the interpreter's life (a static py::object would be released after it ends).
  static const py::handle category = py::object(py::module_::import("stockbridge").attr("UnusualValueWarning")).release();
  for (const std::string& line : lines) {
    if (PyErr_WarnEx(category.ptr(), line.c_str(), 2) != 0) throw py::error_already_set();
  }
}

py::array_t<double> array(const std::vector<double>& values) { return py::array_t<double>(values.size(), values.data()); }

py::dict table_arrays(const requests::TableValues& table, const std::vector<std::size_t>& shape,
                      bool stack_families) {
  py::dict out;
  std::map<std::string, std::vector<const requests::TableValues::Column*>> families;
  std::vector<std::string> order;
  for (const requests::TableValues::Column& c : table.columns) {
    if (!stack_families || c.family.empty()) {
      out[py::str(c.name)] = column_array(c, shape);
      continue;
    }
    if (!families.contains(c.family)) order.push_back(c.family);
    families[c.family].push_back(&c);
  }
  for (const std::string& family : order) {
    const auto& members = families[family];
    std::vector<std::size_t> stacked{members.size()};
    stacked.insert(stacked.end(), shape.begin(), shape.end());
    py::array_t<double> a(stacked);
    double* data = a.mutable_data();
    for (const auto* c : members) data = std::copy(c->numbers.begin(), c->numbers.end(), data);
    out[py::str(family)] = a;
  }
  return out;
}

void add_row(py::dict& out, const requests::TableValues& table, std::size_t r) {
  for (const requests::TableValues::Column& c : table.columns) {
    switch (c.kind) {
      case requests::ColumnKind::label: out[py::str(c.name)] = c.labels[r]; break;
      case requests::ColumnKind::flag: out[py::str(c.name)] = c.numbers[r] == 1.0; break;
      case requests::ColumnKind::count: out[py::str(c.name)] = static_cast<long long>(c.numbers[r]); break;
      case requests::ColumnKind::number: out[py::str(c.name)] = c.numbers[r]; break;
    }
  }
}

std::vector<double> amplitudes_of(const py::object& value) {
  if (value.is_none()) return {};
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return {value.cast<double>()};
  return value.cast<std::vector<double>>();
}

requests::SolverSettings solver_settings(const std::string& method, std::optional<int> harmonics,
                                         std::optional<int> samples, std::optional<int> steps,
                                         std::optional<int> max_iterations, std::optional<int> max_periods,
                                         std::optional<double> energy_tolerance, bool full_period) {
  return {method, harmonics, samples, steps, max_iterations, max_periods, energy_tolerance,
          full_period ? std::optional<bool>(false) : std::nullopt};
}

py::list jenkin_list(const std::vector<std::pair<double, double>>& c_h) {
  py::list list;
  for (const auto& [c, h] : c_h) {
    py::dict e;
    e["c"] = c;
    e["h"] = h;
    list.append(e);
  }
  return list;
}

py::dict from_json(const io::JsonObject& json) {
  return py::module_::import("json").attr("loads")(json.str()).cast<py::dict>();
}

}  // namespace stockbridge::python
