#include "fit_core.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

#include <fmt/format.h>
#include <nlopt.hpp>

#include "../numerics/nlopt_termination.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::identification::fit_core {

L1Sums l1_sums(const std::vector<double>& path, const std::vector<double>& measured,
               const std::vector<double>& model, std::size_t from, std::size_t to) {
  L1Sums sums;
  for (std::size_t k = from + 1; k < to; ++k) {
    const double dp = std::abs(path[k] - path[k - 1]);
    sums.error += 0.5 * (std::abs(model[k] - measured[k]) + std::abs(model[k - 1] - measured[k - 1])) * dp;
    sums.reference += 0.5 * (std::abs(measured[k]) + std::abs(measured[k - 1])) * dp;
  }
  return sums;
}

double relative_l1_misfit(const std::vector<double>& path, const std::vector<double>& measured,
                          const std::vector<double>& model, std::size_t from) {
  if (std::any_of(model.begin(), model.end(), [](double y) { return std::isnan(y); })) {
    return std::numeric_limits<double>::infinity();
  }
  return l1_sums(path, measured, model, from, path.size()).relative();
}

std::vector<std::size_t> checked_reversals(const std::vector<double>& path, const std::vector<double>& measured,
                                           const RecordNames& names) {
  if (path.size() != measured.size()) {
    throw InvalidParameter("record", fmt::format(": {} {} but {} {}", path.size(), names.path_values, measured.size(),
                                       names.measured_values));
  }
  std::vector<std::size_t> turns = reversals(path);
  if (turns.size() < 3) {
    throw InvalidParameter("record", fmt::format(": {} reversals of {}: expected at least one full cycle after the "
                                       "first extreme (3 reversals)",
                                       turns.size(), names.path));
  }
  return turns;
}

section::MasingParameters spread_over_elements(double ei, double c_total, double h_total, int elements) {
  const double weight_sum = elements * (elements + 1) / 2.0;
  section::MasingParameters p{ei, {}};
  for (int j = 0; j < elements; ++j) p.jenkin.push_back({c_total / elements, h_total * (j + 1) / weight_sum});
  return p;
}

section::MasingParameters sorted_by_slip_curvature(section::MasingParameters parameters) {
  std::sort(parameters.jenkin.begin(), parameters.jenkin.end(),
            [](const section::Jenkin& a, const section::Jenkin& b) { return a.h / a.c < b.h / b.c; });
  return parameters;
}

LogParameters::LogParameters(int elements, double offset_scale) : elements_(elements), offset_scale_(offset_scale) {}

std::vector<double> LogParameters::pack(const section::MasingParameters& parameters, double offset) const {
  std::vector<double> x{std::log(parameters.ei)};
  for (const section::Jenkin& e : parameters.jenkin) {
    x.push_back(std::log(e.c));
    x.push_back(std::log(e.h));
  }
  x.push_back(offset / offset_scale_);
  return x;
}

section::MasingParameters LogParameters::parameters(const std::vector<double>& x) const {
  section::MasingParameters p{std::exp(x[0]), {}};
  for (int j = 0; j < elements_; ++j) p.jenkin.push_back({std::exp(x[1 + 2 * j]), std::exp(x[2 + 2 * j])});
  return p;
}

double LogParameters::offset(const std::vector<double>& x) const { return x.back() * offset_scale_; }

namespace {

nlopt::algorithm algorithm(Optimizer optimizer) {
  return optimizer == Optimizer::subplex ? nlopt::LN_SBPLX : nlopt::LN_NELDERMEAD;
}

/// What NLopt's callback needs: the search, and its run's optimiser to stop it.
struct RunContext {
  Search& search;
  nlopt::opt& opt;
  std::exception_ptr failure;  ///< the objective's exception, rethrown after the run
};

/// NLopt turns an exception from the objective into one of its own (a library
/// error into std::runtime_error("nlopt failure")); this keeps the original instead
/// and stops the run, except for nlopt::forced_stop, NLopt's request to stop.
double nlopt_objective(const std::vector<double>& x, std::vector<double>& /*gradient*/, void* data) {
  RunContext& context = *static_cast<RunContext*>(data);
  try {
    return context.search.evaluate(x);
  } catch (const nlopt::forced_stop&) {
    throw;
  } catch (...) {
    context.failure = std::current_exception();
    context.opt.force_stop();
    return HUGE_VAL;
  }
}

/// The candidate where it is lower than the incumbent, else the incumbent.
Minimum better(Minimum incumbent, Minimum candidate) {
  return candidate.value < incumbent.value ? std::move(candidate) : std::move(incumbent);
}

}  // namespace

Search::Search(Objective objective) : objective_(std::move(objective)) {}

double Search::evaluate(const std::vector<double>& x) {
  ++evaluations_;
  const bool inside = std::all_of(x.begin(), x.end(), [](double v) { return std::abs(v) <= variable_limit; });
  if (!inside) return penalty;  // also for NaN
  const double value = objective_(x);
  return std::isfinite(value) ? value : penalty;
}

Minimum Search::run(std::vector<double> x, const SearchSettings& settings) {
  nlopt::opt opt(algorithm(settings.optimizer), static_cast<unsigned>(x.size()));
  RunContext context{*this, opt, nullptr};
  opt.set_min_objective(nlopt_objective, &context);
  opt.set_xtol_rel(settings.tolerance);
  opt.set_maxeval(settings.max_evaluations);
  opt.set_initial_step(settings.initial_step);
  double value = evaluate(x);  // the start's value, should NLopt stop before improving on it
  Termination termination = Termination::inner_failure;
  try {
    termination = numerics::nlopt_termination(opt.optimize(x, value));
  } catch (const nlopt::roundoff_limited&) {
    value = evaluate(x);  // x is the run's best point
    termination = Termination::no_progress;
  } catch (const nlopt::forced_stop&) {
    if (context.failure) std::rethrow_exception(context.failure);
    value = evaluate(x);  // the objective asked to stop: x is the best point so far
  }
  ++runs_;
  return {std::move(x), value, termination};
}

Minimum Search::from_each(const std::vector<std::vector<double>>& starts, const SearchSettings& settings) {
  Minimum best;
  for (const std::vector<double>& start : starts) {
    Minimum candidate = run(start, settings);
    best = better(std::move(best), std::move(candidate));
  }
  return best;
}

Minimum Search::restarted(Minimum best, int times, const SearchSettings& settings) {
  for (int i = 0; i < times; ++i) {
    Minimum candidate = run(best.x, settings);
    best = better(std::move(best), std::move(candidate));
  }
  return best;
}

}  // namespace stockbridge::identification::fit_core
