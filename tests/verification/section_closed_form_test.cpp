// Closed-form checks of the section law (MODEL.md section 1).

#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/regularised_section.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::section {
namespace {

// One element under a symmetric curvature cycle of amplitude ka dissipates
// 4 h (ka - h/c) per cycle when c ka > h, else nothing.
TEST(SectionClosedForm, OneElementDissipationPerCycle) {
  const double c = 20.0;
  const double h = 0.7;
  for (const double ka : {0.01, 0.03499, 0.0351, 0.05, 0.2, 1.5}) {
    MasingSection section({2.8, {{c, h}}});
    const LoopRecord record = run_loop(section, {ka, 3, 400});
    const double expected = c * ka > h ? 4.0 * h * (ka - h / c) : 0.0;
    if (expected == 0.0) {
      EXPECT_EQ(record.last_cycle_dissipation(), 0.0) << "ka = " << ka;
    } else {
      EXPECT_NEAR(record.last_cycle_dissipation(), expected, 1e-12 * expected) << "ka = " << ka;
    }
  }
}

// The loop's area (trapezoid rule on the exact piecewise linear loop, whose
// samples include every corner when the samples include the extremes and the
// slip points fall between them) equals the sliders' dissipation.
TEST(SectionClosedForm, LoopAreaEqualsSliderDissipation) {
  MasingSection section({2.8, {{20.0, 0.7}, {3.0, 0.1}}});
  const LoopRecord record = run_loop(section, {0.1, 2, 4000});
  double area = 0.0;
  const std::size_t n = record.moment.size();
  for (std::size_t k = n - 4000; k < n; ++k) {
    area += 0.5 * (record.moment[k] + record.moment[k - 1]) * (record.curvature[k] - record.curvature[k - 1]);
  }
  EXPECT_NEAR(area, record.last_cycle_dissipation(), 2e-6 * area);
}

/// The virgin (first-loading) moment at curvature kappa >= 0.
double virgin_moment(const MasingParameters& p, double kappa) {
  MasingSection section(p);
  section.set_trial_curvature(kappa);
  return section.moment();
}

// Masing's rule: every branch after a reversal is the virgin curve scaled by 2
// about the reversal point: M(k) = M_r - 2 M_virgin((k_r - k) / 2).
TEST(SectionClosedForm, MasingRuleAfterReversalsThreeElements) {
  const MasingParameters p{2.8, {{20.0, 0.7}, {5.0, 0.3}, {60.0, 0.1}}};
  MasingSection section(p);
  // Load to a first reversal, then unload in small steps, then reload.
  const double k_first = 0.12;
  for (int i = 1; i <= 50; ++i) {
    section.set_trial_curvature(k_first * i / 50.0);
    section.commit();
  }
  const double m_first = section.moment();
  const double k_second = -0.08;
  for (int i = 1; i <= 200; ++i) {
    const double kappa = k_first + (k_second - k_first) * i / 200.0;
    section.set_trial_curvature(kappa);
    section.commit();
    const double expected = m_first - 2.0 * virgin_moment(p, (k_first - kappa) / 2.0);
    ASSERT_NEAR(section.moment(), expected, 1e-12) << "unloading at kappa = " << kappa;
  }
  const double m_second = section.moment();
  for (int i = 1; i <= 200; ++i) {
    const double kappa = k_second + (0.05 - k_second) * i / 200.0;  // reload, not past the first extreme
    section.set_trial_curvature(kappa);
    section.commit();
    const double expected = m_second + 2.0 * virgin_moment(p, (kappa - k_second) / 2.0);
    ASSERT_NEAR(section.moment(), expected, 1e-12) << "reloading at kappa = " << kappa;
  }
}

// The regularised law approaches the exact loop as its exponent grows: the
// error of the loop area decreases monotonically for n = 2, 5, 10, 20, 50.
TEST(SectionClosedForm, RegularisedLawConvergesToExactLoop) {
  const MasingParameters p{2.8, {{20.0, 0.7}}};
  const SinusoidalDrive drive{0.05, 3, 400};
  MasingSection exact(p);
  const double exact_area = run_loop(exact, drive).last_cycle_dissipation();
  ASSERT_NEAR(exact_area, 4.0 * 0.7 * (0.05 - 0.7 / 20.0), 1e-14);
  double previous_error = 1e300;
  std::vector<double> errors;
  for (const double n : {2.0, 5.0, 10.0, 20.0, 50.0}) {
    RegularisedSection regularised(p, RegularisedOptions{n});
    const double area = run_loop(regularised, drive).last_cycle_dissipation();
    const double error = std::abs(area - exact_area) / exact_area;
    errors.push_back(error);
    RecordProperty("area_error_n" + std::to_string(static_cast<int>(n)), std::to_string(error));
    EXPECT_LT(error, previous_error) << "n = " << n;
    previous_error = error;
  }
  EXPECT_LT(errors.back(), 0.01);
  EXPECT_GT(errors.front(), 0.05);  // n = 2 is far off (about 10 %)
}

}  // namespace
}  // namespace stockbridge::section
