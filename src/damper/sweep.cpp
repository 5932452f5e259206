#include "stockbridge/damper/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/parallel.hpp"
#include "stockbridge/damper/tracker.hpp"

namespace stockbridge::damper {

void SweepSpec::validate() const {
  if (frequencies.empty()) throw InvalidParameter("frequencies", ": expected at least one frequency");
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    require_positive(fmt::format("frequency[{}]", i), frequencies[i], "Hz");
    if (i > 0 && !(frequencies[i] > frequencies[i - 1])) {
      throw_invalid(fmt::format("frequency[{}]", i), frequencies[i],
                    fmt::format("frequencies increasing strictly (previous {} Hz)", frequencies[i - 1]));
    }
  }
  if (amplitudes.empty()) throw InvalidParameter("amplitudes", ": expected at least one amplitude");
  for (std::size_t i = 0; i < amplitudes.size(); ++i) {
    require_positive(constant_displacement ? "displacement" : "velocity", amplitudes[i],
                     constant_displacement ? "m" : "m/s");
  }
  require_in_range("threads", threads, 1, 256);
  require_in_range("block_points", block_points, 0, 1000000);
  solver.validate();
}

Excitation SweepSpec::excitation(double frequency_hz, double amplitude) const {
  return constant_displacement ? Excitation{frequency_hz, amplitude} : Excitation::from_velocity(frequency_hz, amplitude);
}

std::vector<double> log_spaced(double fmin, double fmax, int points) {
  require_positive("fmin", fmin, "Hz");
  require_positive("fmax", fmax, "Hz");
  require_in_range("points", points, 1, 1000000);
  if (points > 1 && !(fmax > fmin)) throw_invalid("fmax", fmax, fmt::format("a value > fmin = {} Hz", fmin));
  std::vector<double> f(points);
  for (int i = 0; i < points; ++i) {
    f[i] = points == 1 ? fmin : std::exp(std::log(fmin) + (std::log(fmax) - std::log(fmin)) * i / (points - 1));
  }
  f.front() = fmin;  // the ends exactly as given, not as exp(log(.)) returns them
  if (points > 1) f.back() = fmax;
  return f;
}

namespace {

/// A stretch of one amplitude's frequencies [begin, end) followed by one arm's own
/// continuation: the sweep's unit of work on a thread.
struct Block {
  std::size_t amplitude = 0;
  std::size_t task_column = 0;  ///< which distinct arm
  std::size_t begin = 0, end = 0;
};

/// Each amplitude's frequencies cut into stretches of about spec.block_points (the
/// same cut whatever the threads, so that the results are too), for every distinct arm.
std::vector<Block> cut_into_blocks(const SweepSpec& spec, std::size_t distinct_arms) {
  const std::size_t n = spec.frequencies.size();
  const std::size_t per_block = spec.block_points > 0 ? static_cast<std::size_t>(spec.block_points) : n;
  const std::size_t count = std::max<std::size_t>(1, (n + per_block / 2) / per_block);
  std::vector<Block> blocks;
  for (std::size_t a = 0; a < spec.amplitudes.size(); ++a) {
    for (std::size_t b = 0; b < count; ++b) {
      for (std::size_t d = 0; d < distinct_arms; ++d) blocks.push_back({a, d, b * n / count, (b + 1) * n / count});
    }
  }
  return blocks;
}

/// One arm's continuation over a block: from a cold start kWarmUp frequencies
/// before it (where there are), as the sweep itself would arrive, the warm-up's
/// solutions discarded. Each block frequency's solution goes to `deliver(i, solution)`.
void continue_arm(const Arm& arm, const SweepSpec& spec, const Block& block,
                  const std::function<void(std::size_t, ArmSolution&&)>& deliver) {
  constexpr std::size_t kWarmUp = 1;
  ArmTracker tracker(arm, spec.solver, spec.constant_displacement ? HeldAmplitude::displacement : HeldAmplitude::velocity);
  const double amplitude = spec.amplitudes[block.amplitude];
  for (std::size_t i = block.begin >= kWarmUp ? block.begin - kWarmUp : 0; i < block.begin; ++i) {
    tracker.solve(spec.excitation(spec.frequencies[i], amplitude));
  }
  for (std::size_t i = block.begin; i < block.end; ++i) {
    deliver(i, tracker.solve(spec.excitation(spec.frequencies[i], amplitude)));
  }
}

/// The note of a fold between frequencies f1 and f2 of an arm.
std::string fold_note(const std::string& arm_label, double f1, double f2) {
  return fmt::format("{}: the response curve folds between {:.4g} and {:.4g} Hz "
                     "(Jacobian determinant changes sign): several steady states coexist",
                     arm_label, f1, f2);
}

/// Two Jacobian signs that differ (neither unknown): the curve folds between them.
bool folds(int a, int b) { return a != 0 && b != 0 && a != b; }

/// The points of a sweep made final in their order, from arm solutions that arrive
/// in any order: point (a, i) is combined once every distinct arm's solution at i
/// is in, and handed on once those at i + 1 are too (a fold between i and i + 1
/// flags it). Only the solutions of points not yet handed on are held, so memory
/// follows the threads' spread over the blocks, not the number of points.
class OrderedPoints {
 public:
  OrderedPoints(const Damper& damper, const SweepSpec& spec, const SweepSink& sink)
      : damper_(damper), spec_(spec), sink_(sink), distinct_(damper.distinct()),
        pending_(spec.amplitudes.size() * distinct_.size()), previous_sign_(pending_.size(), 0),
        task_column_(damper.arms().size()) {
    for (std::size_t k = 0; k < task_column_.size(); ++k) {  // each arm's representative among the distinct
      task_column_[k] = static_cast<std::size_t>(
          std::find(distinct_.begin(), distinct_.end(), damper.representative()[k]) - distinct_.begin());
    }
  }

  /// Takes the solution of distinct arm `column` at amplitude `a`, frequency `i`;
  /// hands on every point this makes final. Not thread-safe (the caller serialises).
  void add(std::size_t a, std::size_t column, std::size_t i, ArmSolution&& solution) {
    pending_[a * distinct_.size() + column].emplace(i, std::move(solution));
    while (amplitude_ < spec_.amplitudes.size() && ready(amplitude_, frequency_)) {
      hand_on(amplitude_, frequency_);
      if (++frequency_ == spec_.frequencies.size()) {
        frequency_ = 0;
        ++amplitude_;
      }
    }
  }

 private:
  bool in(std::size_t a, std::size_t i) const {
    for (std::size_t d = 0; d < distinct_.size(); ++d) {
      if (!pending_[a * distinct_.size() + d].contains(i)) return false;
    }
    return true;
  }
  bool ready(std::size_t a, std::size_t i) const { return in(a, i) && (i + 1 == spec_.frequencies.size() || in(a, i + 1)); }

  void hand_on(std::size_t a, std::size_t i) {
    std::vector<const ArmSolution*> per_arm(task_column_.size());
    for (std::size_t k = 0; k < per_arm.size(); ++k) per_arm[k] = &pending_[a * distinct_.size() + task_column_[k]].at(i);
    ImpedancePoint point =
        combine(damper_, spec_.excitation(spec_.frequencies[i], spec_.amplitudes[a]), per_arm, spec_.solver.energy_tolerance);
    // The amplitude the user gave, as given (V = W X computed back may differ in the last bit).
    (spec_.constant_displacement ? point.displacement_amplitude : point.velocity_amplitude) = spec_.amplitudes[a];
    const std::vector<double>& f = spec_.frequencies;
    for (std::size_t d = 0; d < distinct_.size(); ++d) {
      std::map<std::size_t, ArmSolution>& arm = pending_[a * distinct_.size() + d];
      const int sign = arm.at(i).jacobian_sign;
      int& before = previous_sign_[a * distinct_.size() + d];
      const auto note = [&](double f1, double f2) { return fold_note(damper_.arm_label(distinct_[d]), f1, f2); };
      if (point.converged() && i > 0 && folds(before, sign)) flag(point, note(f[i - 1], f[i]));
      if (point.converged() && i + 1 < f.size() && folds(sign, arm.at(i + 1).jacobian_sign)) flag(point, note(f[i], f[i + 1]));
      before = i + 1 < f.size() ? sign : 0;
      arm.erase(i);
    }
    sink_(a, i, std::move(point));
  }
  static void flag(ImpedancePoint& point, const std::string& note) {
    point.non_unique = true;
    if (point.note.empty()) point.note = note;
  }

  const Damper& damper_;
  const SweepSpec& spec_;
  const SweepSink& sink_;
  const std::vector<std::size_t>& distinct_;
  std::vector<std::map<std::size_t, ArmSolution>> pending_;  ///< per (amplitude, distinct arm): by frequency index
  std::vector<int> previous_sign_;                           ///< per (amplitude, distinct arm): at the last point handed on
  std::vector<std::size_t> task_column_;
  std::size_t amplitude_ = 0, frequency_ = 0;  ///< the next point to hand on
};

}  // namespace

void stream_sweep(const Damper& damper, const SweepSpec& spec, const SweepSink& sink, const SweepProgress& progress) {
  spec.validate();
  const std::size_t distinct = damper.distinct().size();
  const std::vector<Block> blocks = cut_into_blocks(spec, distinct);
  // Progress in points (amplitude x frequency), not arm solves: a point is counted
  // once as many arm solves as it needs have been done in all.
  const int total_points = static_cast<int>(spec.amplitudes.size() * spec.frequencies.size());
  std::mutex mutex;
  std::size_t solves = 0;
  int reported = 0;
  OrderedPoints points(damper, spec, sink);
  parallel_for(blocks.size(), spec.threads, [&](std::size_t b) {
    const Block& block = blocks[b];
    continue_arm(damper.arms()[damper.distinct()[block.task_column]], spec, block,
                 [&](std::size_t i, ArmSolution&& solution) {
                   const std::lock_guard<std::mutex> lock(mutex);
                   points.add(block.amplitude, block.task_column, i, std::move(solution));
                   if (!progress) return;
                   const int done = static_cast<int>(++solves / distinct);
                   while (reported < done) progress(++reported, total_points);
                 });
  });
}

std::vector<SweepRun> run_sweep(const Damper& damper, const SweepSpec& spec, const SweepProgress& progress) {
  std::vector<SweepRun> runs(spec.amplitudes.size());
  for (std::size_t a = 0; a < runs.size(); ++a) {
    runs[a].amplitude = spec.amplitudes[a];
    runs[a].points.reserve(spec.frequencies.size());
  }
  stream_sweep(damper, spec, [&](std::size_t a, std::size_t, ImpedancePoint&& point) { runs[a].points.push_back(std::move(point)); },
               progress);
  return runs;
}

}  // namespace stockbridge::damper
