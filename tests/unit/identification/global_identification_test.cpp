// Global identification from synthetic cycles of experiments (a) and (b): the fit
// recovers the cable exactly without noise and within 2 % with 1 % noise; the
// four-step formulas stay within their documented bias. Under
// STOCKBRIDGE_TEST_SCALE=short the fits run on a coarser cable and cycle (8 sections
// rather than 40, measured and fitted alike; 100 samples per cycle rather than 400)
// and with one noise seed.

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/identification/global_identification.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::identification {
namespace {

/// How finely the cable is modelled (measured and fitted alike) and the cycle sampled.
struct Resolution {
  int sections = 40;
  int points_per_cycle = 400;
};

Resolution scaled_resolution() { return stockbridge::testing::scaled(Resolution{}, Resolution{8, 100}); }

/// The dissertation's cable (l = 0.3, ei 2.8, c 20, h 0.7; Table 4.2).
cable::CableDescription truth(const Resolution& r) {
  return cable::CableDescription::uniform(0.3, r.sections, 2.8, {{20.0, 0.7}});
}

/// Two cycles of the cable.
ExperimentMeasurement measure(cable::Experiment experiment, double noise, unsigned seed = 7,
                              const Resolution& r = scaled_resolution()) {
  cable::Cantilever cantilever{cable::Cable(truth(r))};
  const double amplitude = experiment == cable::Experiment::a ? 0.03 : 0.15;
  const cable::ExperimentRecord record =
      cable::run_experiment(cantilever, {experiment, amplitude, 2, r.points_per_cycle});
  ExperimentMeasurement m;
  m.experiment = experiment;
  double largest = 0.0;
  for (const cable::ExperimentSample& s : record.samples) {
    const bool a = experiment == cable::Experiment::a;
    m.prescribed.push_back(a ? s.deflection : s.rotation);
    m.measured.push_back(a ? s.tip_force : s.clamp_moment);
    largest = std::max(largest, std::abs(m.measured.back()));
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (double& y : m.measured) y += noise * largest * gauss(rng);
  return m;
}

GlobalIdentificationOptions options(const Resolution& r = scaled_resolution()) {
  GlobalIdentificationOptions o;
  o.length = 0.3;
  o.sections = r.sections;
  return o;
}

void expect_cable(const GlobalIdentification& fit, double ei, double c, double h, double tol_ei, double tol_c,
                  double tol_h) {
  EXPECT_NEAR(fit.cable.ei.at(0.0), ei, tol_ei * ei);
  ASSERT_EQ(fit.cable.jenkin.size(), 1u);
  EXPECT_NEAR(fit.cable.jenkin[0].c.at(0.0), c, tol_c * c);
  EXPECT_NEAR(fit.cable.jenkin[0].h.at(0.0), h, tol_h * h);
}

// Table 4.2's numbers are consistent with the model: a cable with ei 2.8, c 20,
// h 0.7 gives cycles from which the fit returns those numbers.
TEST(GlobalIdentification, FitRecoversTheCableExactlyWithoutNoise) {
  for (const cable::Experiment e : {cable::Experiment::a, cable::Experiment::b}) {
    const GlobalIdentification fit = identify_fit(measure(e, 0.0), options());
    expect_cable(fit, 2.8, 20.0, 0.7, 1e-6, 1e-6, 1e-6);
    EXPECT_LT(fit.error, 1e-9);
  }
}

// With 1 % noise the fit reaches the L1 minimum: its error is below that of the true
// parameters, for every noise realisation tried. How close that minimum lies to the
// truth is the data's doing: ei and h within 2 % (in fact 0.3 %), c within 2 % from
// (a) but only within 5 % from (b), where the stick zone around l/3 leaves c weakly
// determined (over 12 seeds: c from 19.37 to 20.75).
TEST(GlobalIdentification, FitReachesTheMinimumAtOnePercentNoise) {
  for (const cable::Experiment e : {cable::Experiment::a, cable::Experiment::b}) {
    for (const unsigned seed : stockbridge::testing::scaled<std::vector<unsigned>>({7, 10}, {7})) {
      const ExperimentMeasurement m = measure(e, 0.01, seed);
      const GlobalIdentification fit = identify_fit(m, options());
      EXPECT_LE(fit.error, relative_l1_error(truth(scaled_resolution()), 0.0, m) * (1.0 + 1e-9));
      expect_cable(fit, 2.8, 20.0, 0.7, 0.02, e == cable::Experiment::a ? 0.02 : 0.05, 0.02);
    }
  }
}

// The four steps are biased by the stick zones (docs/identification.md): measured
// without noise, (a) ei +0.8 %, c -0.1 %, h -3.6 %; (b) ei -1.0 %, c -5.1 %, h +6.3 %.
// Those are the figures of the full resolution at any scale (coarser data shift them:
// with 200 samples per cycle c from (b) is -11 %); the four steps cost one simulation.
TEST(GlobalIdentification, FourStepWithinItsBias) {
  const Resolution full;
  expect_cable(identify_four_step(measure(cable::Experiment::a, 0.0, 7, full), options(full)), 2.8, 20.0, 0.7, 0.015,
               0.01, 0.05);
  expect_cable(identify_four_step(measure(cable::Experiment::b, 0.0, 7, full), options(full)), 2.8, 20.0, 0.7, 0.02,
               0.07, 0.08);
  // The bias is real: the fit's error is far below the four-step's.
  const ExperimentMeasurement m = measure(cable::Experiment::b, 0.0);
  EXPECT_GT(identify_four_step(m, options()).error, 100.0 * identify_fit(m, options()).error);
}

TEST(GlobalIdentification, RejectsUnusableRecords) {
  ExperimentMeasurement m = measure(cable::Experiment::a, 0.0);
  const std::size_t kept = static_cast<std::size_t>(scaled_resolution().points_per_cycle) * 3 / 8;
  m.prescribed.resize(kept);  // less than one cycle after the first extreme
  m.measured.resize(kept);
  EXPECT_THROW(identify_fit(m, options()), InvalidParameter);
  GlobalIdentificationOptions bad = options();
  bad.length = 0.0;
  EXPECT_THROW(identify_fit(measure(cable::Experiment::a, 0.0), bad), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::identification

namespace stockbridge::identification {
namespace {

// The Bouc-Wen law fitted to a Bouc-Wen cable's cycles of experiment (a) and (b)
// (12 sections, 100 samples a cycle, measured and fitted alike, 2000 evaluations a
// run) gives its numbers back within 5e-3 (from (b) EI_max and chi0 are the least
// determined: 0.15 % and 0.18 % off when the evaluations run out). Checked with the
// full resolution (40 sections, the cycle command's record of (a), 4000 evaluations
// a run): within 1.5e-5, 13 000 simulations.
TEST(GlobalIdentificationBoucWen, FitRecoversABoucWenCable) {
  const Resolution r{12, 100};
  const cable::CableDescription bouc_wen = cable::CableDescription::uniform(*cable::find_section_law("bouc-wen"), 0.3, r.sections, {2.5, 25.0, 0.03});
  for (const cable::Experiment e : {cable::Experiment::a, cable::Experiment::b}) {
    cable::Cantilever cantilever{cable::Cable(bouc_wen)};
    const cable::ExperimentRecord record =
        cable::run_experiment(cantilever, {e, e == cable::Experiment::a ? 0.01 : 0.08, 2, r.points_per_cycle});
    ExperimentMeasurement m;
    m.experiment = e;
    for (const cable::ExperimentSample& s : record.samples) {
      m.prescribed.push_back(e == cable::Experiment::a ? s.deflection : s.rotation);
      m.measured.push_back(e == cable::Experiment::a ? s.tip_force : s.clamp_moment);
    }
    GlobalIdentificationOptions o = options(r);
    o.law = cable::find_section_law("bouc-wen");
    o.max_evaluations = 2000;
    const GlobalIdentification fit = identify_fit(m, o);
    ASSERT_EQ(fit.cable.law, cable::find_section_law("bouc-wen"));
    const char* name = e == cable::Experiment::a ? "(a)" : "(b)";
    EXPECT_NEAR(fit.cable.number("ei_min").at(0.0), 2.5, 5e-3 * 2.5) << name;
    EXPECT_NEAR(fit.cable.number("ei_max").at(0.0), 25.0, 5e-3 * 25.0) << name;
    EXPECT_NEAR(fit.cable.number("chi0").at(0.0), 0.03, 5e-3 * 0.03) << name;
    EXPECT_LT(fit.error, 1e-3) << name;
  }
}

}  // namespace
}  // namespace stockbridge::identification
