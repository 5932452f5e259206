// stockbridge._core: the Python binding. It holds no logic: each function converts
// its arguments, calls the library with the GIL released, and returns numpy arrays.

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "stockbridge/cable/experiment.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/strand/strand_bounds.hpp"

namespace py = pybind11;
using namespace stockbridge;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

py::array_t<double> array(const std::vector<double>& values) { return py::array_t<double>(values.size(), values.data()); }

py::array_t<double> matrix(const std::vector<std::vector<double>>& rows) {
  const std::size_t n = rows.size(), m = rows.empty() ? 0 : rows.front().size();
  py::array_t<double> out({n, m});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) view(i, j) = rows[i][j];
  }
  return out;
}

std::vector<double> amplitudes_of(const py::object& value) {
  if (value.is_none()) return {};
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return {value.cast<double>()};
  return value.cast<std::vector<double>>();
}

damper::SolverOptions solver_options(const std::string& method, int harmonics, int samples) {
  damper::SolverOptions options;
  options.method = damper::parse_method(method);
  options.harmonic_balance.harmonics = harmonics;
  options.harmonic_balance.samples = samples;
  options.validate();
  return options;
}

py::dict impedance(const damper::DamperDescription& d, const std::vector<double>& frequencies, const py::object& velocity,
                   const py::object& displacement, const std::string& method, int harmonics, int samples, int threads) {
  damper::SweepSpec spec;
  const std::vector<double> v = amplitudes_of(velocity), x = amplitudes_of(displacement);
  if (v.empty() == x.empty()) throw InvalidParameter("give either velocity (m/s) or displacement (m), a value or a list");
  spec.constant_displacement = !x.empty();
  spec.amplitudes = spec.constant_displacement ? x : v;
  spec.frequencies = frequencies;
  spec.solver = solver_options(method, harmonics, samples);
  spec.threads = threads;
  std::vector<damper::SweepRun> runs;
  {
    py::gil_scoped_release release;
    runs = damper::run_sweep(d, spec);
  }
  const std::size_t na = runs.size(), nf = frequencies.size();
  std::vector<std::vector<double>> re(na), im(na), power(na), dissipated(na), energy(na), residual(na), vel(na), disp(na);
  py::array_t<bool> converged({na, nf}), non_unique({na, nf});
  auto c = converged.mutable_unchecked<2>();
  auto u = non_unique.mutable_unchecked<2>();
  py::list messages;
  for (std::size_t a = 0; a < na; ++a) {
    py::list row;
    for (std::size_t i = 0; i < nf; ++i) {
      const damper::ImpedancePoint& p = runs[a].points[i];
      re[a].push_back(p.converged ? p.impedance.real() : kNaN);
      im[a].push_back(p.converged ? p.impedance.imag() : kNaN);
      power[a].push_back(p.converged ? p.power : kNaN);
      dissipated[a].push_back(p.converged ? p.dissipated_power : kNaN);
      energy[a].push_back(p.converged ? p.energy_error : kNaN);
      residual[a].push_back(p.converged ? p.residual : kNaN);
      vel[a].push_back(p.velocity_amplitude);
      disp[a].push_back(p.displacement_amplitude);
      c(a, i) = p.converged;
      u(a, i) = p.non_unique;
      row.append(p.message);
    }
    messages.append(row);
  }
  py::dict out;
  out["frequency_hz"] = array(frequencies);
  out["amplitude"] = array(spec.amplitudes);
  out["velocity_m_s"] = matrix(vel);
  out["displacement_m"] = matrix(disp);
  out["re_z_n_s_m"] = matrix(re);
  out["im_z_n_s_m"] = matrix(im);
  out["power_w"] = matrix(power);
  out["dissipated_power_w"] = matrix(dissipated);
  out["energy_error"] = matrix(energy);
  out["residual"] = matrix(residual);
  out["converged"] = converged;
  out["non_unique"] = non_unique;
  out["messages"] = messages;
  return out;
}

py::dict response(const damper::DamperDescription& d, double frequency, const py::object& velocity,
                  const py::object& displacement, const std::string& method, int harmonics, int samples) {
  const std::vector<double> v = amplitudes_of(velocity), x = amplitudes_of(displacement);
  if (v.size() + x.size() != 1) throw InvalidParameter("give either velocity (m/s) or displacement (m), one value");
  const damper::Excitation e = v.empty() ? damper::Excitation{frequency, x[0]} : damper::Excitation::from_velocity(frequency, v[0]);
  e.validate();
  const damper::SolverOptions options = solver_options(method, harmonics, samples);
  damper::DamperSteadyState state;
  {
    py::gil_scoped_release release;
    state = damper::solve_steady_state(d, e, options);
  }
  if (!state.point.converged) throw NumericalError("no steady state: " + state.point.message);
  std::vector<const damper::ArmSolution*> arms;
  for (const auto& s : state.arms) arms.push_back(&s);
  const Eigen::RowVectorXd force = damper::shaker_force(d, e, arms);
  const std::size_t n = static_cast<std::size_t>(force.size());
  std::vector<double> time(n), clamp(n), shaker(force.data(), force.data() + n);
  for (std::size_t j = 0; j < n; ++j) {
    time[j] = e.period() * static_cast<double>(j) / static_cast<double>(n);
    clamp[j] = e.displacement_amplitude * std::sin(e.angular_frequency() * time[j]);
  }
  std::vector<std::vector<double>> xs, phis, fs, ts, qs, ks, ms;
  for (const auto& s : state.arms) {
    const damper::ArmPeriod& p = s.period;
    std::vector<double> x_row(n), phi_row(n), f_row(n), q_row(n);
    for (std::size_t j = 0; j < n; ++j) {
      x_row[j] = p.kinematics(0, static_cast<Eigen::Index>(j));
      phi_row[j] = p.kinematics(1, static_cast<Eigen::Index>(j));
      f_row[j] = p.loads(0, static_cast<Eigen::Index>(j));
      q_row[j] = p.loads(1, static_cast<Eigen::Index>(j));
    }
    xs.push_back(x_row);
    phis.push_back(phi_row);
    fs.push_back(f_row);
    qs.push_back(q_row);
    ts.push_back(p.clamp_moment);
    ks.push_back(p.clamp_curvature);
    ms.push_back(p.clamp_section_moment);
  }
  py::dict out;
  out["time_s"] = array(time);
  out["clamp_displacement_m"] = array(clamp);
  out["shaker_force_n"] = array(shaker);
  out["x_m"] = matrix(xs);
  out["phi_rad"] = matrix(phis);
  out["force_n"] = matrix(fs);
  out["clamp_moment_n_m"] = matrix(ts);
  out["tip_moment_n_m"] = matrix(qs);
  out["clamp_curvature_per_m"] = matrix(ks);
  out["clamp_section_moment_n_m"] = matrix(ms);
  out["impedance"] = std::complex<double>(state.point.impedance);
  out["power_w"] = state.point.power;
  out["dissipated_power_w"] = state.point.dissipated_power;
  return out;
}

py::dict cycle(const cable::CableDescription& description, const std::string& experiment, double amplitude, int cycles,
               int points) {
  cable::ExperimentDrive drive{cable::parse_experiment(experiment), amplitude, cycles, points};
  drive.validate();
  cable::ExperimentRecord record;
  {
    py::gil_scoped_release release;
    cable::Cantilever cantilever{cable::Cable(description)};
    record = cable::run_experiment(cantilever, drive);
  }
  std::vector<double> x, phi, f, t, q, w;
  py::array_t<bool> converged(record.samples.size());
  auto c = converged.mutable_unchecked<1>();
  for (std::size_t k = 0; k < record.samples.size(); ++k) {
    const cable::ExperimentSample& s = record.samples[k];
    const bool ok = s.solve.converged;
    x.push_back(ok ? s.deflection : kNaN);
    phi.push_back(ok ? s.rotation : kNaN);
    f.push_back(ok ? s.tip_force : kNaN);
    t.push_back(ok ? s.clamp_moment : kNaN);
    q.push_back(ok ? s.tip_moment : kNaN);
    w.push_back(ok ? s.dissipated : kNaN);
    c(k) = ok;
  }
  py::dict out;
  out["x_m"] = array(x);
  out["phi_rad"] = array(phi);
  out["force_n"] = array(f);
  out["clamp_moment_n_m"] = array(t);
  out["tip_moment_n_m"] = array(q);
  out["dissipated_energy_j"] = array(w);
  out["converged"] = converged;
  out["last_cycle_dissipation_j"] = record.summary.slider_dissipation;
  out["last_cycle_loop_work_j"] = record.summary.loop_work;
  return out;
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

py::dict identify_local(const std::vector<double>& curvature, const std::vector<double>& moment, int elements,
                        const std::string& optimizer) {
  identification::LocalIdentificationOptions options;
  options.elements = elements;
  options.optimizer = identification::parse_optimizer(optimizer);
  identification::LocalIdentification fit;
  {
    py::gil_scoped_release release;
    fit = identification::identify_local({curvature, moment}, options);
  }
  std::vector<std::pair<double, double>> c_h;
  for (const auto& e : fit.parameters.jenkin) c_h.emplace_back(e.c, e.h);
  py::dict out;
  out["ei"] = fit.parameters.ei;
  out["jenkin"] = jenkin_list(c_h);
  out["error"] = fit.error;
  out["moment_offset_n_m"] = fit.moment_offset;
  out["cycle_errors"] = array(fit.cycle_errors);
  return out;
}

py::dict identify_global(const std::string& experiment, double length, const std::vector<double>& prescribed,
                         const std::vector<double>& measured, const std::string& method, int sections, int elements) {
  identification::GlobalIdentificationOptions options;
  options.length = length;
  options.sections = sections;
  options.elements = elements;
  options.validate();
  const identification::ExperimentMeasurement m{cable::parse_experiment(experiment), prescribed, measured};
  if (method != "fit" && method != "four-step") {
    throw InvalidParameter("method = '" + method + "': expected four-step or fit");
  }
  identification::GlobalIdentification fit;
  {
    py::gil_scoped_release release;
    fit = method == "fit" ? identification::identify_fit(m, options) : identification::identify_four_step(m, options);
  }
  std::vector<std::pair<double, double>> c_h;
  for (const auto& e : fit.cable.jenkin) c_h.emplace_back(e.c.at(0.0), e.h.at(0.0));
  py::dict out;
  out["ei"] = fit.cable.ei.at(0.0);
  out["jenkin"] = jenkin_list(c_h);
  out["error"] = fit.error;
  out["cable"] = fit.cable;
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "stockbridge: nonlinear impedance of Stockbridge dampers (C++ library binding)";

  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<InvalidParameter> invalid_parameter(m, "InvalidParameter", PyExc_ValueError);
  static py::exception<NumericalError> numerical_error(m, "NumericalError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const InvalidParameter& e) {
      invalid_parameter(e.what());
    } catch (const NumericalError& e) {
      numerical_error(e.what());
    } catch (const Error& e) {
      error(e.what());
    }
  });

  py::class_<cable::CableDescription>(m, "Cable", "A cable description (length, sections, Masing parameters)")
      .def_readonly("length", &cable::CableDescription::length, "m")
      .def_readonly("sections", &cable::CableDescription::sections)
      .def_property_readonly("ei", [](const cable::CableDescription& c) { return c.ei.at(0.0); }, "N m^2 (at the clamp)");
  py::class_<damper::DamperDescription>(m, "Damper", "A damper description (clamp mass and arms)")
      .def_readonly("clamp_mass", &damper::DamperDescription::clamp_mass, "kg")
      .def_property_readonly("arms", [](const damper::DamperDescription& d) {
        py::list names;
        for (const auto& a : d.arms) names.append(a.name);
        return names;
      });

  m.def("load_cable", [](const std::string& path) { return io::read_cable_file(path); }, py::arg("path"),
        "Read a cable TOML file.");
  m.def("load_damper", [](const std::string& path) { return io::read_damper_file(path); }, py::arg("path"),
        "Read a damper TOML file.");
  m.def(
      "make_cable",
      [](double length, int sections, double ei, const std::vector<std::pair<double, double>>& jenkin) {
        cable::CableDescription d = cable::CableDescription::uniform(length, sections, ei, jenkin);
        d.validate();
        return d;
      },
      py::arg("length"), py::arg("sections") = 40, py::arg("ei"), py::arg("jenkin") = std::vector<std::pair<double, double>>{},
      "A cable with constant parameters: jenkin = [(c, h), ...] in N m^2 and N m.");
  m.def(
      "make_damper",
      [](double clamp_mass, const std::vector<py::dict>& arms) {
        damper::DamperDescription d;
        d.clamp_mass = clamp_mass;
        for (const py::dict& a : arms) {
          damper::ArmDescription arm;
          arm.name = a.contains("name") ? a["name"].cast<std::string>() : "arm" + std::to_string(d.arms.size() + 1);
          arm.mass = a["mass"].cast<double>();
          arm.inertia = a["inertia"].cast<double>();
          arm.offset = a["offset"].cast<double>();
          arm.cable = a["cable"].cast<cable::CableDescription>();
          d.arms.push_back(arm);
        }
        d.validate();
        return d;
      },
      py::arg("clamp_mass"), py::arg("arms"),
      "A damper from arms given as dicts {name, mass, inertia, offset, cable} (kg, kg m^2, m, Cable).");
  m.def("impedance", &impedance, py::arg("damper"), py::arg("frequencies"), py::arg("velocity") = py::none(),
        py::arg("displacement") = py::none(), py::arg("method") = "hb", py::arg("harmonics") = 9, py::arg("samples") = 0,
        py::arg("threads") = 1,
        "Z(f, amplitude): arrays of shape (amplitudes, frequencies); NaN where a point did not converge "
        "(see 'converged' and 'messages').");
  m.def("response", &response, py::arg("damper"), py::arg("frequency"), py::arg("velocity") = py::none(),
        py::arg("displacement") = py::none(), py::arg("method") = "hb", py::arg("harmonics") = 9, py::arg("samples") = 0,
        "One steady period; per-arm arrays have shape (arms, samples).");
  m.def("cycle", &cycle, py::arg("cable"), py::arg("experiment"), py::arg("amplitude"), py::arg("cycles") = 2,
        py::arg("points") = 400, "Experiment 'a' (tip force) or 'b' (tip rotation) on a cable.");
  m.def("identify_local", &identify_local, py::arg("curvature"), py::arg("moment"), py::arg("elements") = 1,
        py::arg("optimizer") = "subplex", "Masing parameters of a section from a moment-curvature record.");
  m.def("identify_global", &identify_global, py::arg("experiment"), py::arg("length"), py::arg("prescribed"),
        py::arg("measured"), py::arg("method") = "fit", py::arg("sections") = 40, py::arg("elements") = 1,
        "Constant cable parameters from a cycle of experiment (a) or (b); 'cable' is a Cable ready for make_damper.");
  m.def(
      "strand_bounds",
      [](double core_radius, const std::vector<std::tuple<int, double, double, double>>& layers, double youngs_modulus) {
        strand::Strand s;
        s.core_radius = core_radius;
        s.youngs_modulus = youngs_modulus;
        for (const auto& [count, r, pitch, lay] : layers) s.layers.push_back({count, r, pitch, lay});
        strand::validate(s);
        const strand::StrandBounds b = strand::strand_bounds(s);
        return std::make_pair(b.ei_min, b.ei_max);
      },
      py::arg("core_radius"), py::arg("layers"), py::arg("youngs_modulus") = 210e9,
      "(EI_min, EI_max) in N m^2; layers = [(count, wire_radius, pitch_radius, lay_length), ...] in m.");
}
