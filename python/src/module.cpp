// stockbridge._core: the Python binding. It holds no logic: each function converts
// its arguments, calls the library with the GIL released, and returns numpy arrays.
// The functions are exposed module by module (expose_*.cpp); this file defines the
// module, its version and the defaults the package's wrappers read.

#include <string>

#include <pybind11/pybind11.h>

#include "binding_support.hpp"
#include "stockbridge/requests/design_request.hpp"
#include "stockbridge/requests/impedance_fit_request.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "stockbridge/version.hpp"

namespace py = pybind11;
using namespace stockbridge;

PYBIND11_MODULE(_core, m) {
  m.doc() = "stockbridge: nonlinear impedance of Stockbridge dampers (C++ library binding)";
  m.attr("__version__") = std::string(stockbridge::version());
  python::expose_errors(m);
  // The defaults are the library requests' (the CLI's too); the package's wrappers read theirs here.
  py::dict defaults;
  defaults["span_points"] = requests::SpanRequest{}.points;
  defaults["span_threads"] = requests::SpanRequest{}.threads;
  defaults["span_spacing_min"] = requests::SpanRequest{}.spacing_min;
  defaults["span_objective"] = requests::SpanRequest{}.objective;
  defaults["design_threads"] = requests::DesignRequest{}.threads;
  defaults["design_round_digits"] = requests::DesignRequest{}.round_digits;
  defaults["fit_elements"] = requests::ImpedanceFitRequest{}.elements;
  defaults["fit_clamp_mass"] = requests::ImpedanceFitRequest{}.fit_clamp_mass;
  defaults["fit_threads"] = requests::ImpedanceFitRequest{}.threads;
  defaults["fit_rms_limit"] = requests::ImpedanceFitRequest{}.rms_limit;
  m.attr("_defaults") = defaults;
  python::expose_cable(m);
  python::expose_damper(m);
  python::expose_span(m);
  python::expose_span_modes(m);
  python::expose_simulate(m);
  python::expose_line(m);
  python::expose_design(m);
  python::expose_identification(m);
}
