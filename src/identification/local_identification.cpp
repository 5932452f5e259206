#include "stockbridge/identification/local_identification.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "fit_core.hpp"
#include "record_features.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::identification {

Optimizer parse_optimizer(std::string_view name) {
  if (name == "subplex") return Optimizer::subplex;
  if (name == "nelder-mead") return Optimizer::nelder_mead;
  throw InvalidParameter("optimizer", fmt::format(" = '{}': expected subplex or nelder-mead", name));
}

void LocalIdentificationOptions::validate() const {
  require_in_range("elements", elements, 1, 6);
  if (!law->jenkin_elements() && elements != 1) {
    throw InvalidParameter("elements", fmt::format(" = {}: Jenkin elements belong to the Masing law; the {} law "
                                                   "fits {}",
                                                   elements, law->title(), law->takes()));
  }
  require_in_range("max_evaluations", max_evaluations, 10, 100000000);
  require_positive("tolerance", tolerance, "");
}

std::vector<std::size_t> reversals(const std::vector<double>& curvature) {
  // A reversal counts once the curvature has come back from its running extreme by
  // 5 % of its range, so that noise does not make reversals of its own.
  std::vector<std::size_t> found;
  if (curvature.size() < 3) return found;
  const auto [lo, hi] = std::minmax_element(curvature.begin(), curvature.end());
  const double threshold = 0.05 * (*hi - *lo);
  if (!(threshold > 0.0)) return found;
  std::size_t extreme = 0;
  int direction = 0;  // +1 rising, -1 falling, 0 not yet known
  for (std::size_t k = 1; k < curvature.size(); ++k) {
    const double kappa = curvature[k];
    if (direction == 0) {
      if (std::abs(kappa - curvature[0]) >= threshold) direction = kappa > curvature[0] ? 1 : -1;
      if (direction != 0) extreme = k;
      continue;
    }
    if (direction * (kappa - curvature[extreme]) > 0.0) {
      extreme = k;
    } else if (direction * (curvature[extreme] - kappa) >= threshold) {
      found.push_back(extreme);
      direction = -direction;
      extreme = k;
    }
  }
  return found;
}

namespace {

const fit_core::RecordNames moment_curvature_names{"curvatures", "moments", "the curvature"};

/// Starting values from the record: ei from the slope before the reversals (all
/// slip), sum c from the slope after them (all stick) less ei, sum h and the moment
/// offset from the all-slip line's offsets at the upper and lower extremes.
struct RecordEstimates {
  double ei = 0.0;
  double c_total = 0.0;
  double h_total = 0.0;
  double offset = 0.0;
};

RecordEstimates record_estimates(const MomentCurvatureRecord& record, const std::vector<std::size_t>& turns) {
  const LoopSlopes slopes = loop_slopes(record.curvature, record.moment, turns);
  const double k_max = slopes.after;
  double ei = slopes.before;
  if (!(ei > 0.0) || !(k_max > ei)) ei = std::isfinite(k_max) && k_max > 0.0 ? 0.2 * k_max : 1.0;
  const ExtremeMeans h = extreme_means(record.curvature, turns,
                                       [&](std::size_t r) { return record.moment[r] - ei * record.curvature[r]; });
  const auto [lo, hi] = std::minmax_element(record.curvature.begin(), record.curvature.end());
  RecordEstimates estimates;
  estimates.ei = ei;
  estimates.c_total = std::max(k_max - ei, 0.2 * ei);
  estimates.h_total = std::max(0.5 * (h.upper - h.lower), 1e-6 * std::abs(k_max * (*hi - *lo)) + 1e-300);
  estimates.offset = 0.5 * (h.upper + h.lower);
  return estimates;
}

/// Every start's ei and offset are the estimates'; sum c and sum h are scaled.
std::vector<std::vector<double>> starts(const RecordEstimates& e, int elements, const fit_core::LogParameters& packing) {
  std::vector<std::vector<double>> x;
  for (const auto& [c_factor, h_factor] :
       {std::pair{1.0, 1.0}, std::pair{0.5, 1.0}, std::pair{2.0, 1.0}, std::pair{1.0, 0.7}, std::pair{1.0, 1.4}}) {
    x.push_back(packing.pack(fit_core::spread_over_elements(e.ei, c_factor * e.c_total, h_factor * e.h_total, elements),
                             e.offset));
  }
  return x;
}

/// The relative error of each cycle, between every second reversal (the last to the end).
std::vector<double> cycle_errors(const MomentCurvatureRecord& record, const std::vector<double>& model,
                                 const std::vector<std::size_t>& turns) {
  std::vector<double> errors;
  for (std::size_t i = 0; i < turns.size(); i += 2) {
    const std::size_t to = i + 2 < turns.size() ? turns[i + 2] + 1 : record.curvature.size();
    const fit_core::L1Sums sums = fit_core::l1_sums(record.curvature, record.moment, model, turns[i], to);
    errors.push_back(sums.reference > 0.0 ? sums.relative() : 0.0);
  }
  return errors;
}

}  // namespace

std::vector<double> model_moments(const cable::LawValues& numbers, double moment_offset,
                                  const MomentCurvatureRecord& record) {
  std::vector<double> moments = numbers.law->moments(numbers.values, record.curvature);
  for (double& m : moments) m = m + moment_offset;
  return moments;
}

std::vector<double> model_moments(const LocalIdentification& fit, const MomentCurvatureRecord& record) {
  return fit.numbers ? model_moments(*fit.numbers, fit.moment_offset, record)
                      : model_moments(fit.parameters, fit.moment_offset, record);
}

std::vector<double> model_moments(const section::MasingParameters& parameters, double moment_offset,
                                  const MomentCurvatureRecord& record) {
  section::SectionState state = section::SectionState::virgin(parameters), next = state;
  std::vector<double> moments;
  moments.reserve(record.curvature.size());
  for (const double kappa : record.curvature) {
    section::curvature_update(parameters, state, kappa, next);
    std::swap(state, next);
    moments.push_back(state.moment + moment_offset);
  }
  return moments;
}

double relative_l1_error(const section::MasingParameters& parameters, double moment_offset,
                         const MomentCurvatureRecord& record) {
  const std::vector<std::size_t> turns = fit_core::checked_reversals(record.curvature, record.moment, moment_curvature_names);
  return fit_core::relative_l1_misfit(record.curvature, record.moment, model_moments(parameters, moment_offset, record),
                                      turns.front());
}

namespace {

/// A law of numbers, from its starts (SectionLawDescriptor::starts) made of the record's estimates.
LocalIdentification identify_local_numbers(const MomentCurvatureRecord& record, const LocalIdentificationOptions& options,
                                           const std::vector<std::size_t>& turns, const RecordEstimates& estimates) {
  const cable::SectionLawDescriptor& law = *options.law;
  const fit_core::LawLogParameters packing{&law, estimates.h_total};
  fit_core::Search search([&](const std::vector<double>& x) {
    const std::vector<double> model = model_moments(cable::LawValues{&law, packing.parameters(x)}, packing.offset(x), record);
    return fit_core::relative_l1_misfit(record.curvature, record.moment, model, turns.front());
  });
  std::vector<std::vector<double>> starts;
  for (const std::vector<double>& values :
       law.starts({estimates.ei, estimates.c_total, estimates.h_total}, cable::FitKind::local)) {
    starts.push_back(packing.pack(values, estimates.offset));
  }
  const fit_core::SearchSettings settings{options.optimizer, options.tolerance, options.max_evaluations, 0.2};
  const fit_core::Minimum best = search.restarted(search.from_each(starts, settings), 1, settings);
  LocalIdentification fit;
  fit.numbers = cable::LawValues{&law, packing.parameters(best.x)};
  fit.moment_offset = packing.offset(best.x);
  fit.error = best.value;
  fit.cycle_errors = cycle_errors(record, model_moments(fit, record), turns);
  fit.evaluations = search.evaluations();
  fit.starts = search.runs();
  fit.termination = best.termination;
  return fit;
}

}  // namespace

LocalIdentification identify_local(const MomentCurvatureRecord& record, const LocalIdentificationOptions& options) {
  options.validate();
  const std::vector<std::size_t> turns = fit_core::checked_reversals(record.curvature, record.moment, moment_curvature_names);
  const RecordEstimates estimates = record_estimates(record, turns);
  if (!options.law->jenkin_elements()) return identify_local_numbers(record, options, turns, estimates);
  const fit_core::LogParameters packing(options.elements, estimates.h_total);
  fit_core::Search search([&](const std::vector<double>& x) {
    const std::vector<double> model = model_moments(packing.parameters(x), packing.offset(x), record);
    return fit_core::relative_l1_misfit(record.curvature, record.moment, model, turns.front());
  });
  const fit_core::SearchSettings settings{options.optimizer, options.tolerance, options.max_evaluations, 0.2};
  const fit_core::Minimum best =
      search.restarted(search.from_each(starts(estimates, options.elements, packing), settings), 1, settings);
  LocalIdentification fit;
  fit.parameters = fit_core::sorted_by_slip_curvature(packing.parameters(best.x));
  fit.moment_offset = packing.offset(best.x);
  fit.error = best.value;
  fit.cycle_errors = cycle_errors(record, model_moments(fit.parameters, fit.moment_offset, record), turns);
  fit.evaluations = search.evaluations();
  fit.starts = search.runs();
  fit.termination = best.termination;
  return fit;
}

}  // namespace stockbridge::identification
