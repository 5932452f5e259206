// A damper's impedance over frequencies and amplitudes, one steady response, its linear modes.
#include "binding_support.hpp"

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/requests/modes_request.hpp"
#include "stockbridge/requests/plausibility.hpp"
#include "stockbridge/requests/response_request.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::python {

namespace {

py::dict impedance(const damper::Damper& d, const std::optional<std::vector<double>>& frequencies,
                   const py::object& velocity, const py::object& displacement, double fmin, double fmax, int points,
                   const std::string& method, std::optional<int> harmonics, std::optional<int> samples,
                   std::optional<int> steps, std::optional<int> max_iterations, std::optional<int> max_periods,
                   std::optional<double> energy_tolerance, bool full_period, int threads, bool allow_unusual) {
  requests::SweepRequest request;
  request.velocities = amplitudes_of(velocity);
  request.displacements = amplitudes_of(displacement);
  if (frequencies) {
    if (frequencies->empty()) throw InvalidParameter("frequencies", ": an empty list, expected at least one frequency (Hz)");
    request.frequencies = *frequencies;
  }
  request.grid = {fmin, fmax, points};
  request.solver =
      solver_settings(method, harmonics, samples, steps, max_iterations, max_periods, energy_tolerance, full_period);
  request.threads = threads;
  const damper::SweepSpec spec = requests::sweep_spec(request);
  std::vector<std::string> unusual;
  for (const UnusualValue& u : requests::unusual_values(request)) judge_unusual(u, "", slip_policy(allow_unusual), unusual);
  warn(unusual);
  std::vector<damper::SweepRun> runs;
  {
    py::gil_scoped_release release;
    runs = damper::run_sweep(d, spec);
  }
  const std::vector<std::size_t> shape{runs.size(), spec.frequencies.size()};
  const std::vector<const damper::ImpedancePoint*> rows = requests::sweep_points(runs);
  py::dict out = table_arrays(requests::impedance_table(d).values(rows), shape);
  for (const auto& [name, values] : table_arrays(requests::impedance_point_notes_table().values(rows), shape)) {
    out[name] = values;
  }
  out["frequency_hz"] = array(spec.frequencies);  // 1-D: the frequencies
  out["amplitude"] = array(spec.amplitudes);
  out["arms"] = requests::arm_column_prefixes(d);  // the <arm> of the per-arm columns, as the CSV's
  return out;
}

py::dict response(const damper::Damper& d, double frequency, std::optional<double> velocity, std::optional<double> displacement,
                  const std::string& method, std::optional<int> harmonics, std::optional<int> samples,
                  std::optional<int> steps, std::optional<int> max_iterations, std::optional<int> max_periods,
                  std::optional<double> energy_tolerance, bool full_period, bool allow_unusual) {
  const requests::ResponseRequest request{
      frequency, velocity, displacement,
      solver_settings(method, harmonics, samples, steps, max_iterations, max_periods, energy_tolerance, full_period)};
  requests::validate(request);
  std::vector<std::string> unusual;  // warned of with the result's warnings
  for (const UnusualValue& u : requests::unusual_excitation(frequency, velocity, displacement)) {
    judge_unusual(u, "", slip_policy(allow_unusual), unusual);
  }
  std::optional<requests::ResponseResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_response(d, request));
  }
  warn(warning_messages(result->warnings));
  const damper::ImpedancePoint& point = result->state.point;
  py::dict out = table_arrays(requests::response_table(d).values(requests::response_samples(*result)),
                              {result->time.size()}, true);
  add_row(out, requests::point_summary_table(d).values(point), 0);  // converged, termination, power_w, figures, ...
  out["arms"] = requests::arm_column_prefixes(d);  // the rows of the per-arm arrays, named as the CSV's columns
  out["message"] = point.converged() ? point.note : point.failure;
  out["impedance"] = point.converged() ? point.impedance : std::complex<double>(kNaN, kNaN);
  return out;
}

/// The modes command's JSON as a dict (the same keys), arms named as the CSV's columns.
py::dict modes(const damper::Damper& d) {
  std::optional<requests::ModesResult> result;
  {
    py::gil_scoped_release release;
    result.emplace(requests::run_modes(d));
  }
  return from_json(requests::modes_summary(*result));
}

}  // namespace

void expose_damper(py::module_& m) {
  const requests::FrequencyGrid grid;
  const requests::SolverSettings solver;
  m.def("impedance", &impedance, py::arg("damper"), py::arg("frequencies") = py::none(), py::arg("velocity") = py::none(),
        py::arg("displacement") = py::none(), py::arg("fmin") = grid.fmin, py::arg("fmax") = grid.fmax, py::arg("points") = grid.points,
        py::arg("method") = solver.method, py::arg("harmonics") = py::none(), py::arg("samples") = py::none(),
        py::arg("steps") = py::none(), py::arg("max_iterations") = py::none(), py::arg("max_periods") = py::none(),
        py::arg("energy_tolerance") = py::none(), py::arg("full_period") = false, py::arg("threads") = requests::SweepRequest{}.threads,
        py::arg("allow_unusual") = false,
        "Z(f, amplitude) over `frequencies` (or fmin..fmax, `points` log-spaced): arrays of shape (amplitudes, "
        "frequencies) named as the impedance CSV's columns (the design figures per arm as '<arm>_power_w' and "
        "'<arm>_mass_amplitude_m', the arms named in 'arms'); NaN where a point did not converge (see 'converged', "
        "'termination' and 'messages'). Solver settings left None take the method's default.");
  m.def("response", &response, py::arg("damper"), py::arg("frequency"), py::arg("velocity") = py::none(),
        py::arg("displacement") = py::none(), py::arg("method") = solver.method, py::arg("harmonics") = py::none(),
        py::arg("samples") = py::none(), py::arg("steps") = py::none(), py::arg("max_iterations") = py::none(),
        py::arg("max_periods") = py::none(), py::arg("energy_tolerance") = py::none(), py::arg("full_period") = false,
        py::arg("allow_unusual") = false,
        "One steady period; per-arm arrays have shape (arms, samples). A point that did not converge is returned "
        "as its last iterate with converged = False, its termination and message (NaN where nothing was computed). "
        "The point's design figures are numbers named as the impedance CSV's columns.");
  m.def("modes", &modes, py::arg("damper"),
        "Linear natural frequencies (Hz), every element sticking and every one slipping, as the modes command's "
        "JSON: 'arms' (each arm, clamp held: name, stick_hz, slip_hz) and 'damper' (clamp free, the rigid-body "
        "mode left out: stick_hz, slip_hz, and stick_modes/slip_modes with each arm's share of the energy).");
}

}  // namespace stockbridge::python
