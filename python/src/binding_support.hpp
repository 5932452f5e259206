#pragma once
// What the binding's files share (python/src/expose_*.cpp): the arguments and results
// converted between Python and the library's requests, and the warnings raised as
// Python's UnusualValueWarning. No logic of the library's own.

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/requests/solver_settings.hpp"

namespace stockbridge::python {

namespace py = pybind11;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// allow_unusual=True: a value a unit slip explains is a warning, not an error.
SlipPolicy slip_policy(bool allow_unusual);
/// Each warning line as a Python UnusualValueWarning (a UserWarning), where the CLI
/// prints "warning: ..." (values outside the typical ranges: unit mistakes).
void warn(const std::vector<std::string>& lines);
/// A file reader's result, its warnings raised: the damper or the cable.
template <class Loaded>
auto warned(Loaded loaded) {
  warn(loaded.warnings);
  if constexpr (requires { loaded.damper; }) {
    return std::move(loaded.damper);
  } else {
    return std::move(loaded.cable);
  }
}
py::array_t<double> array(const std::vector<double>& values);
/// A table's columns as a dict of arrays by the CSV's names, each of `shape`; with
/// `stack_families`, a family's columns (one per arm) stacked into one array of
/// (members, *shape) by the family's name ("x_m").
py::dict table_arrays(const requests::TableValues& table, const std::vector<std::size_t>& shape,
                      bool stack_families = false);
/// Row r of a table as Python scalars by name: float, int, bool or str.
void add_row(py::dict& out, const requests::TableValues& table, std::size_t r);
/// A velocity or displacement argument: None, a number or a list of numbers.
std::vector<double> amplitudes_of(const py::object& value);
/// The CLI's solver flags by the same names (None: the method's default).
requests::SolverSettings solver_settings(const std::string& method, std::optional<int> harmonics,
                                         std::optional<int> samples, std::optional<int> steps,
                                         std::optional<int> max_iterations, std::optional<int> max_periods,
                                         std::optional<double> energy_tolerance, bool full_period);
/// [{'c': ..., 'h': ...}, ...] of a Masing law's Jenkin elements.
py::list jenkin_list(const std::vector<std::pair<double, double>>& c_h);
/// A JSON summary of the library as Python objects (json.loads: null as None).
py::dict from_json(const io::JsonObject& json);

/// The module's parts, each in its own file, called by PYBIND11_MODULE (module.cpp).
void expose_errors(py::module_& m);
void expose_cable(py::module_& m);
void expose_damper(py::module_& m);
void expose_identification(py::module_& m);
void expose_span(py::module_& m);
void expose_span_modes(py::module_& m);
void expose_simulate(py::module_& m);
void expose_line(py::module_& m);
void expose_design(py::module_& m);

}  // namespace stockbridge::python
