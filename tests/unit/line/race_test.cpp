// The race of a line's polished arrangements (line/race.cpp) on made-up stress
// sequences: the runner it keeps is the one balancing every runner to the end keeps,
// no runner balances more frequencies than with the winner known beforehand, and a
// point above the limit or a finished runner's largest drops a runner, a tie going to
// the runner earlier in the order.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "line/race.hpp"

namespace stockbridge::line {
namespace {

/// A runner over a fixed sequence of stresses (none: a point not converged),
/// counting the frequencies it balanced. Its bound is its largest stress.
struct Sequence {
  std::vector<std::optional<double>> stresses;
  std::size_t balanced = 0;
  bool finished = false;

  double largest() const {
    double m = -1.0;
    for (const std::optional<double>& s : stresses) m = s ? std::max(m, *s) : m;
    return m;
  }
};

std::vector<RaceRunner> runners_of(std::vector<Sequence>& sequences) {
  std::vector<RaceRunner> runners;
  for (Sequence& q : sequences) {
    runners.push_back({[&q] { return q.balanced == q.stresses.size(); }, [&q] { return q.stresses[q.balanced++]; },
                       [&q]() -> std::optional<double> {
                         q.finished = true;
                         return q.largest();
                       }});
  }
  return runners;
}

/// The runner the schedule keeps of every runner balanced to the end: the lowest
/// largest stress, the earlier where two tie.
std::size_t kept_of_all(const std::vector<Sequence>& sequences) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < sequences.size(); ++k) {
    if (sequences[k].largest() < sequences[best].largest()) best = k;
  }
  return best;
}

/// The frequencies a runner balances where the winner is balanced first and the
/// runner then left at its first point that shows it cannot be kept: at or above the
/// winner's largest, or above it for a runner `earlier` in the order (a tie is its).
std::size_t balanced_with_winner_known(const Sequence& q, double winner_largest, bool earlier) {
  for (std::size_t i = 0; i < q.stresses.size(); ++i) {
    if (q.stresses[i] && (*q.stresses[i] > winner_largest || (!earlier && *q.stresses[i] == winner_largest))) {
      return i + 1;
    }
  }
  return q.stresses.size();
}

TEST(Race, KeepsWhatBalancingEveryRunnerToTheEndKeepsAndBalancesNoMoreThanKnowingTheWinner) {
  std::mt19937 random(20261130);
  std::uniform_real_distribution<double> stress(1.0, 10.0);
  std::uniform_int_distribution<int> runner_count(1, 4), length(1, 30), percent(0, 99);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Sequence> sequences(static_cast<std::size_t>(runner_count(random)));
    const int points = length(random);
    for (Sequence& q : sequences) {
      for (int i = 0; i < points; ++i) {
        // Stresses on a coarse grid, so that runners tie; a few points not converged.
        const int p = percent(random);
        q.stresses.push_back(p < 5 ? std::nullopt : std::optional<double>(std::round(stress(random))));
      }
    }
    std::vector<RaceRunner> runners = runners_of(sequences);
    const std::vector<bool> finished = race(runners, std::nullopt);
    const std::size_t kept = kept_of_all(sequences);
    ASSERT_TRUE(finished[kept]) << "trial " << trial;
    for (std::size_t k = 0; k < sequences.size(); ++k) {
      EXPECT_EQ(finished[k], sequences[k].finished) << "trial " << trial << ", runner " << k;
      if (k != kept) {
        EXPECT_LE(sequences[k].balanced, balanced_with_winner_known(sequences[k], sequences[kept].largest(), k < kept))
            << "trial " << trial << ", runner " << k;
      }
    }
  }
}

TEST(Race, APointAboveTheLimitDropsItsRunnerThere) {
  std::vector<Sequence> sequences{{{1.0, 9.0, 2.0, 2.0}}, {{3.0, 3.0, 3.0, 3.0}}};
  std::vector<RaceRunner> runners = runners_of(sequences);
  const std::vector<bool> finished = race(runners, 8.0);
  EXPECT_FALSE(finished[0]);
  EXPECT_EQ(sequences[0].balanced, 2u);
  EXPECT_TRUE(finished[1]);
}

TEST(Race, ATieGoesToTheRunnerEarlierInTheOrder) {
  // The later runner finishes first (its stresses are lower until the last point);
  // the earlier one then reaches its largest exactly, and is kept on.
  std::vector<Sequence> sequences{{{4.0, 4.0, 4.0}}, {{1.0, 1.0, 4.0}}};
  std::vector<RaceRunner> runners = runners_of(sequences);
  const std::vector<bool> finished = race(runners, std::nullopt);
  EXPECT_TRUE(finished[0]);
  EXPECT_TRUE(finished[1]);
  // And the other way round: the earlier finished, the later tying it is dropped.
  std::vector<Sequence> reversed{{{1.0, 1.0, 4.0}}, {{4.0, 4.0, 4.0}}};
  std::vector<RaceRunner> again = runners_of(reversed);
  const std::vector<bool> ended = race(again, std::nullopt);
  EXPECT_TRUE(ended[0]);
  EXPECT_FALSE(ended[1]);
  EXPECT_EQ(reversed[1].balanced, 1u);
}

}  // namespace
}  // namespace stockbridge::line
