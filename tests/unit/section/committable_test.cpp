// SwappingCommittable (commit by swapping, the trial copied lazily) follows the same
// protocol as Committable (commit and revert by copying): on a random sequence of
// modifications, overwrites, commits and reverts both hold the same states throughout.

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/section/committable.hpp"

namespace stockbridge {
namespace {

using Values = std::vector<double>;

TEST(SwappingCommittable, HoldsTheStatesOfCommittableOnRandomOperations) {
  const Values initial{1.0, 2.0, 3.0};
  Committable<Values> copying(initial);
  SwappingCommittable<Values> swapping(initial);
  std::mt19937 rng(2026);
  std::uniform_int_distribution<int> operation(0, 3);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int step = 0; step < 2000; ++step) {
    switch (operation(rng)) {
      case 0: {  // modify one entry of the trial (reads the rest)
        const double v = value(rng);
        const std::size_t i = static_cast<std::size_t>(step) % initial.size();
        copying.trial()[i] += v;
        swapping.trial()[i] += v;
        break;
      }
      case 1: {  // overwrite the whole trial from the committed state
        const double v = value(rng);
        Values next = copying.committed();
        for (double& x : next) x = 0.5 * x + v;
        copying.trial() = next;
        swapping.trial_to_overwrite() = next;
        break;
      }
      case 2:
        copying.commit();
        swapping.commit();
        break;
      default:
        copying.revert_to_last_commit();
        swapping.revert_to_last_commit();
        break;
    }
    ASSERT_EQ(swapping.committed(), copying.committed()) << "step " << step;
    const SwappingCommittable<Values>& read_only = swapping;
    ASSERT_EQ(read_only.trial(), copying.trial()) << "step " << step;
  }
}

TEST(SwappingCommittable, ACommitWithoutATrialKeepsTheCommittedState) {
  SwappingCommittable<Values> state(Values{4.0, 5.0});
  state.trial()[0] = 7.0;
  state.commit();
  state.commit();  // no trial since: nothing changes
  EXPECT_EQ(state.committed(), (Values{7.0, 5.0}));
  state.trial_to_overwrite() = Values{1.0, 1.0};
  state.revert_to_last_commit();
  state.commit();
  EXPECT_EQ(state.committed(), (Values{7.0, 5.0}));
}

}  // namespace
}  // namespace stockbridge
