#include "stockbridge/design/search.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <random>

#include <boost/random/sobol.hpp>
#include <fmt/format.h>
#include <nlopt.hpp>

#include "../numerics/nlopt_termination.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/core/parallel.hpp"

namespace stockbridge::design {

void SearchOptions::validate() const {
  require_in_range("samples", samples, 1, 1000000);
  require_in_range("polish", polish, 0, 10000);
  require_in_range("polish_evaluations", polish_evaluations, 2, 100000);
  require_positive("polish_tolerance", polish_tolerance, "");
}

ThreadRunner::ThreadRunner(int threads) : threads_(threads) { require_in_range("threads", threads, 1, 256); }

std::vector<TaskOutput> ThreadRunner::run(int tasks, const std::function<TaskOutput(int)>& task) {
  std::vector<TaskOutput> results(static_cast<std::size_t>(std::max(tasks, 0)));
  parallel_for(results.size(), threads_, [&](std::size_t t) { results[t] = task(static_cast<int>(t)); });
  return results;
}

std::string_view stage_name(Stage stage) {
  switch (stage) {
    case Stage::base: return "base";
    case Stage::sample: return "sample";
    case Stage::polish: return "polish";
  }
  return "sample";
}

bool better(const Evaluation& a, const Evaluation& b) {
  if (a.feasible() != b.feasible()) return a.feasible();
  if (a.converged() != b.converged()) return a.converged();
  return a.objective < b.objective;
}

std::vector<std::vector<double>> space_filling_sample(const std::vector<DesignVariable>& variables, int count,
                                                      std::uint64_t seed) {
  const std::size_t n = variables.size();
  boost::random::sobol_engine<std::uint32_t, 32> sobol(n);  // 32-bit coordinates
  // A random digital shift (XOR of each coordinate's bits) keeps the sequence's
  // low discrepancy and makes the seed choose among equally good samples.
  std::mt19937_64 random(seed);
  std::vector<std::uint32_t> shift(n);
  for (std::uint32_t& s : shift) s = static_cast<std::uint32_t>(random() >> 32);
  std::vector<std::vector<double>> points(static_cast<std::size_t>(count), std::vector<double>(n));
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<double>& point = points[i];
    for (std::size_t d = 0; d < n; ++d) {
      // The sequence's first point is 0 (the engine starts at the second).
      const std::uint32_t bits = (i == 0 ? 0u : static_cast<std::uint32_t>(sobol())) ^ shift[d];
      const double u = (static_cast<double>(bits) + 0.5) / 4294967296.0;
      point[d] = variables[d].min + u * (variables[d].max - variables[d].min);
    }
  }
  return points;
}

namespace {

/// One local polish from `start`: COBYLA on the variables scaled to [0, 1], the
/// constraints as inequalities g <= 0; every distinct candidate it evaluates, in order.
class Polish {
 public:
  using Evaluate = std::function<Evaluation(const std::vector<double>&)>;
  Polish(const DesignStudy& study, const SearchOptions& options, const Evaluate& evaluate, const std::function<void()>& tick)
      : study_(study), options_(options), evaluate_(evaluate), tick_(tick) {}

  /// From `start` (an evaluation already made: not made or recorded again): the
  /// candidates evaluated, and how the optimiser ended.
  TaskOutput run(const Evaluation& start) {
    SolverSummary& summary = output_.optimiser;
    start_ = &start;
    const std::size_t n = study_.variables().size();
    nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(n));
    opt.set_lower_bounds(std::vector<double>(n, 0.0));
    opt.set_upper_bounds(std::vector<double>(n, 1.0));
    opt.set_min_objective(&Polish::objective, this);
    const DesignConstraints& c = study_.constraints();
    if (c.total_mass_max) opt.add_inequality_constraint(&Polish::mass, this, 0.0);
    if (c.messenger_curvature_max) opt.add_inequality_constraint(&Polish::curvature, this, 0.0);
    opt.set_maxeval(options_.polish_evaluations);
    opt.set_xtol_abs(options_.polish_tolerance);
    opt.set_initial_step(0.1);
    std::vector<double> z(n);
    for (std::size_t d = 0; d < n; ++d) {
      const DesignVariable& v = study_.variables()[d];
      z[d] = std::clamp((start.x[d] - v.min) / (v.max - v.min), 0.0, 1.0);
    }
    double value = 0.0;
    try {
      summary.termination = numerics::nlopt_termination(opt.optimize(z, value));
    } catch (const nlopt::roundoff_limited&) {
      summary.termination = Termination::no_progress;  // stopped by round-off: the evaluations made stand
    } catch (const nlopt::forced_stop&) {
      if (failure_) std::rethrow_exception(failure_);
      summary.termination = Termination::inner_failure;
      summary.where = "(NLopt was stopped)";
    } catch (const std::exception& e) {  // NLopt's own failures (invalid arguments, out of memory)
      summary.termination = Termination::inner_failure;
      summary.where = fmt::format("(NLopt: {})", e.what());
    }
    summary.evaluations = opt.get_numevals();
    output_.evaluations = std::move(evaluations_);
    return std::move(output_);
  }

 private:
  /// The evaluation at scaled point z (made once; NLopt asks the objective and
  /// each constraint at the same point).
  const Evaluation& at(const double* z, nlopt::opt* = nullptr) {
    const std::size_t n = study_.variables().size();
    std::vector<double> x(n);
    for (std::size_t d = 0; d < n; ++d) {
      const DesignVariable& v = study_.variables()[d];
      x[d] = v.min + std::clamp(z[d], 0.0, 1.0) * (v.max - v.min);
    }
    if (evaluations_.empty() && x == start_->x) return *start_;
    if (evaluations_.empty() || evaluations_.back().x != x) {
      evaluations_.push_back(evaluate_(x));
      tick_();
    }
    return evaluations_.back();
  }

  /// A candidate that did not converge is the worst: far above any stress ratio.
  static constexpr double kNotConverged = 1e6;

  template <class Figure>
  static double guarded(void* self, const double* z, Figure figure) {
    auto* polish = static_cast<Polish*>(self);
    try {
      return figure(polish->at(z));
    } catch (...) {
      polish->failure_ = std::current_exception();
      throw nlopt::forced_stop();
    }
  }

  static double objective(unsigned, const double* z, double*, void* self) {
    return guarded(self, z, [](const Evaluation& e) { return e.converged() ? e.objective : kNotConverged; });
  }
  static double mass(unsigned, const double* z, double*, void* self) {
    const double max = *static_cast<Polish*>(self)->study_.constraints().total_mass_max;
    return guarded(self, z, [max](const Evaluation& e) { return std::isfinite(e.total_mass) ? e.total_mass - max : kNotConverged; });
  }
  static double curvature(unsigned, const double* z, double*, void* self) {
    const double max = *static_cast<Polish*>(self)->study_.constraints().messenger_curvature_max;
    return guarded(self, z, [max](const Evaluation& e) {
      return e.converged() ? (e.messenger_curvature_max - max) / max : kNotConverged;
    });
  }

  const DesignStudy& study_;
  const SearchOptions& options_;
  const Evaluate& evaluate_;
  const std::function<void()>& tick_;
  const Evaluation* start_ = nullptr;
  std::vector<Evaluation> evaluations_;
  TaskOutput output_;
  std::exception_ptr failure_;
};

/// The starts of the polishes: the best feasible distinct candidates.
std::vector<std::size_t> polish_starts(const std::vector<StudyEvaluation>& evaluations, int count) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < evaluations.size(); ++i) {
    if (evaluations[i].evaluation.feasible()) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return better(evaluations[a].evaluation, evaluations[b].evaluation);
  });
  std::vector<std::size_t> starts;
  for (const std::size_t i : order) {
    if (static_cast<int>(starts.size()) == count) break;
    const bool repeated = std::any_of(starts.begin(), starts.end(), [&](std::size_t s) {
      return evaluations[s].evaluation.x == evaluations[i].evaluation.x;
    });
    if (!repeated) starts.push_back(i);
  }
  return starts;
}

}  // namespace

DesignResult run_search(const DesignStudy& study, const SearchOptions& options, TaskRunner& runner,
                        const SearchProgress& progress, EvaluationJournal* journal) {
  options.validate();
  std::mutex progress_mutex;
  int done = 0;
  const int planned = 1 + options.samples + options.polish * options.polish_evaluations;
  const std::function<void()> tick = [&] {
    if (!progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    progress(++done, planned);
  };

  TableCache cache;
  const Polish::Evaluate evaluate_once = [&](const std::vector<double>& x) {
    if (journal) {
      if (std::optional<Evaluation> recalled = journal->recall(x)) return std::move(*recalled);
    }
    Evaluation e = evaluate(study, x, &cache);
    if (journal) journal->record(e);
    return e;
  };
  std::vector<std::vector<double>> candidates{study.base_values()};
  for (auto& x : space_filling_sample(study.variables(), options.samples, options.seed)) candidates.push_back(std::move(x));
  const auto first = runner.run(static_cast<int>(candidates.size()), [&](int i) {
    TaskOutput out{{evaluate_once(candidates[static_cast<std::size_t>(i)])}, {}};
    tick();
    return out;
  });
  DesignResult result;
  for (std::size_t i = 0; i < first.size(); ++i) {
    result.evaluations.push_back({i == 0 ? Stage::base : Stage::sample, static_cast<int>(i), first[i].evaluations.at(0)});
  }

  const std::vector<std::size_t> starts = polish_starts(result.evaluations, options.polish);
  const auto polished = runner.run(static_cast<int>(starts.size()), [&](int j) {
    return Polish(study, options, evaluate_once, tick).run(result.evaluations[starts[static_cast<std::size_t>(j)]].evaluation);
  });
  for (std::size_t j = 0; j < polished.size(); ++j) {
    for (const Evaluation& e : polished[j].evaluations) result.evaluations.push_back({Stage::polish, static_cast<int>(j), e});
    result.polishes.push_back(polished[j].optimiser);
  }

  for (std::size_t i = 0; i < result.evaluations.size(); ++i) {
    const Evaluation& e = result.evaluations[i].evaluation;
    if (e.feasible() && (!result.best || better(e, result.evaluations[*result.best].evaluation))) result.best = i;
  }
  if (progress) progress(planned, planned);  // done (polishes may stop before their budget)
  return result;
}

}  // namespace stockbridge::design
