// The Bouc-Wen section law against MODEL.md section 13's closed forms: the virgin
// curve, the steady loop's eta amplitude tanh(chi_a / chi0) and its dissipation, the
// cubic small-amplitude limit, the dissipation as the loop's area; that it is not a
// Masing law (its unloading branch has the length scale chi0, Masing's rule 2 chi0);
// and its parameters checked where they are named.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"
#include "stockbridge/section/sinusoidal_drive.hpp"

namespace stockbridge::section {
namespace {

// slenderpy's outer messenger zones (MODEL.md 13).
const BoucWenParameters kZone{5.0, 40.0, 0.15};

double virgin_moment(const BoucWenParameters& p, double chi) {
  return p.ei_min * chi + (p.ei_max - p.ei_min) * p.chi0 * (1.0 - std::exp(-chi / p.chi0));
}

double steady_cycle_dissipation(const BoucWenParameters& p, double chi_a) {
  return 4.0 * (p.ei_max - p.ei_min) * p.chi0 * (chi_a - p.chi0 * std::tanh(chi_a / p.chi0));
}

TEST(BoucWen, TheVirginCurveIsExactInOneStepOrInMany) {
  for (const double chi : {0.01, 0.15, 0.6, 2.0}) {
    BoucWenSection one(kZone);
    one.set_trial_curvature(chi);
    EXPECT_NEAR(one.moment(), virgin_moment(kZone, chi), 1e-12 * virgin_moment(kZone, chi)) << chi;
    BoucWenSection many(kZone);
    for (int k = 1; k <= 1000; ++k) {
      many.set_trial_curvature(chi * k / 1000.0);
      many.commit();
    }
    EXPECT_NEAR(many.moment(), one.moment(), 1e-12 * one.moment()) << chi;
    EXPECT_NEAR(many.dissipated_energy(), one.dissipated_energy(), 1e-12 * one.dissipated_energy()) << chi;
  }
  BoucWenSection start(kZone);
  EXPECT_EQ(start.tangent(), kZone.ei_max) << "the virgin tangent is the no-slip stiffness";
}

TEST(BoucWen, TheSteadyLoopSwingsEtaToTanhAndDissipatesItsClosedForm) {
  for (const double chi_a : {0.05, 0.15, 0.5, 1.5}) {
    // The loop's centre drifts from the virgin start by exp(-2 chi_a / chi0) per half
    // cycle: enough cycles that it has settled to round-off.
    BoucWenSection section(kZone);
    const LoopRecord record = run_loop(section, {chi_a, 40, 400});
    // The last sample is the cycle's end (chi = 0 rising); drive once more to the peak.
    section.set_trial_curvature(chi_a);
    EXPECT_NEAR(section.eta(), std::tanh(chi_a / kZone.chi0), 1e-9) << chi_a;
    const double expected = steady_cycle_dissipation(kZone, chi_a);
    EXPECT_NEAR(record.last_cycle_dissipation(), expected, 1e-9 * expected) << chi_a;
  }
}

TEST(BoucWen, SmallCyclesDissipateAsTheCubeOfTheAmplitude) {
  const double chi_a = 0.01 * kZone.chi0;
  const double cubic = 4.0 / 3.0 * (kZone.ei_max - kZone.ei_min) * std::pow(chi_a, 3) / kZone.chi0;
  EXPECT_NEAR(steady_cycle_dissipation(kZone, chi_a) / cubic, 1.0, 1e-3);
  BoucWenSection section(kZone);
  const LoopRecord record = run_loop(section, {chi_a, 2000, 40});  // settled: exp(-0.02) per half cycle
  EXPECT_NEAR(record.last_cycle_dissipation() / cubic, 1.0, 1e-3);
  EXPECT_NEAR(record.last_cycle_dissipation(), steady_cycle_dissipation(kZone, chi_a),
              1e-7 * steady_cycle_dissipation(kZone, chi_a));
}

// The dissipation of a stretch is the integral of a square: over stretches so short
// that its terms cancel to round-off (1e-13 chi0 down), from the virgin state and
// from states on either side, it never goes down.
TEST(BoucWen, AShortStretchNeverDissipatesLess) {
  for (const double start : {0.0, 0.3, -0.3, 2.0}) {
    const BoucWenState from = bouc_wen_update(kZone, BoucWenState::virgin(kZone), start * kZone.chi0);
    for (double step = 1e-3; step > 1e-16; step *= 0.37) {
      for (const double sign : {1.0, -1.0}) {
        const BoucWenState to = bouc_wen_update(kZone, from, from.curvature + sign * step * kZone.chi0);
        EXPECT_GE(to.dissipated, from.dissipated) << "from " << start << " chi0, step " << sign * step << " chi0";
      }
    }
  }
}

TEST(BoucWen, TheDissipationOfASteadyCycleIsTheLoopsArea) {
  BoucWenSection section(kZone);
  const int points = 20000;
  const LoopRecord record = run_loop(section, {0.4, 4, points});
  const std::size_t n = record.moment.size();
  double area = 0.0;  // the trapezoid rule over the last cycle's closed path
  for (std::size_t k = n - points; k < n; ++k) {
    area += 0.5 * (record.moment[k] + record.moment[k - 1]) * (record.curvature[k] - record.curvature[k - 1]);
  }
  EXPECT_NEAR(area, record.last_cycle_dissipation(), 1e-6 * record.last_cycle_dissipation());
}

TEST(BoucWen, IsNotAMasingLawItsUnloadingBranchHasTheScaleChi0) {
  // Load to chi_r on the virgin curve, then unload by d. Masing's rule would give the
  // virgin curve doubled: M_r - M = 2 f(d / 2); Bouc-Wen gives the hysteretic part
  // 1 + eta = (1 + eta_r) exp(-d / chi0), the scale chi0 itself.
  const double chi_r = 0.3, d = 0.2;
  BoucWenSection section(kZone);
  section.set_trial_curvature(chi_r);
  section.commit();
  const double moment_r = section.moment(), eta_r = section.eta();
  section.set_trial_curvature(chi_r - d);
  EXPECT_NEAR(1.0 + section.eta(), (1.0 + eta_r) * std::exp(-d / kZone.chi0), 1e-14);
  const double masing_drop = 2.0 * virgin_moment(kZone, d / 2.0);
  const double drop = moment_r - section.moment();
  EXPECT_GT(std::abs(drop - masing_drop), 0.05 * masing_drop) << drop << " vs Masing's " << masing_drop;
  // The unloading tangent starts at EI_max, as a Masing law's does: the difference is the shape, not the start.
  section.set_trial_curvature(chi_r - 1e-9);
  EXPECT_NEAR(section.tangent(), kZone.ei_min + (kZone.ei_max - kZone.ei_min) * (1.0 + eta_r), 1e-6);
}

TEST(BoucWen, ParametersAreCheckedWhereTheyAreNamed) {
  const auto field_of = [](BoucWenParameters p) {
    try {
      BoucWenSection section(p);
    } catch (const InvalidParameter& e) {
      return e.field();
    }
    return std::string("no error");
  };
  EXPECT_EQ(field_of({0.0, 40.0, 0.15}), "ei_min");
  EXPECT_EQ(field_of({5.0, 4.0, 0.15}), "ei_max");
  EXPECT_EQ(field_of({5.0, 40.0, 0.0}), "chi0");
  EXPECT_EQ(field_of({5.0, 40.0, -1.0}), "chi0");
  EXPECT_EQ(field_of({5.0, 5.0, 0.15}), "no error") << "EI_max = EI_min: an elastic section";
}

}  // namespace
}  // namespace stockbridge::section
