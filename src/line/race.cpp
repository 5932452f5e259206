#include "race.hpp"

#include <cstddef>
#include <limits>

namespace stockbridge::line {

namespace {

/// A stress that drops a runner reaching it: a finished runner's bound.
struct Bound {
  double stress;
  std::size_t runner;  ///< whose
};

enum class RunnerState { running, finished, dropped };

}  // namespace

std::vector<bool> race(std::vector<RaceRunner>& runners, std::optional<double> limit) {
  const std::size_t n = runners.size();
  std::vector<RunnerState> state(n, RunnerState::running);
  std::vector<double> largest(n, -std::numeric_limits<double>::infinity());
  std::vector<Bound> bounds;
  const auto beaten = [&](std::size_t j) {
    for (const Bound& b : bounds) {
      if (largest[j] > b.stress || (largest[j] == b.stress && b.runner < j)) return true;
    }
    return false;
  };
  const auto lowest_running = [&]() -> std::optional<std::size_t> {
    std::optional<std::size_t> k;
    for (std::size_t j = 0; j < n; ++j) {
      if (state[j] == RunnerState::running && (!k || largest[j] < largest[*k])) k = j;
    }
    return k;
  };
  while (const std::optional<std::size_t> k = lowest_running()) {
    RaceRunner& r = runners[*k];
    if (!r.done()) {
      const std::optional<double> s = r.next();
      if (s && *s > largest[*k]) largest[*k] = *s;
      if ((s && limit && *s > *limit) || beaten(*k)) {
        state[*k] = RunnerState::dropped;
        continue;
      }
    }
    if (!r.done()) continue;
    state[*k] = RunnerState::finished;
    if (const std::optional<double> b = r.finish()) {
      bounds.push_back({*b, *k});
      for (std::size_t j = 0; j < n; ++j) {
        if (state[j] == RunnerState::running && beaten(j)) state[j] = RunnerState::dropped;
      }
    }
  }
  std::vector<bool> finished(n);
  for (std::size_t j = 0; j < n; ++j) finished[j] = state[j] == RunnerState::finished;
  return finished;
}

}  // namespace stockbridge::line
