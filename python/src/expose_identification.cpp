// Identification: a section's or a cable's parameters from records, a damper's from a measured impedance, the self-damping law from tests.
#include "binding_support.hpp"

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/measurements/self_damping_tests.hpp"
#include "stockbridge/requests/identify_request.hpp"
#include "stockbridge/requests/impedance_fit_request.hpp"
#include "stockbridge/requests/self_damping_request.hpp"

namespace stockbridge::python {

namespace {

py::dict identify_local(const std::vector<double>& curvature, const std::vector<double>& moment, int elements,
                        const std::string& optimizer, const std::string& law) {
  const requests::LocalRequest request{law, elements, optimizer};
  std::optional<requests::LocalResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_local({curvature, moment}, request));
  }
  py::dict out = from_json(requests::local_summary(*result));
  out["cycle_errors"] = array(result->fit.cycle_errors);
  return out;
}

py::dict identify_global(const std::string& experiment, double length, const std::vector<double>& prescribed,
                         const std::vector<double>& measured, const std::string& method, int sections, int elements,
                         const std::string& optimizer, const std::string& law) {
  const requests::GlobalRequest request{law, experiment, length, method, sections, elements, optimizer};
  std::optional<requests::GlobalResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_global(request, prescribed, measured, "the record"));
  }
  warn(warning_messages(result->warnings));
  py::dict out = from_json(requests::global_summary(request, *result));
  out["cable"] = cable::Cable(result->fit.cable);
  return out;
}

/// The identification from a measured impedance (stockbridge.identify_impedance wraps
/// it): the --fitted CSV's columns as arrays, the --json summary as JSON text, the
/// cable files' texts and the fitted damper.
py::dict identify_impedance(const damper::Damper& start, const std::optional<std::string>& input,
                            const std::optional<std::vector<double>>& frequency,
                            const std::optional<std::vector<double>>& velocity,
                            const std::optional<std::vector<double>>& displacement,
                            const std::optional<std::vector<std::complex<double>>>& z, int elements, bool fit_clamp_mass,
                            const std::vector<std::string>& free, double rms_limit, int threads,
                            const std::optional<double>& scatter, bool allow_unusual) {
  const bool arrays = frequency || velocity || displacement || z;
  if (input.has_value() == arrays) {
    throw InvalidParameter("give either input (a measured CSV's path) or frequency, velocity (or displacement) and z");
  }
  if (arrays && (!frequency || !z || velocity.has_value() == displacement.has_value())) {
    throw InvalidParameter("give frequency, z and one of velocity or displacement (arrays of one value per point)");
  }
  const identification::ImpedanceIdentificationOptions options =
      requests::fit_options({elements, fit_clamp_mass, threads, free, rms_limit, scatter});
  io::MeasuredImpedanceFile measured;
  if (input) {
    measured = io::load_measured_impedance(*input, slip_policy(allow_unusual));
  } else {
    measured.measurement =
        requests::measurement_from_arrays(*frequency, velocity ? *velocity : *displacement, velocity.has_value(), *z);
  }
  warn(measured.warnings);
  const identification::ImpedanceMeasurement& m = measured.measurement;
  identification::ImpedanceIdentification fit;
  {
    py::gil_scoped_release release;
    fit = identification::identify_impedance(start.description(), m, options);
  }
  const std::string source = input ? *input : std::string("the measurement");
  warn(warning_messages(requests::fit_warnings(fit, source)));
  const py::dict fitted = table_arrays(requests::fitted_table().values(requests::fitted_points(m, fit)), {m.points.size()});
  py::list cable_files;
  for (std::size_t t = 0; t < fit.types(); ++t) {
    cable_files.append(requests::fitted_cable_file(fit, t, input ? *input : std::string("arrays")));
  }
  py::dict out;
  out["summary_json"] = requests::fit_summary(m, fit, start, source, measured.warnings).str();
  out["fitted"] = fitted;
  out["cable_files"] = cable_files;
  out["cable"] = cable::Cable(fit.damper.arms.front().cable);
  out["damper"] = damper::Damper(fit.damper);
  out["damper_file"] = requests::fitted_damper_file(fit, input ? *input : std::string("arrays"));
  return out;
}

/// The self-damping law fitted to tests (stockbridge.identify_self_damping wraps
/// it): the --json summary as a dict and 'table', the [self_damping] table -o writes.
py::dict identify_self_damping(const std::optional<std::string>& file, const std::optional<std::vector<double>>& tension,
                               const std::optional<std::vector<double>>& frequency,
                               const std::optional<std::vector<double>>& amplitude,
                               const std::optional<std::vector<double>>& power, const std::optional<double>& n,
                               bool allow_unusual) {
  const bool arrays = tension || frequency || amplitude || power;
  if (file.has_value() == arrays) {
    throw InvalidParameter("give either file (a test CSV's path) or tension, frequency, amplitude and power");
  }
  if (arrays && !(tension && frequency && amplitude && power)) {
    throw InvalidParameter("give tension, frequency, amplitude and power (arrays of one value per test)");
  }
  const measurements::SelfDampingTests tests =
      file ? measurements::load_self_damping_tests(*file, slip_policy(allow_unusual))
           : measurements::self_damping_tests_from_arrays(*tension, *frequency, *amplitude, *power,
                                                          slip_policy(allow_unusual));
  warn(tests.warnings);
  measurements::SelfDampingFit fit;
  try {
    fit = measurements::fit_self_damping(tests.tests, n);
  } catch (const InvalidParameter& e) {
    if (file && e.field() != "n") throw InputError(fmt::format("{}: {}", *file, e.what()));
    throw;
  }
  py::dict out = from_json(requests::self_damping_summary(fit, tests.warnings));
  out["table"] = requests::self_damping_table(fit, file ? *file : std::string("arrays"));
  return out;
}

/// A measured impedance file's warnings (values outside the typical ranges, phases
/// in radians), for the plots: stockbridge.plot impedance draws the file itself.
std::vector<std::string> measured_impedance_warnings(const std::string& path) {
  return io::load_measured_impedance(path, SlipPolicy::warn).warnings;
}

}  // namespace

void expose_identification(py::module_& m) {
  const requests::ImpedanceFitRequest fit;
  const requests::LocalRequest local;
  const requests::GlobalRequest global;
  m.def("identify_local", &identify_local, py::arg("curvature"), py::arg("moment"), py::arg("elements") = local.elements,
        py::arg("optimizer") = local.optimizer, py::arg("law") = local.law,
        "Masing parameters (law='masing': ei, jenkin) or Bouc-Wen ones (law='bouc-wen': ei_min, ei_max, chi0) of a "
        "section from a moment-curvature record.");
  m.def("identify_global", &identify_global, py::arg("experiment"), py::arg("length"), py::arg("prescribed"),
        py::arg("measured"), py::arg("method") = global.method, py::arg("sections") = global.sections,
        py::arg("elements") = global.elements, py::arg("optimizer") = global.optimizer, py::arg("law") = global.law,
        "Constant cable parameters from a cycle of experiment (a) or (b), by the Masing law or (law='bouc-wen', "
        "method='fit') the Bouc-Wen law; 'cable' is a Cable ready for make_damper.");
  m.def("_identify_impedance", &identify_impedance, py::arg("damper"), py::arg("input") = py::none(),
        py::arg("frequency") = py::none(), py::arg("velocity") = py::none(), py::arg("displacement") = py::none(),
        py::arg("z") = py::none(), py::arg("elements") = fit.elements, py::arg("fit_clamp_mass") = fit.fit_clamp_mass,
        py::arg("free") = fit.free, py::arg("rms_limit") = fit.rms_limit, py::arg("threads") = fit.threads,
        py::arg("scatter") = py::none(), py::arg("allow_unusual") = false,
        "The identification from a measured impedance (stockbridge.identify_impedance wraps it).");
  m.def("_identify_self_damping", &identify_self_damping, py::arg("file") = py::none(),
        py::arg("tension") = py::none(), py::arg("frequency") = py::none(), py::arg("amplitude") = py::none(),
        py::arg("power") = py::none(), py::arg("n") = py::none(), py::arg("allow_unusual") = false,
        "The self-damping law fitted to tests (stockbridge.identify_self_damping wraps it).");
  m.def("_measured_impedance_warnings", &measured_impedance_warnings, py::arg("path"),
        "A measured impedance CSV's warnings (values outside the typical ranges, phases in radians), as lines; "
        "InputError for a file identify impedance refuses.");
}

}  // namespace stockbridge::python
