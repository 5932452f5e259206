// A conformance suite that every curvature-driven section law passes: tangent
// against finite differences, dissipation never negative and never decreasing,
// closed steady loops, commit/revert.

#include <functional>
#include <memory>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "stockbridge/section/bouc_wen_section.hpp"
#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/regularised_section.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::section {
namespace {

struct LawCase {
  std::string name;
  std::function<std::unique_ptr<SectionLaw>()> make;
  double tangent_tolerance;  // relative, against central finite differences
  double closure_tolerance;  // relative, cycle-to-cycle in the steady loop
};

MasingParameters two_elements() { return {2.8, {{20.0, 0.7}, {4.0, 0.2}}}; }

class SectionLawConformance : public ::testing::TestWithParam<LawCase> {};

TEST_P(SectionLawConformance, TangentMatchesFiniteDifferencesAwayFromBreakpoints) {
  auto law = GetParam().make();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> step(-0.05, 0.05);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const double kappa0 = law->curvature();
    const double dk = step(rng);
    const double eps = 1e-6;
    const double direction = dk > 0 ? 1.0 : -1.0;
    law->set_trial_curvature(kappa0 + dk);
    const double tangent = law->tangent();
    const double moment = law->moment();
    law->set_trial_curvature(kappa0 + dk + direction * eps);
    const double tangent_after = law->tangent();
    const double moment_after = law->moment();
    law->set_trial_curvature(kappa0 + dk);
    // Away from a breakpoint the exact law's tangent is the same on both points.
    if (std::abs(tangent_after - tangent) <= 1e-3 * std::abs(tangent)) {
      const double fd = (moment_after - moment) / (direction * eps);
      ASSERT_NEAR(fd, tangent, GetParam().tangent_tolerance * std::abs(tangent)) << "step " << i;
      ++checked;
    }
    law->commit();
  }
  EXPECT_GT(checked, 100);
}

TEST_P(SectionLawConformance, DissipationIsNeverNegativeNorDecreasing) {
  auto law = GetParam().make();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> step(-0.08, 0.08);
  double previous = 0.0;
  for (int i = 0; i < 500; ++i) {
    law->set_trial_curvature(law->curvature() + step(rng));
    ASSERT_GE(law->dissipated_energy(), previous);
    law->commit();
    previous = law->dissipated_energy();
  }
  EXPECT_GT(previous, 0.0);
}

TEST_P(SectionLawConformance, SteadyLoopCloses) {
  auto law = GetParam().make();
  const SinusoidalDrive drive{0.1, 4, 200};
  const LoopRecord record = run_loop(*law, drive);
  const std::size_t n = record.moment.size();
  const double per_cycle_late = record.dissipated[n - 1] - record.dissipated[n - 1 - 200];
  const double per_cycle_early = record.dissipated[n - 1 - 200] - record.dissipated[n - 1 - 400];
  EXPECT_NEAR(per_cycle_late, per_cycle_early, GetParam().closure_tolerance * per_cycle_late);
  for (std::size_t k = 0; k <= 200; ++k) {
    ASSERT_NEAR(record.moment[n - 1 - k], record.moment[n - 1 - 200 - k],
                GetParam().closure_tolerance * 3.0);
  }
}

TEST_P(SectionLawConformance, RevertRestoresTheCommittedState) {
  auto law = GetParam().make();
  law->set_trial_curvature(0.07);
  law->commit();
  const double moment = law->moment();
  const double dissipated = law->dissipated_energy();
  law->set_trial_curvature(-0.3);
  EXPECT_NE(law->moment(), moment);
  law->revert_to_last_commit();
  EXPECT_EQ(law->moment(), moment);
  EXPECT_EQ(law->dissipated_energy(), dissipated);
  EXPECT_EQ(law->curvature(), 0.07);
}

INSTANTIATE_TEST_SUITE_P(
    Laws, SectionLawConformance,
    ::testing::Values(
        LawCase{"exact", [] { return std::make_unique<MasingSection>(two_elements()); }, 1e-7, 1e-12},
        LawCase{"regularised_n10",
                [] { return std::make_unique<RegularisedSection>(two_elements(), RegularisedOptions{10.0}); },
                1e-4, 1e-6},
        LawCase{"bouc_wen", [] { return std::make_unique<BoucWenSection>(BoucWenParameters{2.8, 24.8, 0.03}); }, 5e-4,
                1e-9}),
    [](const ::testing::TestParamInfo<LawCase>& info) { return info.param.name; });

}  // namespace
}  // namespace stockbridge::section
