#pragma once
// The design search: the base design, a space-filling sample of the variables'
// box (a Sobol sequence, digitally shifted by the seed), then local polishes of
// the best feasible candidates (NLopt's COBYLA within the bounds, the constraints
// as inequalities), every evaluation kept. Candidates are independent: a
// TaskRunner runs them on threads here, on MPI ranks in the command line; the
// search itself is the same on every rank, so the result is the same, bit for bit,
// for any number of ranks and threads.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/design/study.hpp"

namespace stockbridge::design {

struct SearchOptions {
  int samples = 256;             ///< space-filling candidates (>= 1)
  int polish = 4;                ///< best feasible candidates polished locally (>= 0)
  int polish_evaluations = 40;   ///< evaluations of one polish at most (>= 2)
  double polish_tolerance = 1e-3;  ///< stop when a step moves the variables less than this share of their ranges
  std::uint64_t seed = 1;

  void validate() const;
};

/// What one task of a search gives: its evaluations and, for a local polish, how the
/// optimiser ended (not_run for a task that is no optimisation).
struct TaskOutput {
  std::vector<Evaluation> evaluations;
  SolverSummary optimiser;
};

/// Runs independent tasks and returns every task's output in task order (to every
/// caller, on MPI every rank).
class TaskRunner {
 public:
  virtual ~TaskRunner() = default;
  virtual std::vector<TaskOutput> run(int tasks, const std::function<TaskOutput(int)>& task) = 0;
};

/// Tasks on `threads` threads of this process (tasks taken in turn as threads free up).
class ThreadRunner final : public TaskRunner {
 public:
  explicit ThreadRunner(int threads);
  std::vector<TaskOutput> run(int tasks, const std::function<TaskOutput(int)>& task) override;

 private:
  int threads_;
};

/// Where an evaluation was made.
enum class Stage { base, sample, polish };
std::string_view stage_name(Stage stage);

struct StudyEvaluation {
  Stage stage = Stage::sample;
  int run = 0;  ///< the sample's index, or the polish's (0 for the base)
  Evaluation evaluation;
};

struct DesignResult {
  std::vector<StudyEvaluation> evaluations;  ///< base, samples in order, then each polish's in order
  /// How each local polish (COBYLA) ended: converged (the step fell below the
  /// tolerance), max_iterations (polish_evaluations used up), no_progress (stopped
  /// by round-off), inner_failure (NLopt failed: `where` says how); evaluations.
  std::vector<SolverSummary> polishes;
  /// The best feasible evaluation (index into evaluations); none when no candidate is feasible.
  std::optional<std::size_t> best;
  std::size_t base = 0;  ///< the base design's index (0)
};

/// Called after each candidate (serialised): (evaluations done, evaluations planned
/// at most), and (planned, planned) at the end.
using SearchProgress = std::function<void(int, int)>;

/// The points of the sample: `count` points of the variables' box.
std::vector<std::vector<double>> space_filling_sample(const std::vector<DesignVariable>& variables, int count,
                                                      std::uint64_t seed);

/// Where a study's evaluations are kept as they are made and found again: a resumed
/// study recalls those of its interrupted run instead of computing them, and, the
/// search being deterministic, takes the same path to the same result.
class EvaluationJournal {
 public:
  virtual ~EvaluationJournal() = default;
  /// The evaluation of candidate x made before, if any (from any thread). May throw
  /// (Interrupted: the study was asked to stop).
  virtual std::optional<Evaluation> recall(const std::vector<double>& x) = 0;
  /// A new evaluation as it completes (from any thread).
  virtual void record(const Evaluation& evaluation) = 0;
};

/// The search: the base design, the sample (on the runner's workers), then the
/// polishes from the best feasible candidates. With a journal, every candidate is
/// recalled from it where it was evaluated before, and recorded as it is made.
DesignResult run_search(const DesignStudy& study, const SearchOptions& options, TaskRunner& runner,
                        const SearchProgress& progress = {}, EvaluationJournal* journal = nullptr);

/// Whether a is better than b: feasible before infeasible, converged before not,
/// then the smaller objective.
bool better(const Evaluation& a, const Evaluation& b);

}  // namespace stockbridge::design
