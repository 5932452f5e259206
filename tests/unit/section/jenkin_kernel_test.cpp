// The exact kernels: the moment-driven and the curvature-driven updates are
// inverse to each other, on random monotone steps and after reversals.

#include <random>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/section/masing_law.hpp"
#include "stockbridge/section/masing_section.hpp"

namespace stockbridge::section {
namespace {

MasingParameters three_elements() { return {2.8, {{20.0, 0.7}, {5.0, 0.3}, {60.0, 0.1}}}; }

TEST(MasingLaw, MomentAndCurvatureUpdatesAreInverseOnRandomPaths) {
  const MasingParameters p = three_elements();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> step(-0.04, 0.04);
  SectionState committed = SectionState::virgin(p);
  SectionState by_curvature = committed;
  SectionState by_moment = committed;
  int reversals = 0;
  double previous_step = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double dk = step(rng);
    reversals += dk * previous_step < 0.0;
    previous_step = dk;
    curvature_update(p, committed, committed.curvature + dk, by_curvature);
    moment_update(p, committed, by_curvature.moment, by_moment);
    const double scale = std::abs(by_curvature.curvature) + 1e-3;
    ASSERT_NEAR(by_moment.curvature, by_curvature.curvature, 1e-12 * scale) << "step " << i;
    ASSERT_NEAR(by_moment.tangent, by_curvature.tangent, 1e-12) << "step " << i;
    for (std::size_t j = 0; j < p.jenkin.size(); ++j) {
      ASSERT_NEAR(by_moment.hysteretic[j], by_curvature.hysteretic[j], 1e-12) << "step " << i;
    }
    ASSERT_NEAR(by_moment.dissipated, by_curvature.dissipated, 1e-12);
    committed = by_curvature;
  }
  EXPECT_GT(reversals, 500);
}

TEST(MasingLaw, MomentDrivenStepReproducesTheRequestedMoment) {
  const MasingParameters p = three_elements();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> moment(-3.0, 3.0);
  SectionState committed = SectionState::virgin(p);
  SectionState trial = committed;
  for (int i = 0; i < 2000; ++i) {
    const double target = moment(rng);
    moment_update(p, committed, target, trial);
    ASSERT_NEAR(trial.moment, target, 1e-12 * (1.0 + std::abs(target)));
    SectionState again = committed;
    curvature_update(p, committed, trial.curvature, again);
    ASSERT_NEAR(again.moment, target, 1e-12 * (1.0 + std::abs(target)));
    committed = trial;
  }
}

TEST(MasingLaw, TangentIsTheSumOfStickingStiffnesses) {
  const MasingParameters p{1.0, {{10.0, 1.0}, {100.0, 1.0}}};
  SectionState from = SectionState::virgin(p);
  SectionState to = from;
  curvature_update(p, from, 0.005, to);  // both stick (breakpoints 0.1 and 0.01)
  EXPECT_DOUBLE_EQ(to.tangent, 111.0);
  curvature_update(p, from, 0.05, to);  // the stiff one slips
  EXPECT_DOUBLE_EQ(to.tangent, 11.0);
  curvature_update(p, from, 0.5, to);  // both slip
  EXPECT_DOUBLE_EQ(to.tangent, 1.0);
  EXPECT_DOUBLE_EQ(to.moment, 0.5 + 2.0);
}

TEST(MasingLaw, ElasticSectionWithoutElements) {
  MasingSection section({2.5, {}});
  section.set_trial_curvature(0.2);
  EXPECT_DOUBLE_EQ(section.moment(), 0.5);
  section.set_trial_moment(-1.0);
  EXPECT_DOUBLE_EQ(section.curvature(), -0.4);
  EXPECT_DOUBLE_EQ(section.tangent(), 2.5);
  EXPECT_EQ(section.dissipated_energy(), 0.0);
}

TEST(MasingLaw, MomentBeyondCapacityWithoutElasticPartIsANumericalError) {
  MasingSection section({0.0, {{20.0, 0.7}}});
  section.set_trial_moment(0.5);
  EXPECT_NEAR(section.curvature(), 0.025, 1e-15);
  EXPECT_THROW(section.set_trial_moment(0.8), NumericalError);
}

TEST(MasingSection, TrialsDoNotTouchTheCommittedStateUntilCommit) {
  MasingSection section(three_elements());
  section.set_trial_curvature(0.3);
  section.commit();
  const SectionState committed = section.committed_state();
  section.set_trial_curvature(-0.2);
  section.set_trial_curvature(0.1);
  EXPECT_EQ(section.committed_state().curvature, committed.curvature);
  EXPECT_EQ(section.committed_state().hysteretic, committed.hysteretic);
  // A trial is always taken from the committed state: the same trial twice agrees.
  const double moment = section.moment();
  section.set_trial_curvature(-0.2);
  section.set_trial_curvature(0.1);
  EXPECT_EQ(section.moment(), moment);
  section.revert_to_last_commit();
  EXPECT_EQ(section.curvature(), committed.curvature);
  EXPECT_EQ(section.moment(), committed.moment);
}

}  // namespace
}  // namespace stockbridge::section
