// Identification from a vendor's damper sheet (MODEL.md 11): the damper's arm
// masses and cable lengths fitted with its cable (ImpedanceIdentificationOptions::
// free) from |Z| at three clamp velocities over 5-60 Hz with 1 % scatter, the start
// 15-20 % off in each; the paths of `free` checked, naming the path; the poor-fit flag.

#include <cmath>
#include <complex>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::identification {
namespace {

using damper::DamperDescription;

/// examples/asymmetric_damper.toml on 12-section cables (the sheet comes from the same
/// model, so the mesh does not matter): a long arm (1.4 kg on 0.22 m) and a short one
/// (0.7 kg on 0.14 m), one cable.
DamperDescription asymmetric_damper(double long_mass, double long_length, double short_mass, double short_length,
                                    double ei, double c, double h) {
  DamperDescription d;
  d.clamp_mass = 0.6;
  damper::ArmDescription arm;
  arm.name = "long";
  arm.mass = long_mass;
  arm.inertia = 0.0035;
  arm.offset = 0.04;
  arm.cable = cable::CableDescription::uniform(long_length, 12, ei, {{c, h}});
  d.arms.push_back(arm);
  arm.name = "short";
  arm.mass = short_mass;
  arm.inertia = 0.0012;
  arm.offset = 0.025;
  arm.cable = cable::CableDescription::uniform(short_length, 12, ei, {{c, h}});
  d.arms.push_back(arm);
  return d;
}

const DamperDescription kTruth = asymmetric_damper(1.4, 0.22, 0.7, 0.14, 2.8, 20.0, 0.7);
/// The masses +18 % and -17 %, the lengths -16 % and +18 %, the cable guessed.
const DamperDescription kStart = asymmetric_damper(1.65, 0.185, 0.58, 0.165, 3.2, 26.0, 0.9);

/// The sheet: the model's Z of `truth` at `points` log-spaced frequencies over 5-60 Hz
/// at 0.05, 0.1 and 0.2 m/s, with complex Gaussian scatter of RMS `noise` |Z| (fixed seed).
ImpedanceMeasurement vendor_sheet(const DamperDescription& truth, int points, double noise) {
  const damper::Damper damper(truth);
  ImpedanceMeasurement m;
  for (const double v : {0.05, 0.1, 0.2}) {
    for (const double f : damper::log_spaced(5.0, 60.0, points)) m.points.push_back({damper::Excitation::from_velocity(f, v), 0.0});
  }
  const std::vector<damper::ImpedancePoint> z = model_impedance(damper, m, {});
  std::mt19937 random(61897);
  std::normal_distribution<double> gaussian(0.0, noise / std::sqrt(2.0));
  for (std::size_t i = 0; i < z.size(); ++i) {
    EXPECT_TRUE(z[i].converged()) << z[i].failure;
    m.points[i].impedance = z[i].impedance + std::complex<double>(gaussian(random), gaussian(random)) * std::abs(z[i].impedance);
  }
  return m;
}

const ParameterEstimate& estimate(const ImpedanceIdentification& fit, const std::string& name) {
  for (const ParameterEstimate& p : fit.parameters) {
    if (p.name == name) return p;
  }
  throw std::out_of_range("no parameter " + name);
}

/// The sheet with a lognormal scatter of RMS about `scatter` in |dZ| / |Z|: each Z
/// times exp(e_1 + i e_2), e_1 (log |Z|) and e_2 (the phase, rad) normal with
/// standard deviation scatter / sqrt(2) each (fixed seed).
ImpedanceMeasurement lognormal_vendor_sheet(const DamperDescription& truth, int points, double scatter, unsigned seed) {
  ImpedanceMeasurement m = vendor_sheet(truth, points, 0.0);
  std::mt19937 random(seed);
  std::normal_distribution<double> gaussian(0.0, scatter / std::sqrt(2.0));
  for (MeasuredImpedance& p : m.points) p.impedance *= std::exp(std::complex<double>(gaussian(random), gaussian(random)));
  return m;
}

/// The lack-of-fit cases' sheet: 8 frequencies per velocity (4 under the sanitizers), 1 % lognormal scatter.
const ImpedanceMeasurement& scattered_sheet() {
  static const ImpedanceMeasurement sheet = lognormal_vendor_sheet(kTruth, testing::scaled(8, 4), 0.01, 19);
  return sheet;
}

/// The cable alone fitted to scattered_sheet() from a guess (ei 3.2, c 26, h 0.9),
/// the damper's numbers the truth's but the long arm's inertia times `inertia_factor`.
ImpedanceIdentification cable_fit_with_long_inertia(double inertia_factor) {
  DamperDescription start = asymmetric_damper(1.4, 0.22, 0.7, 0.14, 3.2, 26.0, 0.9);
  start.arms[0].inertia *= inertia_factor;
  ImpedanceIdentificationOptions options;
  options.threads = 2;
  return identify_impedance(start, scattered_sheet(), options);
}

const ImpedanceIdentification& true_numbers_fit() {
  static const ImpedanceIdentification fit = cable_fit_with_long_inertia(1.0);
  return fit;
}

TEST(VendorSheet, TheTrueDampersFitShowsNoLackOfFitAndItsStandardErrorsCoverTheTruth) {
  const ImpedanceIdentification& fit = true_numbers_fit();
  const LackOfFit& l = fit.lack_of_fit;
  EXPECT_TRUE(l.assumed);
  EXPECT_EQ(l.scatter, default_scatter);
  // The statistic is 2 N (rms / scatter)^2 on 2N - 3 degrees of freedom.
  const double n = static_cast<double>(scattered_sheet().points.size());
  EXPECT_NEAR(l.statistic / (2.0 * n * std::pow(fit.rms_relative_error / 0.01, 2)), 1.0, 1e-12);
  EXPECT_EQ(l.degrees_of_freedom, static_cast<int>(2 * n) - 3);
  EXPECT_NEAR(l.ratio, 1.0, 0.35);
  EXPECT_FALSE(l.significant);
  EXPECT_GT(l.p_value, 0.05);
  EXPECT_LT(l.statistic, l.critical);
  EXPECT_TRUE(l.suspects.empty());  // computed only for a significant lack of fit
  EXPECT_TRUE(l.notes.empty());
  EXPECT_GE(l.error_inflation, 1.0);
  EXPECT_LT(l.error_inflation, 1.3);
  const std::pair<const char*, double> truth[] = {{"ei", 2.8}, {"jenkin[0].c", 20.0}, {"jenkin[0].h", 0.7}};
  for (const auto& [name, value] : truth) {
    const ParameterEstimate& p = estimate(fit, name);
    EXPECT_TRUE(p.determined) << name;
    EXPECT_TRUE(p.confounded_by.empty()) << name << ": " << p.confounded_by;
    EXPECT_LT(std::abs(p.value - value), 3.0 * p.standard_error) << name << " = " << p.value << " +- " << p.standard_error;
  }
}

TEST(VendorSheet, AnArmInertia19PercentOffIsALackOfFitThatNamesItFirstAndInflatesTheErrors) {
  // The long arm's inertia 19 % high and not fitted: the cable absorbs what it can
  // (ei a few % off, its standard error 0.1 % at the stated scatter); the misfit
  // is several times the scatter, which the test flags, naming the inertia.
  const ImpedanceIdentification fit = cable_fit_with_long_inertia(1.19);
  const LackOfFit& l = fit.lack_of_fit;
  EXPECT_TRUE(l.significant);
  EXPECT_LT(l.p_value, 1e-6);
  EXPECT_GT(l.statistic, l.critical);
  EXPECT_GT(l.ratio, 3.0);
  ASSERT_EQ(l.suspects.size(), 9u);  // two arms' mass, inertia, offset and length, and the clamp mass
  EXPECT_EQ(l.suspects[0].name, "arm.long.inertia");
  EXPECT_EQ(l.suspects[0].unit, "kg m^2");
  EXPECT_EQ(l.suspects[0].value, 0.0035 * 1.19);
  EXPECT_GT(l.suspects[0].misfit_reduction, 0.3);
  for (std::size_t k = 1; k < l.suspects.size(); ++k) {
    EXPECT_LE(l.suspects[k].misfit_reduction, l.suspects[k - 1].misfit_reduction) << l.suspects[k].name;
  }
  // Its suggested value lies toward the truth, 0.0035.
  EXPECT_LT(l.suspects[0].suggested_value, 0.0035 * 1.15);
  EXPECT_GT(l.suspects[0].suggested_value, 0.0035 * 0.85);
  // The standard errors carry the lack of fit: the residuals' own scatter, rms / sqrt(2)
  // per real residual, not the stated 1 %'s.
  EXPECT_GT(l.error_inflation, 3.0);
  const ImpedanceIdentification& right = true_numbers_fit();
  for (std::size_t i = 0; i < fit.parameters.size(); ++i) {
    const ParameterEstimate& p = fit.parameters[i];
    // standard error / (value x resolution at 1 %) = the scatter per real residual / 1 %.
    EXPECT_NEAR(p.standard_error / (p.value * p.resolution_at_1_percent), l.error_inflation / std::sqrt(2.0), 1e-9) << p.name;
    EXPECT_GT(p.standard_error, 2.0 * right.parameters[i].standard_error) << p.name;
  }
  // The cable's estimates hang on the inertia, and a note says by how much.
  EXPECT_EQ(estimate(fit, "ei").confounded_by, "arm.long.inertia");
  EXPECT_NE(estimate(fit, "ei").confounded_shift, 0.0);
  ASSERT_FALSE(l.notes.empty());
  EXPECT_NE(l.notes.front().find("were arm.long.inertia "), std::string::npos) << l.notes.front();
  // Below the 10 % limit (9 % here; 15 % on the sanitizers' 4 frequencies per
  // velocity): only the test against the scatter catches it.
  if (!testing::short_tests()) {
    EXPECT_FALSE(fit.poor_fit);
  }
}

TEST(VendorSheet, RecoversArmMassesCableLengthsAndTheCableWithinTwoPercent) {
  // 16 frequencies per velocity (8 under the sanitizers, where a model run costs 20
  // times more; the 1 % scatter then moves the estimates more, within the same 2 %).
  const ImpedanceMeasurement sheet = vendor_sheet(kTruth, testing::scaled(16, 8), 0.01);
  ImpedanceIdentificationOptions options;
  options.free = {"arm.long.mass", "arm.short.mass", "arm.long.cable.length", "arm.short.cable.length"};
  options.threads = 2;
  const ImpedanceIdentification fit = identify_impedance(kStart, sheet, options);
  const std::pair<const char*, double> truth[] = {
      {"ei", 2.8},           {"jenkin[0].c", 20.0},         {"jenkin[0].h", 0.7},           {"arm.long.mass", 1.4},
      {"arm.short.mass", 0.7}, {"arm.long.cable.length", 0.22}, {"arm.short.cable.length", 0.14}};
  ASSERT_EQ(fit.parameters.size(), 7u);
  for (const auto& [name, value] : truth) {
    const ParameterEstimate& p = estimate(fit, name);
    EXPECT_NEAR(p.value / value, 1.0, 0.02) << name;
    // The statistics say so: determined, the standard error covering the truth.
    EXPECT_TRUE(p.determined) << name;
    EXPECT_LT(std::abs(p.value - value), 4.0 * p.standard_error) << name << " +- " << p.standard_error;
    EXPECT_EQ(p.geometry, std::string(name).starts_with("arm.")) << name;
  }
  EXPECT_TRUE(fit.notes.empty()) << fit.notes.front();
  EXPECT_NEAR(fit.rms_relative_error, 0.01, 0.003);
  EXPECT_FALSE(fit.poor_fit);
  // The fitted damper holds the fitted numbers.
  EXPECT_EQ(fit.damper.arms[0].mass, estimate(fit, "arm.long.mass").value);
  EXPECT_EQ(fit.damper.arms[1].cable.length, estimate(fit, "arm.short.cable.length").value);
  EXPECT_EQ(fit.damper.arms[1].inertia, 0.0012);  // not fitted: the start's
}

TEST(VendorSheet, TheStartIsAPoorFitAboveTheLimit) {
  // The start's Z against the truth's, nothing fitted that could mend the geometry:
  // one iteration leaves it far off, a poor fit by the default 10 %.
  const ImpedanceMeasurement sheet = vendor_sheet(kTruth, 4, 0.0);
  ImpedanceIdentificationOptions options;
  options.max_jacobians = 1;
  const ImpedanceIdentification fit = identify_impedance(kStart, sheet, options);
  EXPECT_GT(fit.rms_relative_error, 0.1);
  EXPECT_TRUE(fit.poor_fit);
  EXPECT_EQ(fit.rms_limit, 0.1);
  if (testing::short_tests()) return;  // the same fit again: the Release build checks the limit moves
  options.rms_limit = 10.0;
  EXPECT_FALSE(identify_impedance(kStart, sheet, options).poor_fit);
}

TEST(VendorSheet, ASheetDoesNotDetermineTheDampersSizeWhereLengthsInertiasAndOffsetsAreAllFree) {
  // Lengths and offsets times s, inertias times s^2, ei and c times s^3, h times s:
  // the same Z. The statistics say so exactly (the direction is projected out of the
  // difference Jacobian), and a note says what to fix.
  if (testing::short_tests()) GTEST_SKIP() << "nine parameters from six starts: the Release build runs it";
  ImpedanceIdentificationOptions options;
  options.free = {"arm.long.cable.length", "arm.short.cable.length", "arm.long.inertia", "arm.short.inertia",
                  "arm.long.offset",       "arm.short.offset",       "arm.long.mass"};
  options.max_jacobians = 3;
  const ImpedanceIdentification fit = identify_impedance(kTruth, vendor_sheet(kTruth, 4, 0.0), options);
  for (const char* name : {"ei", "jenkin[0].c", "jenkin[0].h", "arm.long.cable.length", "arm.short.inertia", "arm.short.offset"}) {
    EXPECT_FALSE(estimate(fit, name).determined) << name;
    EXPECT_TRUE(std::isinf(estimate(fit, name).standard_error)) << name;
  }
  EXPECT_TRUE(estimate(fit, "arm.long.mass").determined);  // the masses do not scale
  bool says_scaled = false;
  for (const std::string& note : fit.notes) says_scaled |= note.find("a damper scaled by any s") != std::string::npos;
  EXPECT_TRUE(says_scaled);
}

TEST(VendorSheet, TwoIdenticalArmsMassesAreNotDeterminedApartAndArmsThatBecomeDistinctStartCold) {
  // Regression: a start with two identical arms is solved as one; its Jacobian column
  // for one arm's mass makes them two (a warm start from the one threw).
  DamperDescription twin = kTruth;
  twin.arms[1] = twin.arms[0];
  twin.arms[1].name = "twin";
  ImpedanceIdentificationOptions options;
  options.free = {"arm.long.mass", "arm.twin.mass"};
  options.max_jacobians = 2;
  const ImpedanceIdentification fit = identify_impedance(twin, vendor_sheet(twin, 4, 0.0), options);
  EXPECT_LT(fit.rms_relative_error, 1e-6);
  EXPECT_FALSE(estimate(fit, "arm.long.mass").determined);
  EXPECT_FALSE(estimate(fit, "arm.twin.mass").determined);
  EXPECT_TRUE(estimate(fit, "jenkin[0].h").determined);
}

/// The message of the InvalidParameter identify_impedance throws with `free` (empty if none).
std::string free_error(const std::vector<std::string>& free) {
  ImpedanceIdentificationOptions options;
  options.free = free;
  try {
    options.max_jacobians = 1;
    identify_impedance(kStart, vendor_sheet(kTruth, 4, 0.0), options);
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "free");
    return e.what();
  }
  return "";
}

TEST(VendorSheet, EachPathOfFreeIsCheckedAndNamed) {
  EXPECT_NE(free_error({"arm.middle.mass"}).find("free = arm.middle.mass: no arm is named 'middle' (the arms: long, short"),
            std::string::npos);
  EXPECT_NE(free_error({"arm.long.cable.ei"}).find("free = arm.long.cable.ei: a cable parameter"), std::string::npos);
  EXPECT_NE(free_error({"arm.long.colour"}).find("free = arm.long.colour: not a number the fit can free: expected clamp.mass"),
            std::string::npos);
  EXPECT_NE(free_error({"arm.long.mass", "arm[0].mass"}).find("free = arm[0].mass: given twice"), std::string::npos);
  EXPECT_NE(free_error({"clamp.mass", "clamp.mass"}).find("free = clamp.mass: given twice"), std::string::npos);
}

TEST(VendorSheet, FreeClampMassIsTheOldOptionAndOffsetsAreLinear) {
  // Noise-free: the numbers come back exactly, an offset through 0.
  DamperDescription truth = kTruth;
  truth.arms[1].offset = 0.005;
  DamperDescription start = truth;
  start.clamp_mass = 0.5;
  start.arms[1].offset = -0.01;
  ImpedanceIdentificationOptions options;
  options.free = {"arm[1].offset", "clamp.mass"};
  const ImpedanceIdentification fit = identify_impedance(start, vendor_sheet(truth, testing::scaled(6, 4), 0.0), options);
  ASSERT_EQ(fit.parameters.size(), 5u);
  EXPECT_EQ(fit.parameters[3].name, "arm.short.offset");
  EXPECT_EQ(fit.parameters[3].unit, "m");
  EXPECT_NEAR(fit.parameters[3].value, 0.005, 1e-6);
  EXPECT_EQ(fit.parameters[4].name, "clamp.mass");
  EXPECT_NEAR(fit.parameters[4].value, 0.6, 1e-6);
  EXPECT_LT(fit.rms_relative_error, 1e-6);
}

}  // namespace
}  // namespace stockbridge::identification
