#include "stockbridge/identification/global_identification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "fit_core.hpp"
#include "record_features.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::identification {

void GlobalIdentificationOptions::validate() const {
  require_positive("length", length, "m");
  require_in_range("sections", sections, cable::min_sections, cable::max_sections);
  require_in_range("elements", elements, 1, 6);
  if (!law->jenkin_elements() && elements != 1) {
    throw InvalidParameter("elements", fmt::format(" = {}: Jenkin elements belong to the Masing law; the {} law "
                                                   "fits {}",
                                                   elements, law->title(), law->takes()));
  }
  require_in_range("max_evaluations", max_evaluations, 10, 100000000);
  require_positive("tolerance", tolerance, "");
}

namespace {

const fit_core::RecordNames experiment_record_names{"prescribed values", "measured", "the prescribed motion"};

std::vector<std::size_t> checked_reversals(const ExperimentMeasurement& m) {
  return fit_core::checked_reversals(m.prescribed, m.measured, experiment_record_names);
}

cable::CableDescription constant_cable(double length, int sections, const section::MasingParameters& p) {
  std::vector<std::pair<double, double>> c_h;
  for (const section::Jenkin& e : p.jenkin) c_h.emplace_back(e.c, e.h);
  return cable::CableDescription::uniform(length, sections, p.ei, c_h);
}

/// The four-step result and variations of it (noise can throw the four steps' local
/// slopes off by tens of percent), its element spread over the elements, no offset.
std::vector<std::vector<double>> starts(const cable::CableDescription& four_step, int elements,
                                        const fit_core::LogParameters& packing) {
  const double ei = four_step.ei.at(0.0), c = four_step.jenkin[0].c.at(0.0), h = four_step.jenkin[0].h.at(0.0);
  std::vector<std::vector<double>> x;
  for (const auto& [ei_factor, h_factor] : {std::pair{1.0, 1.0}, std::pair{1.4, 0.6}, std::pair{0.7, 1.5},
                                            std::pair{1.0, 0.6}, std::pair{1.4, 1.0}}) {
    x.push_back(packing.pack(fit_core::spread_over_elements(ei * ei_factor, c, h * h_factor, elements), 0.0));
  }
  return x;
}

}  // namespace

std::vector<double> model_output(const cable::CableDescription& description, double output_offset,
                                 const ExperimentMeasurement& m) {
  cable::Cantilever cantilever{cable::Cable(description)};
  std::vector<double> output;
  output.reserve(m.prescribed.size());
  for (const cable::ExperimentSample& s : cable::run_path(cantilever, m.experiment, m.prescribed)) {
    const double value = m.experiment == cable::Experiment::a ? s.tip_force : s.clamp_moment;
    output.push_back(s.solve.converged() ? value + output_offset : std::numeric_limits<double>::quiet_NaN());
  }
  return output;
}

double relative_l1_error(const cable::CableDescription& cable, double output_offset,
                         const ExperimentMeasurement& measurement) {
  const std::size_t from = checked_reversals(measurement).front();
  return fit_core::relative_l1_misfit(measurement.prescribed, measurement.measured,
                                      model_output(cable, output_offset, measurement), from);
}

GlobalIdentification identify_four_step(const ExperimentMeasurement& m, const GlobalIdentificationOptions& options) {
  options.validate();
  const std::vector<std::size_t> turns = checked_reversals(m);
  const double l = options.length;
  const bool a = m.experiment == cable::Experiment::a;
  // (a): F = 3 EI x / l^3, so EI = l^3/3 dF/dx; (b): T = -2 EI phi / l, so EI = l/2 (-dT/dphi).
  const double factor = a ? l * l * l / 3.0 : -l / 2.0;
  const LoopSlopes slopes = loop_slopes(m.prescribed, m.measured, turns);
  const double stick = factor * slopes.after;    // step 1: ei + c
  double ei = factor * slopes.before;            // step 2: ei
  if (!(ei > 0.0) || !(stick > ei)) {
    throw InvalidParameter("record", fmt::format(": slopes after and before the reversals give ei + c = {} and ei = {}: "
                                       "expected 0 < ei < ei + c (a loop that slips)",
                                       format_value(stick), format_value(ei)));
  }
  // Step 3: the offset from the all-slip line at the extremes, half the difference
  // between the maxima and the minima of the prescribed motion.
  const ExtremeMeans offsets = extreme_means(m.prescribed, turns, [&](std::size_t r) {
    const double u = m.prescribed[r];
    return a ? 2.0 * l / 3.0 * (m.measured[r] - 3.0 * ei * u / (l * l * l)) : -m.measured[r] - 2.0 * ei * u / l;
  });
  const double h = 0.5 * (offsets.upper - offsets.lower);
  if (!(h > 0.0)) {
    throw InvalidParameter("record", fmt::format(": the loop's offset at the extremes gives h = {}: expected > 0",
                                       format_value(h)));
  }
  GlobalIdentification result;
  result.cable = constant_cable(options.length, options.sections, {ei, {{stick - ei, h}}});  // step 4: c = (ei + c) - ei
  result.error = relative_l1_error(result.cable, 0.0, m);
  return result;
}

namespace {

/// A law of numbers, from its starts (SectionLawDescriptor::starts) made of the four-step Masing cable.
GlobalIdentification identify_fit_numbers(const ExperimentMeasurement& m, const GlobalIdentificationOptions& options,
                                          const GlobalIdentification& four_step, double output_scale) {
  const cable::SectionLawDescriptor& law = *options.law;
  const std::size_t from = checked_reversals(m).front();
  const fit_core::LawLogParameters packing{&law, output_scale};
  auto cable_of = [&](const std::vector<double>& x, int sections) {
    return cable::CableDescription::uniform(law, options.length, sections, packing.parameters(x));
  };
  auto objective_on = [&](int sections) {
    return [&, sections](const std::vector<double>& x) {
      return fit_core::relative_l1_misfit(m.prescribed, m.measured, model_output(cable_of(x, sections), packing.offset(x), m),
                                          from);
    };
  };
  const cable::CableDescription& c = four_step.cable;
  std::vector<std::vector<double>> starts;
  for (const std::vector<double>& values :
       law.starts({c.ei.at(0.0), c.jenkin[0].c.at(0.0), c.jenkin[0].h.at(0.0)}, cable::FitKind::global)) {
    starts.push_back(packing.pack(values, 0.0));
  }
  // As for the Masing law: the starts on a coarse cable, the best polished on the full one.
  fit_core::Search coarse(objective_on(std::min(options.sections, 12)));
  fit_core::Search fine(objective_on(options.sections));
  fit_core::SearchSettings settings{options.optimizer, options.tolerance, options.max_evaluations / 4, 0.1};
  const fit_core::Minimum explored = coarse.from_each(starts, settings);
  settings.max_evaluations = options.max_evaluations;
  const fit_core::Minimum best = fine.restarted({explored.x}, 2, settings);
  GlobalIdentification result;
  result.cable = cable_of(best.x, options.sections);
  result.output_offset = packing.offset(best.x);
  result.error = best.value;
  result.evaluations = coarse.evaluations() + fine.evaluations();
  result.termination = best.termination;
  return result;
}

}  // namespace

GlobalIdentification identify_fit(const ExperimentMeasurement& m, const GlobalIdentificationOptions& options) {
  const GlobalIdentification four_step = identify_four_step(m, options);
  const std::size_t from = checked_reversals(m).front();
  const double output_scale = std::abs(*std::max_element(
      m.measured.begin(), m.measured.end(), [](double x, double y) { return std::abs(x) < std::abs(y); }));
  if (!options.law->jenkin_elements()) return identify_fit_numbers(m, options, four_step, output_scale);
  const fit_core::LogParameters packing(options.elements, output_scale);
  auto objective_on = [&](int sections) {
    return [&, sections](const std::vector<double>& x) {
      const cable::CableDescription cable = constant_cable(options.length, sections, packing.parameters(x));
      return fit_core::relative_l1_misfit(m.prescribed, m.measured, model_output(cable, packing.offset(x), m), from);
    };
  };
  // The starts are explored on a coarse cable (12 sections: 0.5 % off, a third of the
  // cost), the best is then polished on the full one, twice.
  fit_core::Search coarse(objective_on(std::min(options.sections, 12)));
  fit_core::Search fine(objective_on(options.sections));
  fit_core::SearchSettings settings{options.optimizer, options.tolerance, options.max_evaluations / 4, 0.1};
  const fit_core::Minimum explored = coarse.from_each(starts(four_step.cable, options.elements, packing), settings);
  settings.max_evaluations = options.max_evaluations;
  const fit_core::Minimum best = fine.restarted({explored.x}, 2, settings);
  GlobalIdentification result;
  result.cable =
      constant_cable(options.length, options.sections, fit_core::sorted_by_slip_curvature(packing.parameters(best.x)));
  result.output_offset = packing.offset(best.x);
  result.error = best.value;
  result.evaluations = coarse.evaluations() + fine.evaluations();
  result.termination = best.termination;
  return result;
}

}  // namespace stockbridge::identification
