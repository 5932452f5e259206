#include "stockbridge/requests/impedance_fit_request.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/csv_writer.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/requests/identify_request.hpp"

namespace stockbridge::requests {

namespace {

constexpr double kNotModelled = std::numeric_limits<double>::quiet_NaN();

io::JsonObject estimate_json(const identification::ParameterEstimate& e) {
  return io::JsonObject()
      .add("name", e.name)
      .add("unit", e.unit)
      .add("value", e.value)
      .add("standard_error", e.standard_error)
      .add("resolution_at_1_percent", e.resolution_at_1_percent)
      .add("sensitivity", e.sensitivity)
      .add("determined", e.determined)
      .add("geometry", e.geometry);
}

std::vector<io::JsonObject> jenkin_json(const section::MasingParameters& p) {
  std::vector<io::JsonObject> out;
  for (const section::Jenkin& e : p.jenkin) out.push_back(io::JsonObject().add("c", e.c).add("h", e.h));
  return out;
}

/// "2.79 +- 0.02" or "2.79 (not determined)".
std::string with_error(const identification::ParameterEstimate& e) {
  if (!e.determined) return fmt::format("{:.6g} (not determined)", e.value);
  return fmt::format("{:.6g} +- {:.2g}", e.value, e.standard_error);
}

}  // namespace

identification::ImpedanceIdentificationOptions fit_options(const ImpedanceFitRequest& request) {
  require_in_range("elements", request.elements, 1, 6);
  require_in_range("threads", request.threads, 1, 1024);
  identification::ImpedanceIdentificationOptions options;
  options.elements = request.elements;
  options.fit_clamp_mass = request.fit_clamp_mass;
  options.threads = request.threads;
  options.free = request.free;
  options.rms_limit = request.rms_limit;
  options.validate();
  return options;
}

identification::ImpedanceMeasurement measurement_from_arrays(const std::vector<double>& frequency,
                                                             const std::vector<double>& amplitude, bool velocity,
                                                             const std::vector<std::complex<double>>& z) {
  if (frequency.size() != amplitude.size() || frequency.size() != z.size()) {
    throw InvalidParameter(fmt::format("frequency, {} and z: {}, {} and {} values: expected as many of each",
                                       velocity ? "velocity" : "displacement", frequency.size(), amplitude.size(),
                                       z.size()));
  }
  identification::ImpedanceMeasurement m;
  m.held = velocity ? damper::HeldAmplitude::velocity : damper::HeldAmplitude::displacement;
  for (std::size_t i = 0; i < frequency.size(); ++i) {
    require_positive(fmt::format("frequency[{}]", i), frequency[i], "Hz");
    require_positive(fmt::format("{}[{}]", velocity ? "velocity" : "displacement", i), amplitude[i], velocity ? "m/s" : "m");
    const damper::Excitation e =
        velocity ? damper::Excitation::from_velocity(frequency[i], amplitude[i]) : damper::Excitation{frequency[i], amplitude[i]};
    m.points.push_back({e, z[i]});
  }
  m.validate();
  return m;
}

std::vector<FittedPoint> fitted_points(const identification::ImpedanceMeasurement& measurement,
                                       const identification::ImpedanceIdentification& fit) {
  std::vector<FittedPoint> rows;
  for (std::size_t i = 0; i < measurement.points.size(); ++i) rows.push_back({&measurement.points[i], &fit.fitted[i]});
  return rows;
}

namespace {

Quantity<FittedPoint> measured(std::string name, std::string unit, std::string meaning,
                               std::function<double(const identification::MeasuredImpedance&)> value) {
  return {std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
          [value = std::move(value)](const FittedPoint& p, std::size_t) { return value(*p.measured); }, {}};
}

Quantity<FittedPoint> modelled(std::string name, std::string meaning, double (*part)(const std::complex<double>&)) {
  return {std::move(name), "N s/m", std::move(meaning), ColumnKind::number,
          [part](const FittedPoint& p, std::size_t) { return p.model->converged() ? part(p.model->impedance) : kNotModelled; },
          {}};
}

double real_part(const std::complex<double>& z) { return z.real(); }
double imaginary_part(const std::complex<double>& z) { return z.imag(); }

}  // namespace

Table<FittedPoint> fitted_table() {
  using M = identification::MeasuredImpedance;
  return Table<FittedPoint>({
      measured("frequency_hz", "Hz", "the measured point's frequency", [](const M& m) { return m.excitation.frequency_hz; }),
      measured("velocity_m_s", "m/s", "its clamp velocity amplitude", [](const M& m) { return m.excitation.velocity_amplitude(); }),
      measured("displacement_m", "m", "its clamp displacement amplitude",
               [](const M& m) { return m.excitation.displacement_amplitude; }),
      measured("re_z_n_s_m", "N s/m", "the measured Re Z", [](const M& m) { return m.impedance.real(); }),
      measured("im_z_n_s_m", "N s/m", "the measured Im Z", [](const M& m) { return m.impedance.imag(); }),
      modelled("model_re_z_n_s_m", "the fitted model's Re Z there (empty where it did not converge)", real_part),
      modelled("model_im_z_n_s_m", "the fitted model's Im Z there", imaginary_part),
      {"converged", "", "1 where the fitted model converged at the point, else 0", ColumnKind::flag,
       [](const FittedPoint& p, std::size_t) { return p.model->converged() ? 1.0 : 0.0; }, {}},
  });
}

std::vector<Warning> fit_warnings(const identification::ImpedanceIdentification& fit, std::string_view source) {
  std::vector<Warning> out = plain_warnings(fit.notes);
  if (fit.poor_fit) {
    out.push_back({fmt::format("the fit's RMS relative error of Z {:.3g} % is large (above {:g} %): the model does not "
                               "follow {} (check its units, the damper's masses and lengths or fit them with --free{})",
                               100.0 * fit.rms_relative_error, 100.0 * fit.rms_limit, source,
                               fit.law == cable::SectionLawKind::masing ? ", --elements" : ""),
                   false});
  }
  return out;
}

io::JsonObject fit_summary(const identification::ImpedanceMeasurement& measurement,
                           const identification::ImpedanceIdentification& fit, const damper::Damper& start,
                           std::string_view source, const std::vector<std::string>& input_warnings) {
  std::vector<io::JsonObject> parameters, stick, cables;
  std::vector<std::string> undetermined;
  io::JsonObject geometry;
  for (const identification::ParameterEstimate& e : fit.parameters) {
    parameters.push_back(estimate_json(e));
    if (!e.determined) undetermined.push_back(e.name);
    if (e.geometry) geometry.add(e.name, e.value);
  }
  for (const identification::ParameterEstimate& e : fit.stick_stiffness) stick.push_back(estimate_json(e));
  // A cable type's law and numbers.
  auto add_cable = [&](io::JsonObject& json, std::size_t t) -> io::JsonObject& {
    if (fit.law == cable::SectionLawKind::bouc_wen) return add_bouc_wen(json, fit.bouc_wen_cables[t]);
    return json.add("ei", fit.cables[t].ei).add("jenkin", jenkin_json(fit.cables[t]));
  };
  for (std::size_t t = 0; t < fit.types(); ++t) {
    std::vector<std::string> arms;
    for (std::size_t k = 0; k < fit.cable_type.size(); ++k) {
      if (fit.cable_type[k] == t) arms.push_back(start.arm_name(k));
    }
    io::JsonObject type;
    cables.push_back(add_cable(type.add("arms", arms), t));
  }
  std::vector<std::vector<double>> correlation(static_cast<std::size_t>(fit.correlation.rows()));
  for (Eigen::Index i = 0; i < fit.correlation.rows(); ++i) {
    for (Eigen::Index j = 0; j < fit.correlation.cols(); ++j) correlation[static_cast<std::size_t>(i)].push_back(fit.correlation(i, j));
  }
  io::JsonObject summary;
  return add_cable(summary, 0)
      .add("clamp_mass_kg", fit.clamp_mass)
      .add("misfit", fit.misfit)
      .add("rms_relative_error", fit.rms_relative_error)
      .add("rms_limit", fit.rms_limit)
      .add("poor_fit", fit.poor_fit)
      .add("points", static_cast<int>(measurement.points.size()))
      .add("curves", static_cast<int>(identification::measured_curves(measurement).size()))
      .add("not_converged", fit.not_converged)
      .add("parameters", parameters)
      .add("geometry", geometry)
      .add("correlation", correlation)
      .add("stick_stiffness", stick)
      .add("undetermined", undetermined)
      .add("notes", fit.notes)
      .add("cables", cables)
      .add("model_runs", fit.model_evaluations)
      .add("starts", fit.starts)
      .add("termination", termination_name(fit.fit.termination))
      .add("iterations", fit.fit.jacobians)
      .add("warnings", [&] {
        std::vector<std::string> lines = input_warnings;
        for (std::string& line : warning_messages(fit_warnings(fit, source))) lines.push_back(std::move(line));
        return lines;
      }());
}

std::string fit_summary_line(const identification::ImpedanceMeasurement& measurement,
                             const identification::ImpedanceIdentification& fit) {
  std::vector<std::string> parts;
  for (const identification::ParameterEstimate& e : fit.parameters) {
    parts.push_back(fmt::format("{} = {} {}", e.name, with_error(e), e.unit));
  }
  const std::size_t curves = identification::measured_curves(measurement).size();
  return fmt::format("identify impedance: {}; RMS relative error of Z {:.3g} % over {} points ({} curve{}), {} model runs",
                     fmt::join(parts, ", "), 100.0 * fit.rms_relative_error, measurement.points.size(), curves,
                     curves == 1 ? "" : "s", fit.model_evaluations);
}

std::string fitted_cable_file(const identification::ImpedanceIdentification& fit, std::size_t type,
                              std::string_view source) {
  const std::size_t arm = static_cast<std::size_t>(
      std::find(fit.cable_type.begin(), fit.cable_type.end(), type) - fit.cable_type.begin());
  std::string comment = fmt::format(
      "Identified by stockbridge identify impedance from {}:\n"
      "RMS relative error of Z {:.4g} % at {} points; the length is arm[{}]'s (damper files cut it to theirs).",
      source, 100.0 * fit.rms_relative_error, fit.fitted.size(), arm);
  const std::string prefix = fit.types() > 1 ? fmt::format("arm[{}].cable.", arm) : "";
  for (const identification::ParameterEstimate& e : fit.parameters) {
    if (!e.determined && e.name.starts_with(prefix) && !e.geometry) comment += fmt::format("\n{} = {:.6g} {} is NOT determined by the data.", e.name, e.value, e.unit);
  }
  return io::cable_file_toml(fit.damper.arms[arm].cable, comment);
}

std::string fitted_damper_file(const identification::ImpedanceIdentification& fit, std::string_view source) {
  std::string comment = fmt::format("Identified by stockbridge identify impedance from {}:\nRMS relative error of Z {:.4g} % at {} points{}.",
                                    source, 100.0 * fit.rms_relative_error, fit.fitted.size(),
                                    fit.poor_fit ? fmt::format(", above the limit {:g} %: a poor fit", 100.0 * fit.rms_limit) : "");
  std::vector<std::string> fitted;
  for (const identification::ParameterEstimate& e : fit.parameters) {
    if (e.geometry) fitted.push_back(e.name);
  }
  if (!fitted.empty()) comment += fmt::format("\nFitted with the cables: {}.", fmt::join(fitted, ", "));
  for (const identification::ParameterEstimate& e : fit.parameters) {
    if (!e.determined) comment += fmt::format("\n{} = {:.6g} {} is NOT determined by the data.", e.name, e.value, e.unit);
  }
  return io::damper_file_toml(fit.damper, comment);
}

}  // namespace stockbridge::requests
