#pragma once
// Several arrangements' polished balances raced frequency by frequency, so that the
// ones that cannot be chosen are left as early as a point shows it (schedule.cpp).
// Library-internal.

#include <functional>
#include <optional>
#include <vector>

namespace stockbridge::line {

/// One arrangement's balance as a race advances it.
struct RaceRunner {
  /// Every frequency balanced.
  std::function<bool()> done;
  /// Balances the next frequency (from the lowest): its judged stress, Pa; none where
  /// the point did not converge (it neither raises the runner's largest nor drops it).
  std::function<std::optional<double>()> next;
  /// Called once, when the runner has balanced every frequency: the largest stress
  /// another runner must stay below to beat it, Pa; none where no such bound holds.
  std::function<std::optional<double>()> finish;
};

/// The runners, in the order of preference (of two that tie, the earlier is chosen),
/// advanced one frequency at a time: always the one whose largest stress so far is
/// the lowest (the earlier where they tie). A runner is dropped where a point shows it
/// cannot be chosen:
/// * a stress above `limit` (proven unsafe);
/// * its largest stress at or above a finished runner's bound (above it, for a runner
///   earlier in the order).
/// Returns which runners finished (the others were dropped).
///
/// What the schedule keeps of them is the one it would keep of every runner balanced
/// to the end: a dropped runner's largest stress can only grow, so it could not have
/// beaten the runner that dropped it. And no runner balances a frequency more than it
/// would if the winner were balanced first and the others then left where they reach
/// its largest: a runner is advanced only while its largest is the lowest, so never
/// once it is above the winner's.
std::vector<bool> race(std::vector<RaceRunner>& runners, std::optional<double> limit);

}  // namespace stockbridge::line
