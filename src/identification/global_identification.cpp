#include "stockbridge/identification/global_identification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlopt.hpp>

#include "record_features.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::identification {

void GlobalIdentificationOptions::validate() const {
  require_positive("length", length, "m");
  require_in_range("sections", sections, cable::min_sections, cable::max_sections);
  require_in_range("elements", elements, 1, 6);
  require_in_range("max_evaluations", max_evaluations, 10, 100000000);
  require_positive("tolerance", tolerance, "");
}

namespace {

std::vector<std::size_t> checked_reversals(const ExperimentMeasurement& m) {
  if (m.prescribed.size() != m.measured.size()) {
    throw InvalidParameter(fmt::format("record: {} prescribed values but {} measured", m.prescribed.size(), m.measured.size()));
  }
  const std::vector<std::size_t> turns = reversals(m.prescribed);
  if (turns.size() < 3) {
    throw InvalidParameter(fmt::format("record: {} reversals of the prescribed motion: expected at least one full "
                                       "cycle after the first extreme (3 reversals)",
                                       turns.size()));
  }
  return turns;
}

/// The L1 sums of the simulated output against the measured one, from sample `from`.
struct Sums {
  double error = std::numeric_limits<double>::infinity();
  double reference = 1.0;
};

Sums simulate(const cable::CableDescription& description, double offset, const ExperimentMeasurement& m,
              std::size_t from) {
  cable::Cantilever cantilever{cable::Cable(description)};
  const std::vector<cable::ExperimentSample> samples = cable::run_path(cantilever, m.experiment, m.prescribed);
  Sums sums{0.0, 0.0};
  double previous = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (!samples[k].solve.converged()) return {};
    const double output = m.experiment == cable::Experiment::a ? samples[k].tip_force : samples[k].clamp_moment;
    const double residual = output + offset - m.measured[k];
    if (k > from) {
      const double dx = std::abs(m.prescribed[k] - m.prescribed[k - 1]);
      sums.error += 0.5 * (std::abs(residual) + std::abs(previous)) * dx;
      sums.reference += 0.5 * (std::abs(m.measured[k]) + std::abs(m.measured[k - 1])) * dx;
    }
    previous = residual;
  }
  return sums;
}

cable::CableDescription constant_cable(const GlobalIdentificationOptions& options, double ei,
                                       const std::vector<section::Jenkin>& jenkin) {
  std::vector<std::pair<double, double>> c_h;
  for (const section::Jenkin& e : jenkin) c_h.emplace_back(e.c, e.h);
  return cable::CableDescription::uniform(options.length, options.sections, ei, c_h);
}

}  // namespace

std::vector<double> model_output(const cable::CableDescription& description, double output_offset,
                                 const ExperimentMeasurement& m) {
  cable::Cantilever cantilever{cable::Cable(description)};
  std::vector<double> output;
  for (const cable::ExperimentSample& s : cable::run_path(cantilever, m.experiment, m.prescribed)) {
    const double value = m.experiment == cable::Experiment::a ? s.tip_force : s.clamp_moment;
    output.push_back(s.solve.converged() ? value + output_offset : std::numeric_limits<double>::quiet_NaN());
  }
  return output;
}

double relative_l1_error(const cable::CableDescription& cable, double output_offset,
                         const ExperimentMeasurement& measurement) {
  const Sums s = simulate(cable, output_offset, measurement, checked_reversals(measurement).front());
  return s.error / s.reference;
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
    throw InvalidParameter(fmt::format("record: slopes after and before the reversals give ei + c = {} and ei = {}: "
                                       "expected 0 < ei < ei + c (a loop that slips)",
                                       format_value(stick), format_value(ei)));
  }
  // Step 3: the offset from the all-slip line at the extremes, half the difference
  // between the maxima and the minima of the prescribed motion.
  const auto [lo, hi] = std::minmax_element(m.prescribed.begin(), m.prescribed.end());
  const double middle = 0.5 * (*hi + *lo);
  double upper = 0.0, lower = 0.0;
  int n_upper = 0, n_lower = 0;
  for (const std::size_t r : turns) {
    const double u = m.prescribed[r];
    const double h = a ? 2.0 * l / 3.0 * (m.measured[r] - 3.0 * ei * u / (l * l * l))
                       : -m.measured[r] - 2.0 * ei * u / l;
    if (u > middle) {
      upper += h;
      ++n_upper;
    } else {
      lower += h;
      ++n_lower;
    }
  }
  const double h = 0.5 * (upper / std::max(n_upper, 1) - lower / std::max(n_lower, 1));
  if (!(h > 0.0)) {
    throw InvalidParameter(fmt::format("record: the loop's offset at the extremes gives h = {}: expected > 0",
                                       format_value(h)));
  }
  GlobalIdentification result;
  result.cable = constant_cable(options, ei, {{stick - ei, h}});  // step 4: c = (ei + c) - ei
  result.error = relative_l1_error(result.cable, 0.0, m);
  return result;
}

GlobalIdentification identify_fit(const ExperimentMeasurement& m, const GlobalIdentificationOptions& options) {
  const GlobalIdentification start = identify_four_step(m, options);
  const std::vector<std::size_t> turns = checked_reversals(m);
  const int elements = options.elements;
  const int n = 2 + 2 * elements;
  const double ei0 = start.cable.ei.at(0.0), c0 = start.cable.jenkin[0].c.at(0.0), h0 = start.cable.jenkin[0].h.at(0.0);
  const double output_scale = *std::max_element(m.measured.begin(), m.measured.end(),
                                                [](double x, double y) { return std::abs(x) < std::abs(y); });
  struct Problem {
    const ExperimentMeasurement& m;
    GlobalIdentificationOptions options;
    std::size_t from;
    double output_scale;
    int evaluations = 0;
    cable::CableDescription cable(const std::vector<double>& x) const {
      std::vector<section::Jenkin> jenkin;
      for (int j = 0; j < options.elements; ++j) jenkin.push_back({std::exp(x[1 + 2 * j]), std::exp(x[2 + 2 * j])});
      return constant_cable(options, std::exp(x[0]), jenkin);
    }
    double objective(const std::vector<double>& x) {
      ++evaluations;
      for (const double v : x) {
        if (!std::isfinite(v) || std::abs(v) > 60.0) return 1e300;
      }
      const Sums s = simulate(cable(x), x.back() * std::abs(output_scale), m, from);
      return std::isfinite(s.error) ? s.error / s.reference : 1e300;
    }
  } problem{m, options, turns.front(), output_scale};
  // Starts: the four-step result and variations of it (noise can throw the four
  // steps' local slopes off by tens of percent), then a restart from the best.
  auto start_at = [&](double ei_factor, double h_factor) {
    std::vector<double> x(n);
    x[0] = std::log(ei0 * ei_factor);
    for (int j = 0; j < elements; ++j) {  // spread the four-step element over the elements
      x[1 + 2 * j] = std::log(c0 / elements);
      x[2 + 2 * j] = std::log(h0 * h_factor * (j + 1) * 2.0 / (elements * (elements + 1)));
    }
    x[n - 1] = 0.0;
    return x;
  };
  const nlopt::algorithm algorithm = options.optimizer == Optimizer::subplex ? nlopt::LN_SBPLX : nlopt::LN_NELDERMEAD;
  std::vector<double> x;
  double best = std::numeric_limits<double>::infinity();
  auto run = [&](std::vector<double> from, int max_evaluations) {
    nlopt::opt opt(algorithm, static_cast<unsigned>(n));
    opt.set_min_objective(
        [](const std::vector<double>& v, std::vector<double>&, void* data) { return static_cast<Problem*>(data)->objective(v); },
        &problem);
    opt.set_xtol_rel(options.tolerance);
    opt.set_maxeval(max_evaluations);
    opt.set_initial_step(0.1);
    double value = problem.objective(from);
    try {
      opt.optimize(from, value);
    } catch (const std::exception&) {
      value = problem.objective(from);  // stopped on round-off: `from` is its best point
    }
    if (value < best) {
      best = value;
      x = from;
    }
  };
  // The starts are explored on a coarse cable (12 sections: 0.5 % off, a third of the
  // cost), the best is then polished on the full one.
  problem.options.sections = std::min(options.sections, 12);
  for (const auto& [ei_factor, h_factor] : {std::pair{1.0, 1.0}, std::pair{1.4, 0.6}, std::pair{0.7, 1.5},
                                            std::pair{1.0, 0.6}, std::pair{1.4, 1.0}}) {
    run(start_at(ei_factor, h_factor), options.max_evaluations / 4);
  }
  problem.options.sections = options.sections;
  best = std::numeric_limits<double>::infinity();
  run(x, options.max_evaluations);
  run(x, options.max_evaluations);  // a restart escapes a collapsed simplex
  GlobalIdentification result;
  result.cable = problem.cable(x);
  std::sort(result.cable.jenkin.begin(), result.cable.jenkin.end(), [](const auto& p, const auto& q) {
    return p.h.at(0.0) / p.c.at(0.0) < q.h.at(0.0) / q.c.at(0.0);
  });
  result.output_offset = x[n - 1] * std::abs(output_scale);
  result.error = best;
  result.evaluations = problem.evaluations;
  return result;
}

}  // namespace stockbridge::identification
