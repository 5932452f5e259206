// The impedance fit's statistics (impedance_fit_statistics.hpp).
#include "impedance_fit_statistics.hpp"

#include <fmt/ranges.h>

namespace stockbridge::identification::impedance_fit {

/// How a law's numbers scale with the damper: "ei_min and ei_max times s^3, chi0 times s^-2".
std::string scaling_words(const cable::SectionLawDescriptor& law) {
  std::vector<int> powers;
  for (const cable::LawNumber& n : law.numbers()) {
    if (n.scaling_power != 0 && std::find(powers.begin(), powers.end(), n.scaling_power) == powers.end()) {
      powers.push_back(n.scaling_power);
    }
  }
  std::string out;
  for (int p : powers) {
    std::vector<std::string> keys;
    for (const cable::LawNumber& n : law.numbers()) {
      if (n.scaling_power == p) keys.push_back(std::string(n.key));
    }
    out += fmt::format("{}{} times s{}", out.empty() ? "" : ", ", cable::joined_with_and(keys),
                       p == 1 ? "" : fmt::format("^{}", p));
  }
  return out;
}

/// Parameter i outside the null space and resolved within kUndeterminedResolution.
bool determined_on_its_own(const std::vector<ParameterEstimate>& parameters, const least_squares::Statistics& s,
                           std::size_t i) {
  return !s.in_null_space[i] && parameters[i].resolution_at_1_percent <= kUndeterminedResolution;
}

/// The first parameter not determined on its own whose estimate is correlated with
/// parameter i's beyond kTiedCorrelation; -1 if none.
int tied_partner(const std::vector<ParameterEstimate>& parameters, const least_squares::Statistics& s, std::size_t i) {
  for (std::size_t j = 0; j < parameters.size(); ++j) {
    const double r = s.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    if (j != i && !determined_on_its_own(parameters, s, j) && std::abs(r) > kTiedCorrelation) return static_cast<int>(j);
  }
  return -1;
}

/// Each variable's estimate (value, standard error, resolution, sensitivity), in the variables' order.
std::vector<ParameterEstimate> estimates(const FitVariables& variables, const Eigen::VectorXd& x,
                                         const least_squares::Statistics& s) {
  std::vector<ParameterEstimate> out;
  for (int i = 0; i < variables.size(); ++i) {
    ParameterEstimate e;
    e.name = variables.name(i);
    e.unit = variables.unit(i);
    if (variables.fits_clamp_mass() && i == variables.clamp_mass_index()) {
      // A linear variable in units of the damper's mass: its resolution in those units.
      e.value = variables.clamp_mass(x);
      e.geometry = true;
      e.standard_error = variables.mass_scale() * s.standard_error(i);
      e.resolution_at_1_percent = s.resolution(i);
      e.sensitivity = s.sensitivity(i) / variables.mass_scale();
    } else if (const DamperNumber* n = variables.number(i)) {
      e.value = n->value(x(i));
      e.geometry = true;
      // A log variable's errors are relative; an offset's in units of its scale.
      e.standard_error = (n->logarithmic ? e.value : n->scale) * s.standard_error(i);
      e.resolution_at_1_percent = s.resolution(i);
      e.sensitivity = n->logarithmic ? s.sensitivity(i) : s.sensitivity(i) / n->scale;
    } else {
      e.value = variables.cable_value(x, i);
      // A log variable: relative errors; a linear one's in units of its step.
      const double scale = variables.linear_scale(i);
      e.standard_error = (scale > 0.0 ? scale : e.value) * s.standard_error(i);
      e.resolution_at_1_percent = s.resolution(i);
      e.sensitivity = scale > 0.0 ? s.sensitivity(i) / scale : s.sensitivity(i);
    }
    if (s.in_null_space[static_cast<std::size_t>(i)]) e.standard_error = kInfinity;
    out.push_back(e);
  }
  // A parameter tied to an undetermined one moves with it: not determined either.
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].determined = determined_on_its_own(out, s, i) && tied_partner(out, s, i) < 0;
  }
  return out;
}

/// Each type's ei + sum c, a combination the data determine even where nothing slips
/// (none under a law of numbers, such as Bouc-Wen's, whose stick stiffness ei_max is a parameter).
std::vector<ParameterEstimate> stick_stiffnesses(const FitVariables& variables, const Eigen::VectorXd& x,
                                                 const least_squares::Statistics& s) {
  std::vector<ParameterEstimate> out;
  const std::vector<section::MasingParameters> cables = variables.cables(x);
  for (std::size_t t = 0; t < cables.size(); ++t) {
    const section::MasingParameters& p = cables[t];
    const double stiffness = p.max_stiffness();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(variables.size());  // d(ei + sum c) / (ei + sum c) per log variable
    const int o = variables.per_type() * static_cast<int>(t);
    g(o) = p.ei / stiffness;
    for (int j = 0; j < variables.elements(); ++j) g(o + 1 + 2 * j) = p.jenkin[j].c / stiffness;
    ParameterEstimate e;
    e.name = variables.type_prefix(t) + "ei_plus_c";
    e.unit = "N m^2";
    e.value = stiffness;
    e.resolution_at_1_percent = s.resolution_of(g);
    e.standard_error = stiffness * s.standard_error_of(g);
    e.sensitivity = std::numeric_limits<double>::quiet_NaN();
    e.determined = e.resolution_at_1_percent <= kUndeterminedResolution;
    out.push_back(e);
  }
  return out;
}

/// One sentence per null-space direction and per poorly resolved parameter, and
/// one where the fitted model never slips.
std::vector<std::string> determination_notes(const std::vector<ParameterEstimate>& parameters,
                                             const least_squares::Statistics& s,
                                             const std::vector<ParameterEstimate>& stick,
                                             const std::vector<damper::ImpedancePoint>& fitted) {
  std::vector<std::string> notes;
  for (Eigen::Index k = 0; k < s.null_space.cols(); ++k) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      if (std::abs(s.null_space(static_cast<Eigen::Index>(i), k)) > 0.1) names.push_back(parameters[i].name);
    }
    notes.push_back(names.size() == 1 ? fmt::format("Z does not change with {}: the data do not determine it", names[0])
                                      : fmt::format("Z changes only with a combination of {}: the data do not "
                                                    "determine them apart",
                                                    fmt::join(names, ", ")));
  }
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const ParameterEstimate& p = parameters[i];
    if (p.determined || s.in_null_space[i]) continue;
    const int partner = tied_partner(parameters, s, i);
    if (p.resolution_at_1_percent <= kUndeterminedResolution && partner >= 0) {
      notes.push_back(fmt::format("{} is not determined apart from {}: their estimates are correlated at {:.6f}", p.name,
                                  parameters[static_cast<std::size_t>(partner)].name,
                                  s.correlation(static_cast<Eigen::Index>(i), partner)));
      continue;
    }
    notes.push_back(fmt::format("{} is not determined: a 1 % scatter of Z moves it by {:.3g} %", p.name,
                                100.0 * p.resolution_at_1_percent));
  }
  const bool slips = std::any_of(fitted.begin(), fitted.end(),
                                 [](const damper::ImpedancePoint& p) { return p.converged() && p.dissipated_power > 0.0; });
  if (!slips) {
    std::string stiffness;
    for (const ParameterEstimate& e : stick) stiffness += fmt::format(", {} = {:.6g} N m^2", e.name, e.value);
    notes.push_back(fmt::format("the fitted cable never slips at the measured points: they determine only its stick "
                                "stiffness{}; measure at a higher velocity or across the arms' resonances",
                                stiffness));
  }
  return notes;
}

/// The lack-of-fit test of the misfit S at the optimum against the stated `scatter`
/// of Z (m real residuals; the statistics' rank the parameters determined).
LackOfFit lack_of_fit(const least_squares::Statistics& s, double sum_of_squares, double rms, double scatter, bool assumed,
                      int residuals) {
  const double component = scatter / std::sqrt(2.0);
  const least_squares::ChiSquareTest test =
      least_squares::chi_square_test(sum_of_squares / (component * component), residuals - s.rank, lack_of_fit_level);
  LackOfFit out;
  out.scatter = scatter;
  out.assumed = assumed;
  out.ratio = rms / scatter;
  out.statistic = test.statistic;
  out.degrees_of_freedom = test.degrees_of_freedom;
  out.p_value = test.p_value;
  out.critical = test.critical;
  out.level = test.level;
  out.significant = test.significant;
  out.error_inflation = s.error_scatter / component;
  return out;
}

/// The change of parameter i's value (in its unit) for a change dx of its variable at x.
double value_change(const FitVariables& variables, const Eigen::VectorXd& x, int i, double dx) {
  if (variables.fits_clamp_mass() && i == variables.clamp_mass_index()) return variables.mass_scale() * dx;
  if (const DamperNumber* n = variables.number(i)) return n->value(x(i) + dx) - n->value(x(i));
  Eigen::VectorXd moved = x;
  moved(i) += dx;
  return variables.cable_value(moved, i) - variables.cable_value(x, i);
}

/// Marks each parameter (confounded_by, confounded_shift) that a suspect explaining
/// at least explaining_share of the misfit, moved to its suggested value, would move
/// by more than its standard error (the suspect moving it most, in standard errors),
/// and says so: one note per such suspect.
std::vector<std::string> confounding_notes(const FitVariables& variables, const Eigen::VectorXd& x,
                                           const least_squares::Statistics& s,
                                           const std::vector<FixedNumberSuspect>& suspects,
                                           const std::vector<least_squares::ExtraVariable>& steps,
                                           std::vector<ParameterEstimate>& parameters) {
  std::vector<double> worst(parameters.size(), 1.0);  // |shift| in standard errors
  for (std::size_t k = 0; k < suspects.size(); ++k) {
    if (suspects[k].misfit_reduction < explaining_share) break;  // ranked: the rest explain less
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      const double se = s.standard_error(static_cast<Eigen::Index>(i));
      const double shift = steps[k].shift(static_cast<Eigen::Index>(i));
      if (!std::isfinite(se) || !(std::abs(shift) > worst[i] * se)) continue;
      worst[i] = std::abs(shift) / se;
      parameters[i].confounded_by = suspects[k].name;
      parameters[i].confounded_shift = value_change(variables, x, static_cast<int>(i), shift);
    }
  }
  std::vector<std::string> notes;
  for (const FixedNumberSuspect& suspect : suspects) {
    std::vector<std::string> moved;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      const ParameterEstimate& p = parameters[i];
      if (p.confounded_by != suspect.name) continue;
      moved.push_back(fmt::format("{} by {:+.3g} {} ({:.2g} standard errors)", p.name, p.confounded_shift, p.unit, worst[i]));
    }
    if (moved.empty()) continue;
    notes.push_back(fmt::format("were {} {:.4g} {} instead of {:.4g}, as the lack of fit suggests, {} would move beyond "
                                "{} standard error{}: {} (free it, or check it on the drawing)",
                                suspect.name, suspect.suggested_value, suspect.unit, suspect.value,
                                moved.size() == 1 ? "this estimate" : "these estimates", moved.size() == 1 ? "its" : "their",
                                moved.size() == 1 ? "" : "s", fmt::join(moved, ", ")));
  }
  return notes;
}

}  // namespace stockbridge::identification::impedance_fit
