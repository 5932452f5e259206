#include "stockbridge/identification/local_identification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlopt.hpp>

#include "record_features.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::identification {

Optimizer parse_optimizer(std::string_view name) {
  if (name == "subplex") return Optimizer::subplex;
  if (name == "nelder-mead") return Optimizer::nelder_mead;
  throw InvalidParameter(fmt::format("optimizer = '{}': expected subplex or nelder-mead", name));
}

void LocalIdentificationOptions::validate() const {
  require_in_range("elements", elements, 1, 6);
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

/// Sum of |r| |d kappa| (trapezoid) from `from` on; r_k = model + offset - measured.
struct L1Sums {
  double error = 0.0;
  double reference = 0.0;
};

L1Sums l1_sums(const section::MasingParameters& p, double offset, const MomentCurvatureRecord& record,
               std::size_t from, std::size_t to) {
  section::SectionState state = section::SectionState::virgin(p), next = state;
  L1Sums sums;
  double previous_residual = 0.0;
  for (std::size_t k = 0; k < to; ++k) {
    section::curvature_update(p, state, record.curvature[k], next);
    std::swap(state, next);
    const double residual = state.moment + offset - record.moment[k];
    if (k > from) {
      const double dk = std::abs(record.curvature[k] - record.curvature[k - 1]);
      sums.error += 0.5 * (std::abs(residual) + std::abs(previous_residual)) * dk;
      sums.reference += 0.5 * (std::abs(record.moment[k]) + std::abs(record.moment[k - 1])) * dk;
    }
    previous_residual = residual;
  }
  return sums;
}

void check(const MomentCurvatureRecord& record, const std::vector<std::size_t>& turns) {
  if (record.curvature.size() != record.moment.size()) {
    throw InvalidParameter(fmt::format("record: {} curvatures but {} moments", record.curvature.size(),
                                       record.moment.size()));
  }
  if (turns.size() < 3) {
    throw InvalidParameter(fmt::format("record: {} reversals of the curvature: expected at least one full cycle after "
                                       "the first extreme (3 reversals)",
                                       turns.size()));
  }
}

struct Problem {
  const MomentCurvatureRecord& record;
  std::size_t from;
  int elements;
  double moment_scale;
  int evaluations = 0;

  section::MasingParameters parameters(const std::vector<double>& x) const {
    section::MasingParameters p{std::exp(x[0]), {}};
    for (int j = 0; j < elements; ++j) p.jenkin.push_back({std::exp(x[1 + 2 * j]), std::exp(x[2 + 2 * j])});
    return p;
  }
  double offset(const std::vector<double>& x) const { return x.back() * moment_scale; }
  double objective(const std::vector<double>& x) {
    ++evaluations;
    for (const double v : x) {
      if (!std::isfinite(v) || std::abs(v) > 60.0) return 1e300;
    }
    const L1Sums s = l1_sums(parameters(x), offset(x), record, from, record.curvature.size());
    return s.error / s.reference;
  }
};

double nlopt_objective(const std::vector<double>& x, std::vector<double>& /*gradient*/, void* data) {
  return static_cast<Problem*>(data)->objective(x);
}

}  // namespace

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
  const std::vector<std::size_t> turns = reversals(record.curvature);
  check(record, turns);
  const L1Sums s = l1_sums(parameters, moment_offset, record, turns.front(), record.curvature.size());
  return s.error / s.reference;
}

LocalIdentification identify_local(const MomentCurvatureRecord& record, const LocalIdentificationOptions& options) {
  options.validate();
  const std::vector<std::size_t> turns = reversals(record.curvature);
  check(record, turns);
  const auto [lo, hi] = std::minmax_element(record.curvature.begin(), record.curvature.end());
  const double middle = 0.5 * (*hi + *lo);

  // Starting values from the record.
  const LoopSlopes slopes = loop_slopes(record.curvature, record.moment, turns);
  const double k_max = slopes.after;
  double ei = slopes.before;
  if (!(ei > 0.0) || !(k_max > ei)) ei = std::isfinite(k_max) && k_max > 0.0 ? 0.2 * k_max : 1.0;
  const double c_total = std::max(k_max - ei, 0.2 * ei);
  double upper = 0.0, lower = 0.0;
  int n_upper = 0, n_lower = 0;
  for (const std::size_t r : turns) {
    const double h = record.moment[r] - ei * record.curvature[r];
    if (record.curvature[r] > middle) {
      upper += h;
      ++n_upper;
    } else {
      lower += h;
      ++n_lower;
    }
  }
  upper /= std::max(n_upper, 1);
  lower /= std::max(n_lower, 1);
  const double h_total = std::max(0.5 * (upper - lower), 1e-6 * std::abs(k_max * (*hi - *lo)) + 1e-300);
  const double offset = 0.5 * (upper + lower);

  Problem problem{record, turns.front(), options.elements, h_total};
  const int n = 2 + 2 * options.elements;
  auto start = [&](double c_factor, double h_factor) {
    std::vector<double> x(n);
    x[0] = std::log(ei);
    double weight_sum = 0.0;
    for (int j = 0; j < options.elements; ++j) weight_sum += j + 1;
    for (int j = 0; j < options.elements; ++j) {
      x[1 + 2 * j] = std::log(c_factor * c_total / options.elements);
      x[2 + 2 * j] = std::log(h_factor * h_total * (j + 1) / weight_sum);
    }
    x[n - 1] = offset / h_total;
    return x;
  };
  LocalIdentification best;
  best.error = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  const nlopt::algorithm algorithm = options.optimizer == Optimizer::subplex ? nlopt::LN_SBPLX : nlopt::LN_NELDERMEAD;
  auto run = [&](std::vector<double> x) {
    nlopt::opt opt(algorithm, static_cast<unsigned>(n));
    opt.set_min_objective(nlopt_objective, &problem);
    opt.set_xtol_rel(options.tolerance);
    opt.set_ftol_abs(0.0);
    opt.set_maxeval(options.max_evaluations);
    opt.set_initial_step(0.2);
    double value = problem.objective(x);
    try {
      opt.optimize(x, value);
    } catch (const std::exception&) {
      value = problem.objective(x);  // NLopt stops on round-off: x is still its best point
    }
    ++best.starts;
    if (value < best.error) {
      best.error = value;
      best_x = x;
    }
  };
  for (const auto& [c_factor, h_factor] :
       {std::pair{1.0, 1.0}, std::pair{0.5, 1.0}, std::pair{2.0, 1.0}, std::pair{1.0, 0.7}, std::pair{1.0, 1.4}}) {
    run(start(c_factor, h_factor));
  }
  run(best_x);  // a restart from the best point escapes a collapsed simplex
  best.parameters = problem.parameters(best_x);
  std::sort(best.parameters.jenkin.begin(), best.parameters.jenkin.end(),
            [](const section::Jenkin& a, const section::Jenkin& b) { return a.h / a.c < b.h / b.c; });
  best.moment_offset = problem.offset(best_x);
  best.evaluations = problem.evaluations;
  for (std::size_t i = 0; i < turns.size(); i += 2) {  // cycles from every second reversal
    const std::size_t to = i + 2 < turns.size() ? turns[i + 2] + 1 : record.curvature.size();
    const L1Sums all = l1_sums(best.parameters, best.moment_offset, record, turns[i], to);
    best.cycle_errors.push_back(all.reference > 0.0 ? all.error / all.reference : 0.0);
  }
  return best;
}

}  // namespace stockbridge::identification
