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

io::JsonObject& add_confounding(io::JsonObject& json, const identification::ParameterEstimate& e) {
  if (e.confounded_by.empty()) return json.add_null("confounded_by").add("confounded_shift", 0.0);
  return json.add("confounded_by", e.confounded_by).add("confounded_shift", e.confounded_shift);
}

io::JsonObject lack_of_fit_json(const identification::LackOfFit& l) {
  std::vector<io::JsonObject> suspects;
  for (const identification::FixedNumberSuspect& s : l.suspects) {
    suspects.push_back(io::JsonObject()
                           .add("name", s.name)
                           .add("unit", s.unit)
                           .add("value", s.value)
                           .add("misfit_reduction", s.misfit_reduction)
                           .add("suggested_value", s.suggested_value));
  }
  return io::JsonObject()
      .add("scatter", l.scatter)
      .add("scatter_assumed", l.assumed)
      .add("ratio", l.ratio)
      .add("statistic", l.statistic)
      .add("degrees_of_freedom", l.degrees_of_freedom)
      .add("p_value", l.p_value)
      .add("critical_statistic", l.critical)
      .add("level", l.level)
      .add("significant", l.significant)
      .add("error_inflation", l.error_inflation)
      .add("suspects", suspects)
      .add("notes", l.notes);
}

/// "p = 0.13", "p = 2.1e-40", "p < 1e-300" (a p-value below double's range).
std::string p_value_text(double p) {
  if (std::isnan(p)) return "no degrees of freedom";
  return p > 0.0 ? fmt::format("p = {:.2g}", p) : "p < 1e-300";
}

/// "the scatter 1 %" with where it came from.
std::string scatter_text(const identification::LackOfFit& l) {
  return fmt::format("{:g} %{}", 100.0 * l.scatter, l.assumed ? ", assumed: a shaker test's; state the sheet's with --scatter" : "");
}

std::vector<io::JsonObject> jenkin_json(const section::MasingParameters& p) {
  std::vector<io::JsonObject> out;
  for (const section::Jenkin& e : p.jenkin) out.push_back(io::JsonObject().add("c", e.c).add("h", e.h));
  return out;
}

/// "2.79 +- 0.02", "2.79 (not determined)" or "3.18 +- 0.047 (confounded by arm.long.inertia)".
std::string with_error(const identification::ParameterEstimate& e) {
  if (!e.determined) return fmt::format("{:.6g} (not determined)", e.value);
  if (!e.confounded_by.empty()) return fmt::format("{:.6g} +- {:.2g} (confounded by {})", e.value, e.standard_error, e.confounded_by);
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
  options.scatter = request.scatter;
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
    require_plausible(fmt::format("frequency[{}]", i), frequency[i], "Hz");
    require_plausible(fmt::format("{}[{}]", velocity ? "velocity" : "displacement", i), amplitude[i], velocity ? "m/s" : "m");
    if (const double magnitude = std::abs(z[i]); !(magnitude >= smallest_magnitude && magnitude <= largest_magnitude)) {
      throw InvalidParameter(fmt::format("z[{}]", i),
                             fmt::format(" = {} + {} i N s/m: expected finite, with |Z| from {:g} to {:g}; one outside "
                                         "is a unit mistake",
                                         format_value(z[i].real()), format_value(z[i].imag()), smallest_magnitude,
                                         largest_magnitude));
    }
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
          [part](const FittedPoint& p, std::size_t) { return p.model->converged() ? part(p.model->impedance) : kNoValue; },
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
                               fit.law->jenkin_elements() ? ", --elements" : ""),
                   false});
  }
  const identification::LackOfFit& l = fit.lack_of_fit;
  if (l.significant) {
    out.push_back({fmt::format("lack of fit: the RMS relative error of Z {:.3g} % is {:.3g} times the scatter of {} "
                               "({}; chi-square {:.4g} on {} degrees of freedom, above {:.4g} at {:g} %, {}): the model "
                               "cannot reach it within its scatter; the standard errors are inflated {:.3g} times",
                               100.0 * fit.rms_relative_error, l.ratio, source, scatter_text(l), l.statistic,
                               l.degrees_of_freedom, l.critical, 100.0 * (1.0 - l.level), p_value_text(l.p_value),
                               l.error_inflation),
                   false});
    std::vector<std::string> named;
    for (const identification::FixedNumberSuspect& s : l.suspects) {
      if (s.misfit_reduction < identification::explaining_share || named.size() == 3) break;
      named.push_back(fmt::format("{} {:.2g} % (to {:.4g} {}, from {:.4g})", s.name, 100.0 * s.misfit_reduction,
                                  s.suggested_value, s.unit, s.value));
    }
    if (!named.empty()) {
      // Shares within a tenth of the first's: the data hardly tell those numbers apart.
      const bool close = named.size() > 1 && l.suspects[1].misfit_reduction >= 0.9 * l.suspects[0].misfit_reduction;
      out.push_back({fmt::format("fixed numbers of the damper that may be wrong, by the share of the misfit freeing each "
                                 "would remove: {}: {}",
                                 fmt::join(named, ", "),
                                 named.size() == 1 ? "check it on the drawing, or fit it with --free"
                                 : close ? "shares this close hardly tell them apart: check them on the drawing, or fit "
                                           "one at a time with --free"
                                         : "check the first on the drawing, or fit it with --free"),
                     false});
    } else if (!l.suspects.empty()) {
      out.push_back({fmt::format("no fixed number of the damper explains the lack of fit (freeing {}, the most, would "
                                 "remove {:.2g} % of the misfit): check the measurement's units and scatter, the "
                                 "cable's law{}",
                                 l.suspects.front().name, 100.0 * l.suspects.front().misfit_reduction,
                                 fit.law->jenkin_elements() ? " and --elements" : ""),
                     false});
    }
    for (const Warning& w : plain_warnings(l.notes)) out.push_back(w);
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
    io::JsonObject json = estimate_json(e);
    parameters.push_back(add_confounding(json, e));
    if (!e.determined) undetermined.push_back(e.name);
    if (e.geometry) geometry.add(e.name, e.value);
  }
  for (const identification::ParameterEstimate& e : fit.stick_stiffness) stick.push_back(estimate_json(e));
  // A cable type's law and numbers.
  auto add_cable = [&](io::JsonObject& json, std::size_t t) -> io::JsonObject& {
    if (!fit.law->jenkin_elements()) return add_law_numbers(json, fit.law_cables[t]);
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
      .add("lack_of_fit", lack_of_fit_json(fit.lack_of_fit))
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
  const identification::LackOfFit& l = fit.lack_of_fit;
  return fmt::format("identify impedance: {}; RMS relative error of Z {:.3g} % over {} points ({} curve{}), {:.3g} times "
                     "the scatter {:g} %{} ({}{}), {} model runs",
                     fmt::join(parts, ", "), 100.0 * fit.rms_relative_error, measurement.points.size(), curves,
                     curves == 1 ? "" : "s", l.ratio, 100.0 * l.scatter, l.assumed ? " assumed" : "",
                     l.significant ? "lack of fit, " : "", p_value_text(l.p_value), fit.model_evaluations);
}

namespace {

/// A file comment's line on a significant lack of fit ("" without one).
std::string lack_of_fit_comment(const identification::ImpedanceIdentification& fit) {
  const identification::LackOfFit& l = fit.lack_of_fit;
  if (!l.significant) return "";
  std::string line = fmt::format("\nLACK OF FIT: the error is {:.3g} times the scatter {:g} % ({}): the model does not reach "
                                 "the measurement; a fixed number of the damper may be wrong",
                                 l.ratio, 100.0 * l.scatter, p_value_text(l.p_value));
  if (!l.suspects.empty() && l.suspects.front().misfit_reduction >= identification::explaining_share) {
    line += fmt::format(" ({} explains {:.2g} % of the misfit)", l.suspects.front().name,
                        100.0 * l.suspects.front().misfit_reduction);
  }
  return line + ".";
}

}  // namespace

std::string fitted_cable_file(const identification::ImpedanceIdentification& fit, std::size_t type,
                              std::string_view source) {
  const std::size_t arm = static_cast<std::size_t>(
      std::find(fit.cable_type.begin(), fit.cable_type.end(), type) - fit.cable_type.begin());
  std::string comment = fmt::format(
      "Identified by stockbridge identify impedance from {}:\n"
      "RMS relative error of Z {:.4g} % at {} points; the length is arm[{}]'s (damper files cut it to theirs).",
      source, 100.0 * fit.rms_relative_error, fit.fitted.size(), arm);
  comment += lack_of_fit_comment(fit);
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
  comment += lack_of_fit_comment(fit);
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
