#include "stockbridge/damper/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

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
/// solutions discarded.
void continue_arm(const Arm& arm, const SweepSpec& spec, const Block& block, std::vector<ArmSolution>& solutions,
                  const std::function<void()>& tick) {
  constexpr std::size_t kWarmUp = 1;
  ArmTracker tracker(arm, spec.solver, spec.constant_displacement ? HeldAmplitude::displacement : HeldAmplitude::velocity);
  const double amplitude = spec.amplitudes[block.amplitude];
  for (std::size_t i = block.begin >= kWarmUp ? block.begin - kWarmUp : 0; i < block.begin; ++i) {
    tracker.solve(spec.excitation(spec.frequencies[i], amplitude));
  }
  for (std::size_t i = block.begin; i < block.end; ++i) {
    solutions[i] = tracker.solve(spec.excitation(spec.frequencies[i], amplitude));
    tick();
  }
}

/// Flags both ends of every interval where an arm's Jacobian sign changes.
void flag_folds(const std::vector<ArmSolution>& arm, const std::string& arm_label, std::vector<ImpedancePoint>& points) {
  for (std::size_t i = 1; i < arm.size(); ++i) {
    const int a = arm[i - 1].jacobian_sign, b = arm[i].jacobian_sign;
    if (a != 0 && b != 0 && a != b) {
      const std::string note = fmt::format("{}: the response curve folds between {:.4g} and {:.4g} Hz "
                                           "(Jacobian determinant changes sign): several steady states coexist",
                                           arm_label, points[i - 1].frequency_hz, points[i].frequency_hz);
      for (const std::size_t k : {i - 1, i}) {
        if (!points[k].converged()) continue;
        points[k].non_unique = true;
        if (points[k].note.empty()) points[k].note = note;
      }
    }
  }
}

}  // namespace

std::vector<SweepRun> run_sweep(const Damper& damper, const SweepSpec& spec, const SweepProgress& progress) {
  spec.validate();
  const std::vector<std::size_t>& distinct = damper.distinct();
  const std::vector<Block> blocks = cut_into_blocks(spec, distinct.size());
  // Per (amplitude, distinct arm): every frequency's solution.
  std::vector<std::vector<ArmSolution>> results(spec.amplitudes.size() * distinct.size(),
                                                std::vector<ArmSolution>(spec.frequencies.size()));
  // Progress in points (amplitude x frequency), not arm solves: a point is counted
  // once as many arm solves as it needs have been done in all.
  const int total_points = static_cast<int>(spec.amplitudes.size() * spec.frequencies.size());
  std::mutex progress_mutex;
  std::size_t solves = 0;
  int reported = 0;
  auto tick = [&] {
    if (!progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    const int points = static_cast<int>(++solves / distinct.size());
    while (reported < points) progress(++reported, total_points);
  };
  parallel_for(blocks.size(), spec.threads, [&](std::size_t b) {
    const Block& block = blocks[b];
    continue_arm(damper.arms()[distinct[block.task_column]], spec, block,
                 results[block.amplitude * distinct.size() + block.task_column], tick);
  });

  // Each arm's solutions: those of its representative among the distinct arms.
  std::vector<std::size_t> task_column(damper.arms().size());
  for (std::size_t k = 0; k < task_column.size(); ++k) {
    task_column[k] = static_cast<std::size_t>(
        std::find(distinct.begin(), distinct.end(), damper.representative()[k]) - distinct.begin());
  }
  std::vector<SweepRun> runs(spec.amplitudes.size());
  for (std::size_t a = 0; a < spec.amplitudes.size(); ++a) {
    runs[a].amplitude = spec.amplitudes[a];
    for (std::size_t i = 0; i < spec.frequencies.size(); ++i) {
      std::vector<const ArmSolution*> per_arm(task_column.size());
      for (std::size_t k = 0; k < per_arm.size(); ++k) per_arm[k] = &results[a * distinct.size() + task_column[k]][i];
      ImpedancePoint point =
          combine(damper, spec.excitation(spec.frequencies[i], spec.amplitudes[a]), per_arm, spec.solver.energy_tolerance);
      // The amplitude the user gave, as given (V = W X computed back may differ in the last bit).
      (spec.constant_displacement ? point.displacement_amplitude : point.velocity_amplitude) = spec.amplitudes[a];
      runs[a].points.push_back(std::move(point));
    }
    for (std::size_t d = 0; d < distinct.size(); ++d) {
      flag_folds(results[a * distinct.size() + d], damper.arm_label(distinct[d]), runs[a].points);
    }
  }
  return runs;
}

}  // namespace stockbridge::damper
