// Local identification recovers the parameters of synthetic records: exact without
// noise, within 2 % with 1 % noise, for one and two elements and varying amplitudes,
// with a moment offset and with uneven sampling. Under STOCKBRIDGE_TEST_SCALE=short
// the long fits run on shorter records (three cycles, 100 or 200 samples each) and
// one noise seed.

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/identification/local_identification.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::identification {
namespace {

struct Synthetic {
  double noise = 0.0;          // standard deviation relative to the largest moment
  double offset = 0.0;         // added to every measured moment, N m
  bool uneven = false;         // phase steps alternately 0.4 and 1.6 times the nominal
  unsigned seed = 1;
  int cycles = 5;
  int points_per_cycle = 400;
};

/// `cycles` cycles of growing amplitude (0.05 -> 0.1 1/m), `points_per_cycle` samples each.
MomentCurvatureRecord synthesise(const section::MasingParameters& p, const Synthetic& how) {
  MomentCurvatureRecord record;
  section::SectionState state = section::SectionState::virgin(p), next = state;
  std::mt19937 rng(how.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const int per = how.points_per_cycle, cycles = how.cycles;
  double largest = 0.0;
  double phase = 0.0;
  for (int k = 0; k <= per * cycles; ++k) {
    if (k > 0) phase += 2.0 * std::numbers::pi / per * (how.uneven ? (k % 2 ? 0.4 : 1.6) : 1.0);  // uneven: short, long, ...
    const double amplitude = 0.05 + 0.05 * k / double(per * cycles);
    const double kappa = amplitude * std::sin(phase);
    section::curvature_update(p, state, kappa, next);
    std::swap(state, next);
    record.curvature.push_back(kappa);
    record.moment.push_back(state.moment);
    largest = std::max(largest, std::abs(state.moment));
  }
  for (double& m : record.moment) m += how.offset + how.noise * largest * gauss(rng);
  return record;
}

void expect_parameters(const LocalIdentification& fit, const section::MasingParameters& truth, double tolerance) {
  EXPECT_NEAR(fit.parameters.ei, truth.ei, tolerance * truth.ei);
  ASSERT_EQ(fit.parameters.jenkin.size(), truth.jenkin.size());
  for (std::size_t j = 0; j < truth.jenkin.size(); ++j) {
    EXPECT_NEAR(fit.parameters.jenkin[j].c, truth.jenkin[j].c, tolerance * truth.jenkin[j].c) << "element " << j;
    EXPECT_NEAR(fit.parameters.jenkin[j].h, truth.jenkin[j].h, tolerance * truth.jenkin[j].h) << "element " << j;
  }
}

const section::MasingParameters kOne{2.8, {{20.0, 0.7}}};
// Sorted by slip curvature h/c, as the fit reports them.
const section::MasingParameters kTwo{2.8, {{60.0, 0.2}, {20.0, 0.7}}};

TEST(LocalIdentification, NoiseFreeRecordsAreRecoveredExactly) {
  for (const auto& truth : {kOne, kTwo}) {
    LocalIdentificationOptions options;
    options.elements = static_cast<int>(truth.jenkin.size());
    Synthetic how;
    how.cycles = stockbridge::testing::scaled(5, 3);
    how.points_per_cycle = stockbridge::testing::scaled(400, 100);
    const LocalIdentification fit = identify_local(synthesise(truth, how), options);
    expect_parameters(fit, truth, 1e-6);
    EXPECT_LT(fit.error, 1e-9);
  }
}

TEST(LocalIdentification, OnePercentNoiseWithinTwoPercent) {
  for (const auto& truth : {kOne, kTwo}) {
    for (const unsigned seed : stockbridge::testing::scaled<std::vector<unsigned>>({1, 2, 3}, {1})) {
      LocalIdentificationOptions options;
      options.elements = static_cast<int>(truth.jenkin.size());
      Synthetic how;
      how.noise = 0.01;
      how.seed = seed;
      how.cycles = stockbridge::testing::scaled(5, 3);
      how.points_per_cycle = stockbridge::testing::scaled(400, 200);
      const LocalIdentification fit = identify_local(synthesise(truth, how), options);
      expect_parameters(fit, truth, 0.02);
      EXPECT_GT(fit.error, 0.0);
      EXPECT_LT(fit.error, 0.03);
    }
  }
}

TEST(LocalIdentification, MomentOffsetAndUnevenSampling) {
  Synthetic how;
  how.offset = 0.15;
  how.uneven = true;
  const LocalIdentification fit = identify_local(synthesise(kOne, how), LocalIdentificationOptions{});
  expect_parameters(fit, kOne, 1e-6);
  EXPECT_NEAR(fit.moment_offset, 0.15, 1e-6);
}

TEST(LocalIdentification, NelderMeadAlsoRecoversOneElement) {
  LocalIdentificationOptions options;
  options.optimizer = Optimizer::nelder_mead;
  expect_parameters(identify_local(synthesise(kOne, {}), options), kOne, 1e-6);
}

TEST(LocalIdentification, ErrorPerCycleAndReversalsIgnoreNoise) {
  Synthetic how;
  how.noise = 0.01;
  const MomentCurvatureRecord record = synthesise(kOne, how);
  EXPECT_EQ(reversals(record.curvature).size(), 10u);  // five cycles: a maximum and a minimum each
  const LocalIdentification fit = identify_local(record, LocalIdentificationOptions{});
  EXPECT_EQ(fit.cycle_errors.size(), 5u);
  // The truth's own error is the noise's: the fit cannot be worse.
  EXPECT_LE(fit.error, relative_l1_error(kOne, 0.0, record) * (1.0 + 1e-9));
}

TEST(LocalIdentification, RejectsRecordsShorterThanOneCycle) {
  MomentCurvatureRecord record;
  for (int k = 0; k <= 300; ++k) {  // three quarters of a cycle
    record.curvature.push_back(0.05 * std::sin(2.0 * std::numbers::pi * k / 400));
    record.moment.push_back(2.8 * record.curvature.back());
  }
  EXPECT_THROW(identify_local(record, LocalIdentificationOptions{}), InvalidParameter);
  LocalIdentificationOptions bad;
  bad.elements = 0;
  EXPECT_THROW(identify_local(synthesise(kOne, {}), bad), InvalidParameter);
  EXPECT_THROW(parse_optimizer("bfgs"), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::identification

namespace stockbridge::identification {
namespace {

/// A Bouc-Wen section's record: the curvature of `synthesise`, its moment by the law,
/// plus relative noise.
MomentCurvatureRecord synthesise_bouc_wen(const section::BoucWenParameters& p, double noise) {
  MomentCurvatureRecord record = synthesise(kOne, Synthetic{});  // the curvature path only
  record.moment = model_moments(cable::LawValues{cable::find_section_law("bouc-wen"), {p.ei_min, p.ei_max, p.chi0}}, 0.0, record);
  double largest = 0.0;
  for (const double m : record.moment) largest = std::max(largest, std::abs(m));
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (double& m : record.moment) m += noise * largest * gauss(rng);
  return record;
}

// The Bouc-Wen law fitted to its own record gives its numbers back (to 1e-6; 2 % at
// 1 % noise), and fits it far better than the Masing law does (the two laws' loops
// differ in shape: MODEL.md section 13).
TEST(LocalIdentificationBoucWen, ItsOwnRecordGivesItsNumbersBack) {
  const section::BoucWenParameters truth{2.5, 25.0, 0.03};
  LocalIdentificationOptions options;
  options.law = cable::find_section_law("bouc-wen");
  for (const double noise : {0.0, 0.01}) {
    const LocalIdentification fit = identify_local(synthesise_bouc_wen(truth, noise), options);
    ASSERT_TRUE(fit.numbers.has_value());
    const double tolerance = noise == 0.0 ? 1e-6 : 0.02;
    EXPECT_NEAR((*fit.numbers)[0], truth.ei_min, tolerance * truth.ei_min) << "noise " << noise;
    EXPECT_NEAR((*fit.numbers)[1], truth.ei_max, tolerance * truth.ei_max) << "noise " << noise;
    EXPECT_NEAR((*fit.numbers)[2], truth.chi0, tolerance * truth.chi0) << "noise " << noise;
    if (noise == 0.0) {
      EXPECT_LT(fit.error, 1e-8);
    }
  }
  const LocalIdentification masing = identify_local(synthesise_bouc_wen(truth, 0.0), LocalIdentificationOptions{});
  EXPECT_FALSE(masing.numbers.has_value());
  EXPECT_GT(masing.error, 0.02) << "one Jenkin element does not draw a Bouc-Wen loop";
}

TEST(LocalIdentificationBoucWen, JenkinElementsAreRefusedUnderTheBoucWenLaw) {
  LocalIdentificationOptions options;
  options.law = cable::find_section_law("bouc-wen");
  options.elements = 2;
  try {
    (void)identify_local(synthesise_bouc_wen({2.5, 25.0, 0.03}, 0.0), options);
    FAIL() << "two elements under the Bouc-Wen law were accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "elements");
  }
}

}  // namespace
}  // namespace stockbridge::identification
