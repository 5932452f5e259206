// Identification from a measured damper impedance: exact recovery from curves the
// model computes with known parameters, recovery at 1 % complex noise with
// standard errors that cover the truth, what a curve that never slips does not
// determine, the clamp mass, the curves' grouping, and the least-squares core's
// statistics against closed forms.

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "identification/least_squares.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/requests/impedance_fit_request.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::identification {
namespace {

using damper::DamperDescription;

/// The verification damper (two identical arms) on a coarse cable (12 sections:
/// the data come from the same model, so the mesh does not matter) with `cable`'s
/// parameters.
DamperDescription impedance_test_damper(double ei, std::vector<std::pair<double, double>> jenkin, double clamp_mass = 0.7) {
  DamperDescription d;
  d.clamp_mass = clamp_mass;
  for (const char* name : {"left", "right"}) {
    damper::ArmDescription a = testing::sauter_arm(12);
    a.name = name;
    a.cable = cable::CableDescription::uniform(0.1875, 12, ei, jenkin);
    d.arms.push_back(a);
  }
  return d;
}

/// The model's Z of `truth` at `points` log-spaced frequencies over 4-60 Hz (the
/// arms' slip and stick resonances, 7.5 and 19 Hz, and beyond) at each velocity;
/// optionally with complex Gaussian noise of RMS `noise` |Z|.
ImpedanceMeasurement measured(const DamperDescription& truth, const std::vector<double>& velocities, int points,
                              double noise = 0.0, unsigned seed = 1) {
  const damper::Damper damper(truth);
  ImpedanceMeasurement m;
  for (const double v : velocities) {
    for (const double f : damper::log_spaced(4.0, 60.0, points)) {
      m.points.push_back({damper::Excitation::from_velocity(f, v), 0.0});
    }
  }
  const std::vector<damper::ImpedancePoint> z = model_impedance(damper, m, {});
  std::mt19937 random(seed);
  std::normal_distribution<double> gaussian(0.0, noise / std::sqrt(2.0));
  for (std::size_t i = 0; i < z.size(); ++i) {
    EXPECT_TRUE(z[i].converged()) << z[i].failure;
    const double scale = std::abs(z[i].impedance);
    m.points[i].impedance = z[i].impedance + (noise > 0.0 ? std::complex<double>(gaussian(random), gaussian(random)) * scale : 0.0);
  }
  return m;
}

double relative_error(double value, double truth) { return std::abs(value / truth - 1.0); }

/// Frequencies per velocity: fewer under the sanitizers (STOCKBRIDGE_TEST_SCALE=
/// short), where each model run costs 20 times more; noise-free curves still
/// determine every parameter from four.
int points_per_curve(int full) { return testing::scaled(full, 4); }

TEST(ImpedanceIdentification, RecoversOneElementExactlyFromNoiseFreeCurves) {
  const ImpedanceMeasurement m = measured(impedance_test_damper(2.8, {{20.0, 0.7}}), {0.05, 0.2}, points_per_curve(8));
  const ImpedanceIdentification fit = identify_impedance(impedance_test_damper(3.0, {{17.0, 0.8}}), m, {});
  ASSERT_EQ(fit.cables.size(), 1u);
  EXPECT_LT(relative_error(fit.cables[0].ei, 2.8), 1e-5);
  EXPECT_LT(relative_error(fit.cables[0].jenkin[0].c, 20.0), 1e-5);
  EXPECT_LT(relative_error(fit.cables[0].jenkin[0].h, 0.7), 1e-5);
  EXPECT_LT(fit.rms_relative_error, 1e-6);
  EXPECT_EQ(fit.not_converged, 0);
  EXPECT_EQ(fit.fit.termination, Termination::converged) << brief_report(fit.fit);
  EXPECT_GE(fit.fit.jacobians, 1);
  for (const ParameterEstimate& p : fit.parameters) EXPECT_TRUE(p.determined) << p.name;
  EXPECT_TRUE(fit.notes.empty()) << fit.notes.front();
  // Every arm gets the type's parameters; the fitted points are the model's.
  EXPECT_EQ(fit.damper.arms[1].cable.jenkin[0].h.at(0.0), fit.cables[0].jenkin[0].h);
  ASSERT_EQ(fit.fitted.size(), m.points.size());
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    EXPECT_LT(std::abs(fit.fitted[i].impedance - m.points[i].impedance), 1e-5 * std::abs(m.points[i].impedance));
  }
}

TEST(ImpedanceIdentification, RecoversTwoElementsExactlyFromNoiseFreeCurves) {
  // Two elements of distinct slip curvatures (h/c = 0.0033 and 0.035 1/m), from one
  // element's starting values spread over two.
  if (testing::short_tests()) GTEST_SKIP() << "six starts on five parameters: the Release build runs it";
  const ImpedanceMeasurement m = measured(impedance_test_damper(2.8, {{60.0, 0.2}, {20.0, 0.7}}), {0.05, 0.2}, 12);
  ImpedanceIdentificationOptions options;
  options.elements = 2;
  const ImpedanceIdentification fit = identify_impedance(impedance_test_damper(2.8, {{70.0, 0.8}}), m, options);
  const section::MasingParameters& p = fit.cables[0];
  ASSERT_EQ(p.jenkin.size(), 2u);
  EXPECT_LT(relative_error(p.ei, 2.8), 1e-4);
  EXPECT_LT(relative_error(p.jenkin[0].c, 60.0), 1e-4);  // sorted by slip curvature
  EXPECT_LT(relative_error(p.jenkin[0].h, 0.2), 1e-4);
  EXPECT_LT(relative_error(p.jenkin[1].c, 20.0), 1e-4);
  EXPECT_LT(relative_error(p.jenkin[1].h, 0.7), 1e-4);
  EXPECT_EQ(fit.parameters[1].name, "jenkin[0].c");
  EXPECT_EQ(fit.parameters[4].name, "jenkin[1].h");
}

TEST(ImpedanceIdentification, RecoversWithinTwoPercentAtOnePercentNoiseWithHonestStandardErrors) {
  if (testing::short_tests()) GTEST_SKIP() << "a statistical check of code the exact recoveries cover";
  const DamperDescription truth = impedance_test_damper(2.8, {{20.0, 0.7}});
  for (const unsigned seed : {1u}) {
    const ImpedanceMeasurement m = measured(truth, {0.05, 0.2}, 12, 0.01, seed);
    const ImpedanceIdentification fit = identify_impedance(impedance_test_damper(3.6, {{14.0, 1.0}}), m, {});
    const double values[] = {2.8, 20.0, 0.7};
    ASSERT_EQ(fit.parameters.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      const ParameterEstimate& p = fit.parameters[i];
      EXPECT_LT(relative_error(p.value, values[i]), 0.02) << p.name << " seed " << seed;
      EXPECT_LT(std::abs(p.value - values[i]), 4.0 * p.standard_error) << p.name << " seed " << seed;
      EXPECT_TRUE(p.determined) << p.name;
    }
    // The residual scatter is the noise's: sqrt(S / N) about 1 % (N complex points).
    EXPECT_NEAR(fit.rms_relative_error, 0.01, 0.003);
  }
}

TEST(ImpedanceIdentification, ACurveThatNeverSlipsLeavesHUndeterminedButTheStickStiffness) {
  // At 0.2 mm/s the clamp curvatures stay far below the slip curvature h / c.
  const ImpedanceMeasurement m = measured(impedance_test_damper(2.8, {{20.0, 0.7}}), {0.0002}, points_per_curve(12));
  const ImpedanceIdentification fit = identify_impedance(impedance_test_damper(3.6, {{14.0, 1.0}}), m, {});
  ASSERT_EQ(fit.parameters.size(), 3u);
  EXPECT_EQ(fit.parameters[2].name, "jenkin[0].h");
  EXPECT_FALSE(fit.parameters[2].determined);
  EXPECT_TRUE(std::isinf(fit.parameters[2].standard_error));
  // ei and c apart are not determined either; their sum is, exactly.
  EXPECT_FALSE(fit.parameters[0].determined);
  EXPECT_FALSE(fit.parameters[1].determined);
  ASSERT_EQ(fit.stick_stiffness.size(), 1u);
  EXPECT_TRUE(fit.stick_stiffness[0].determined);
  EXPECT_LT(relative_error(fit.stick_stiffness[0].value, 22.8), 1e-6);
  bool says_never_slips = false;
  for (const std::string& note : fit.notes) says_never_slips |= note.find("never slips") != std::string::npos;
  EXPECT_TRUE(says_never_slips);
}

TEST(ImpedanceIdentification, FitsTheClampMass) {
  const ImpedanceMeasurement m = measured(impedance_test_damper(2.8, {{20.0, 0.7}}, 0.7), {0.05, 0.2}, points_per_curve(6));
  ImpedanceIdentificationOptions options;
  options.fit_clamp_mass = true;
  const ImpedanceIdentification fit = identify_impedance(impedance_test_damper(3.0, {{18.0, 0.75}}, 0.4), m, options);
  EXPECT_NEAR(fit.clamp_mass, 0.7, 1e-5);
  EXPECT_EQ(fit.parameters.back().name, "clamp.mass");
  EXPECT_EQ(fit.parameters.back().unit, "kg");
  EXPECT_NEAR(fit.damper.clamp_mass, 0.7, 1e-5);
  EXPECT_LT(relative_error(fit.cables[0].jenkin[0].h, 0.7), 1e-5);
}

TEST(ImpedanceIdentification, PointsTheModelCannotConvergeCountAsMisfitNotAsFailures) {
  const ImpedanceMeasurement m = measured(impedance_test_damper(2.8, {{20.0, 0.7}}), {0.2}, 2);
  ImpedanceIdentificationOptions options;
  options.solver.energy_tolerance = 1e-300;  // no point is trusted
  options.max_jacobians = 1;
  const ImpedanceIdentification fit = identify_impedance(impedance_test_damper(3.0, {{16.0, 0.8}}), m, options);
  EXPECT_EQ(fit.not_converged, 2);
  EXPECT_NEAR(fit.misfit, 2.0, 1e-12);  // each point as Z = 0: |r|^2 = 1
}

TEST(ImpedanceIdentification, ArmsWithDifferentCablesAreDifferentTypes) {
  DamperDescription d = impedance_test_damper(2.8, {{20.0, 0.7}});
  EXPECT_EQ(cable_types(d), (std::vector<std::size_t>{0, 0}));
  d.arms[1].cable.length = 0.15;  // a shorter arm of the same cable: the same type
  EXPECT_EQ(cable_types(d), (std::vector<std::size_t>{0, 0}));
  d.arms[1].cable.ei = cable::Profile::constant(3.0);
  EXPECT_EQ(cable_types(d), (std::vector<std::size_t>{0, 1}));
}

TEST(ImpedanceIdentification, TwoCableTypesAreFittedApartAndNamedByTheirArm) {
  if (testing::short_tests()) GTEST_SKIP() << "six parameters from six starts: the Release build runs it";
  DamperDescription truth = impedance_test_damper(2.8, {{20.0, 0.7}});
  truth.arms[1].cable = cable::CableDescription::uniform(0.15, 12, 4.0, {{30.0, 1.1}});
  DamperDescription start = truth;
  start.arms[0].cable = cable::CableDescription::uniform(0.1875, 12, 3.0, {{18.0, 0.8}});
  start.arms[1].cable = cable::CableDescription::uniform(0.15, 12, 3.6, {{33.0, 1.0}});
  const ImpedanceIdentification fit = identify_impedance(start, measured(truth, {0.05, 0.2}, points_per_curve(8)), {});
  ASSERT_EQ(fit.cables.size(), 2u);
  EXPECT_LT(relative_error(fit.cables[0].jenkin[0].h, 0.7), 1e-4);
  EXPECT_LT(relative_error(fit.cables[1].jenkin[0].h, 1.1), 1e-4);
  EXPECT_LT(relative_error(fit.cables[1].ei, 4.0), 1e-4);
  EXPECT_EQ(fit.parameters[0].name, "arm[0].cable.ei");
  EXPECT_EQ(fit.parameters[3].name, "arm[1].cable.ei");
}

TEST(ImpedanceIdentification, GroupsPointsIntoCurvesByTheHeldAmplitudeInFrequencyOrder) {
  ImpedanceMeasurement m;
  m.points = {{damper::Excitation::from_velocity(20.0, 0.2), 1.0},  {damper::Excitation::from_velocity(10.0, 0.05), 1.0},
              {damper::Excitation::from_velocity(5.0, 0.201), 1.0}, {damper::Excitation::from_velocity(7.0, 0.05), 1.0}};
  EXPECT_EQ(measured_curves(m), (std::vector<std::vector<std::size_t>>{{3, 1}, {2, 0}}));
  m.held = damper::HeldAmplitude::displacement;  // X = V / W: all four differ
  EXPECT_EQ(measured_curves(m).size(), 4u);
}

TEST(ImpedanceIdentification, RefusesProfilesAndTooFewPointsNamingThem) {
  const ImpedanceMeasurement m = measured(impedance_test_damper(2.8, {{20.0, 0.7}}), {0.2}, 4);
  DamperDescription start = impedance_test_damper(2.8, {{20.0, 0.7}});
  start.arms[1].cable.jenkin[0].h = cable::Profile::table({0.0, 0.1}, {0.7, 0.6}, "h");
  EXPECT_THROW(
      {
        try {
          identify_impedance(start, m, {});
        } catch (const InvalidParameter& e) {
          EXPECT_NE(std::string(e.what()).find("arm[1].cable.jenkin[0].h: a profile"), std::string::npos) << e.what();
          throw;
        }
      },
      InvalidParameter);
  ImpedanceMeasurement one = m;
  one.points.resize(1);
  EXPECT_THROW(identify_impedance(impedance_test_damper(2.8, {{20.0, 0.7}}), one, {}), InvalidParameter);
  one.points[0].impedance = 0.0;
  EXPECT_THROW(one.validate(), InvalidParameter);
}

// Issue 49: a |Z| of 1e-310 (a unit mistake, or a cell mistyped) made every residual
// (divided by |Z|) infinite, no start better than another, and the polish ran from an
// empty point: identify impedance segfaulted. A measurement is now refused at the
// point whose |Z| or frequency lies outside the magnitudes a description may hold,
// however it was given (a sheet read under --allow-unusual, Python's arrays).
TEST(ImpedanceIdentification, RefusesAMagnitudeNoDamperHasNamingThePointInsteadOfCrashing) {
  ImpedanceMeasurement m;
  for (const double v : {0.05, 0.2}) {
    for (const double f : {10.0, 20.0, 30.0}) m.points.push_back({damper::Excitation::from_velocity(f, v), {5.0, 100.0}});
  }
  const DamperDescription start = impedance_test_damper(2.8, {{20.0, 0.7}});
  const auto refusal = [&](const ImpedanceMeasurement& bad) {
    try {
      identify_impedance(start, bad, {});
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  ImpedanceMeasurement tiny = m;
  tiny.points[3].impedance = {1e-310, 0.0};
  EXPECT_EQ(refusal(tiny), "point 4: |Z| = 1e-310 N s/m: expected a value from 1e-12 to 1e+12; one outside is a unit "
                           "mistake");
  // Python's arrays (identify_impedance(frequency=, velocity=, z=)) are refused as they are taken.
  std::vector<double> f, v;
  std::vector<std::complex<double>> z;
  for (const MeasuredImpedance& p : tiny.points) {
    f.push_back(p.excitation.frequency_hz);
    v.push_back(p.excitation.velocity_amplitude());
    z.push_back(p.impedance);
  }
  try {
    requests::measurement_from_arrays(f, v, true, z);
    ADD_FAILURE() << "z[3] = 1e-310 accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find("z[3] = 1e-310 + 0 i N s/m: expected finite, with |Z| from 1e-12"),
              std::string::npos) << e.what();
  }
  ImpedanceMeasurement huge = m;
  huge.points[1].impedance = {0.0, 1e13};
  EXPECT_NE(refusal(huge).find("point 2: |Z| = 10000000000000 N s/m: expected a value from 1e-12 to 1e+12"), std::string::npos) << refusal(huge);
  ImpedanceMeasurement slow = m;
  slow.points[0].excitation = {1e-300, 1e-3};
  EXPECT_NE(refusal(slow).find("point 1: frequency_hz = 1e-300: expected a value from 1e-12"), std::string::npos)
      << refusal(slow);
  // The smallest magnitude admitted fits (its residuals are large but finite).
  ImpedanceMeasurement smallest = m;
  smallest.points[3].impedance = {smallest_magnitude, 0.0};
  ImpedanceIdentificationOptions bounded;
  bounded.max_jacobians = 1;
  const ImpedanceIdentification fit = identify_impedance(start, smallest, bounded);
  EXPECT_TRUE(std::isfinite(fit.misfit));
  EXPECT_EQ(fit.fitted.size(), m.points.size());
}

/// The test damper with Bouc-Wen cables (12 sections) of ei_min, ei_max, chi0.
DamperDescription bouc_wen_test_damper(double ei_min, double ei_max, double chi0) {
  DamperDescription d = impedance_test_damper(2.8, {{20.0, 0.7}});
  for (damper::ArmDescription& a : d.arms) a.cable = cable::CableDescription::uniform(*cable::find_section_law("bouc-wen"), 0.1875, 12, {ei_min, ei_max, chi0});
  return d;
}

TEST(ImpedanceIdentificationBoucWen, RecoversTheLawsNumbersExactlyFromNoiseFreeCurves) {
  // The Masing test cable's equivalent (stick 22.8, slip 2.8 N m^2, hysteretic moment
  // 20 x 0.035 = 0.7 N m), from a start 5-10 % off.
  const ImpedanceMeasurement m = measured(bouc_wen_test_damper(2.8, 22.8, 0.035), {0.05, 0.2}, 6);
  const ImpedanceIdentification fit = identify_impedance(bouc_wen_test_damper(2.95, 21.0, 0.038), m, {});
  EXPECT_EQ(fit.law, cable::find_section_law("bouc-wen"));
  EXPECT_TRUE(fit.cables.empty());
  ASSERT_EQ(fit.law_cables.size(), 1u);
  EXPECT_LT(relative_error(fit.law_cables[0][0], 2.8), 1e-5);
  EXPECT_LT(relative_error(fit.law_cables[0][1], 22.8), 1e-5);
  EXPECT_LT(relative_error(fit.law_cables[0][2], 0.035), 1e-5);
  EXPECT_LT(fit.rms_relative_error, 1e-6);
  EXPECT_EQ(fit.fit.termination, Termination::converged) << brief_report(fit.fit);
  ASSERT_EQ(fit.parameters.size(), 3u);
  EXPECT_EQ(fit.parameters[0].name, "ei_min");
  EXPECT_EQ(fit.parameters[1].name, "ei_max");
  EXPECT_EQ(fit.parameters[2].name, "chi0");
  EXPECT_EQ(fit.parameters[2].unit, "1/m");
  for (const ParameterEstimate& p : fit.parameters) EXPECT_TRUE(p.determined) << p.name;
  EXPECT_TRUE(fit.stick_stiffness.empty());
  // Every arm's cable is the fitted Bouc-Wen law.
  for (const damper::ArmDescription& a : fit.damper.arms) {
    EXPECT_EQ(a.cable.law, cable::find_section_law("bouc-wen"));
    EXPECT_EQ(a.cable.number("chi0").at(0.0), fit.law_cables[0][2]);
  }
}

TEST(ImpedanceIdentificationBoucWen, TheDampersScalingIsANullDirection) {
  // Cable lengths and offsets times s, inertias times s^2, ei_min and ei_max times
  // s^3 and chi0 (a curvature) times s^-2: the same Z ...
  const double s = 1.3;
  const DamperDescription truth = bouc_wen_test_damper(2.8, 22.8, 0.035);
  DamperDescription scaled = bouc_wen_test_damper(2.8 * s * s * s, 22.8 * s * s * s, 0.035 / (s * s));
  for (std::size_t k = 0; k < scaled.arms.size(); ++k) {
    scaled.arms[k].cable.length = s * truth.arms[k].cable.length;
    scaled.arms[k].offset = s * truth.arms[k].offset;
    scaled.arms[k].inertia = s * s * truth.arms[k].inertia;
  }
  const ImpedanceMeasurement m = measured(truth, {0.2}, points_per_curve(6));
  const std::vector<damper::ImpedancePoint> z = model_impedance(damper::Damper(scaled), m, {});
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    EXPECT_LT(std::abs(z[i].impedance - m.points[i].impedance), 1e-6 * std::abs(m.points[i].impedance)) << i;
  }
  // ... which the fit, with both arms' lengths, offsets and inertias free, reports.
  if (testing::short_tests()) GTEST_SKIP() << "nine parameters: the Release build runs the fit";
  ImpedanceIdentificationOptions options;
  options.free = {"arm.left.cable.length",  "arm.left.inertia",  "arm.left.offset",
                  "arm.right.cable.length", "arm.right.inertia", "arm.right.offset"};
  options.max_jacobians = 2;
  const ImpedanceIdentification fit = identify_impedance(truth, m, options);
  EXPECT_LT(fit.rms_relative_error, 1e-6);
  EXPECT_TRUE(std::any_of(fit.notes.begin(), fit.notes.end(), [](const std::string& n) {
    return n.starts_with("a damper scaled by any s (cable lengths and offsets times s, inertias times s^2, ei_min and "
                         "ei_max times s^3, chi0 times s^-2)");
  }));
  for (const ParameterEstimate& p : fit.parameters) {
    EXPECT_FALSE(p.determined) << p.name;
    EXPECT_TRUE(std::isinf(p.standard_error)) << p.name;
  }
}

TEST(ImpedanceIdentificationBoucWen, RefusesElementsMixedLawsAndAStartWithoutHysteresis) {
  const ImpedanceMeasurement m = measured(bouc_wen_test_damper(2.8, 22.8, 0.035), {0.2}, 4);
  auto message = [&](const DamperDescription& start, const ImpedanceIdentificationOptions& options) -> std::string {
    try {
      identify_impedance(start, m, options);
    } catch (const InvalidParameter& e) {
      return e.what();
    }
    return "(accepted)";
  };
  ImpedanceIdentificationOptions two;
  two.elements = 2;
  EXPECT_EQ(message(bouc_wen_test_damper(2.8, 22.8, 0.035), two).rfind("elements = 2: Jenkin elements belong to the "
                                                                         "Masing law", 0),
            0u);
  DamperDescription mixed = bouc_wen_test_damper(2.8, 22.8, 0.035);
  mixed.arms[1].cable = impedance_test_damper(2.8, {{20.0, 0.7}}).arms[1].cable;
  EXPECT_EQ(message(mixed, {}).rfind("arm[1].cable.law = \"masing\" but arm[0]'s is \"bouc-wen\"", 0), 0u)
      << message(mixed, {});
  EXPECT_EQ(message(bouc_wen_test_damper(2.8, 2.8, 0.035), {}).rfind("arm[0].cable.ei_max = 2.8 N m^2: expected a "
                                                                     "starting value above ei_min",
                                                                     0),
            0u)
      << message(bouc_wen_test_damper(2.8, 2.8, 0.035), {});
}

TEST(ImpedanceIdentificationBoucWen, ArmsOfOneLawWithOtherNumbersAreOtherTypes) {
  DamperDescription d = bouc_wen_test_damper(2.8, 22.8, 0.035);
  EXPECT_EQ(cable_types(d), (std::vector<std::size_t>{0, 0}));
  d.arms[1].cable.number("chi0") = cable::Profile::constant(0.04);
  EXPECT_EQ(cable_types(d), (std::vector<std::size_t>{0, 1}));
}

// The least-squares core on problems with closed-form answers.

/// r(x) = A x - b, linear: one Levenberg-Marquardt step solves it.
class LinearProblem : public least_squares::Problem {
 public:
  LinearProblem(Eigen::MatrixXd a, Eigen::VectorXd b) : a_(std::move(a)), b_(std::move(b)) {}
  int variables() const override { return static_cast<int>(a_.cols()); }
  int residual_count() const override { return static_cast<int>(a_.rows()); }
  Eigen::VectorXd residuals(const Eigen::VectorXd& x) override { return a_ * x - b_; }
  Eigen::MatrixXd jacobian(const Eigen::VectorXd&) override { return a_; }

 private:
  Eigen::MatrixXd a_;
  Eigen::VectorXd b_;
};

TEST(LeastSquares, SolvesALinearProblemAndGivesItsClassicalCovariance) {
  Eigen::MatrixXd a(4, 2);
  a << 1, 0, 1, 1, 1, 2, 1, 3;  // a straight line through 4 points
  const Eigen::VectorXd b = Eigen::Vector4d(1.0, 2.9, 5.1, 7.0);
  LinearProblem problem(a, b);
  const least_squares::Run run = least_squares::levenberg_marquardt(problem, Eigen::Vector2d::Zero(), 20);
  const Eigen::Vector2d expected = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  EXPECT_NEAR(run.x(0), expected(0), 1e-9);
  EXPECT_NEAR(run.x(1), expected(1), 1e-9);
  const double s = (a * expected - b).squaredNorm();
  EXPECT_NEAR(run.sum_of_squares, s, 1e-12);
  const least_squares::Statistics st = least_squares::statistics(a, s, 0.01);
  const Eigen::Matrix2d c = (a.transpose() * a).inverse();
  EXPECT_NEAR(st.standard_error(1), std::sqrt(s / 2.0 * c(1, 1)), 1e-12);
  EXPECT_NEAR(st.resolution(0), 0.01 * std::sqrt(c(0, 0)), 1e-12);
  EXPECT_NEAR(st.correlation(0, 1), c(0, 1) / std::sqrt(c(0, 0) * c(1, 1)), 1e-12);
  EXPECT_NEAR(st.sensitivity(1), std::sqrt(14.0 / 4.0), 1e-12);
  EXPECT_NEAR(st.resolution_of(Eigen::Vector2d(1.0, 1.0)), 0.01 * std::sqrt(c.sum()), 1e-12);
  EXPECT_EQ(run.summary.termination, Termination::converged);
  EXPECT_NEAR(run.summary.residual, std::sqrt(s), 1e-12);
  // One iteration allowed: the run says it was cut short.
  const least_squares::Run cut = least_squares::levenberg_marquardt(problem, Eigen::Vector2d(-50.0, 40.0), 1, 1e-3);
  EXPECT_EQ(cut.summary.termination, Termination::max_iterations);
  EXPECT_EQ(cut.summary.jacobians, 1);
}

TEST(LeastSquares, FindsTheNullSpaceOfAZeroColumnAndOfEqualColumns) {
  Eigen::MatrixXd a(3, 3);
  a << 1, 1, 0, 2, 2, 0, 0.5, 0.5, 0;  // columns 0 and 1 equal, column 2 zero; rank 1
  const least_squares::Statistics st = least_squares::statistics(a, 1.0, 0.01);
  EXPECT_EQ(st.null_space.cols(), 2);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(st.in_null_space[static_cast<std::size_t>(i)]) << i;
  EXPECT_TRUE(std::isinf(st.standard_error(2)));
  EXPECT_TRUE(std::isnan(st.correlation(0, 1)));
  // Their sum is what the data see: determined.
  EXPECT_TRUE(std::isfinite(st.resolution_of(Eigen::Vector3d(1.0, 1.0, 0.0))));
  EXPECT_TRUE(std::isinf(st.resolution_of(Eigen::Vector3d(1.0, -1.0, 0.0))));
}

TEST(LeastSquares, TheStandardErrorsAreAtTheStatedScatterWhereTheResidualsScatterLess) {
  // The straight line above with a floor on the residual scatter: below the
  // residuals' own it changes nothing, above it the errors are the floor's.
  Eigen::MatrixXd a(4, 2);
  a << 1, 0, 1, 1, 1, 2, 1, 3;
  const Eigen::Matrix2d c = (a.transpose() * a).inverse();
  const double s = 0.02;  // residual scatter sqrt(0.02 / 2) = 0.1
  const least_squares::Statistics below = least_squares::statistics(a, s, 0.01, 0.05);
  EXPECT_NEAR(below.residual_scatter, 0.1, 1e-12);
  EXPECT_NEAR(below.error_scatter, 0.1, 1e-12);
  EXPECT_NEAR(below.standard_error(0), 0.1 * std::sqrt(c(0, 0)), 1e-12);
  const least_squares::Statistics above = least_squares::statistics(a, s, 0.01, 0.3);
  EXPECT_EQ(above.rank, 2);
  EXPECT_NEAR(above.error_scatter, 0.3, 1e-12);
  EXPECT_NEAR(above.standard_error(1), 0.3 * std::sqrt(c(1, 1)), 1e-12);
  EXPECT_NEAR(above.standard_error_of(Eigen::Vector2d(1.0, 1.0)), 0.3 * std::sqrt(c.sum()), 1e-12);
}

TEST(LeastSquares, TheChiSquareTestEqualsItsClosedFormsAtTwoAndFourDegreesOfFreedom) {
  // Survival functions: exp(-x/2) for 2 degrees of freedom, exp(-x/2)(1 + x/2) for 4;
  // the 99 % quantile for 2 is -2 ln 0.01.
  for (const double x : {0.5, 3.0, 9.0, 20.0, 60.0}) {
    const least_squares::ChiSquareTest two = least_squares::chi_square_test(x, 2, 0.01);
    EXPECT_NEAR(two.p_value / std::exp(-x / 2.0), 1.0, 1e-12) << x;
    EXPECT_EQ(two.significant, std::exp(-x / 2.0) < 0.01) << x;
    const least_squares::ChiSquareTest four = least_squares::chi_square_test(x, 4, 0.01);
    EXPECT_NEAR(four.p_value / (std::exp(-x / 2.0) * (1.0 + x / 2.0)), 1.0, 1e-12) << x;
  }
  const least_squares::ChiSquareTest two = least_squares::chi_square_test(1.0, 2, 0.01);
  EXPECT_NEAR(two.critical, -2.0 * std::log(0.01), 1e-12);
  EXPECT_EQ(two.degrees_of_freedom, 2);
  EXPECT_EQ(two.level, 0.01);
  // At the critical value itself p is the level; just above it the test is significant.
  EXPECT_NEAR(least_squares::chi_square_test(two.critical, 2, 0.01).p_value, 0.01, 1e-14);
  EXPECT_TRUE(least_squares::chi_square_test(two.critical * 1.001, 2, 0.01).significant);
  EXPECT_FALSE(least_squares::chi_square_test(two.critical * 0.999, 2, 0.01).significant);
  // Far in the tail p underflows to 0, still significant; no degrees of freedom: no test.
  EXPECT_TRUE(least_squares::chi_square_test(1e6, 10, 0.01).significant);
  const least_squares::ChiSquareTest none = least_squares::chi_square_test(3.0, 0, 0.01);
  EXPECT_TRUE(std::isnan(none.p_value));
  EXPECT_FALSE(none.significant);
}

TEST(LeastSquares, AnExtraVariablesStepIsTheAugmentedLinearProblemsSolution) {
  // A straight line fitted to points that lie on a parabola: the quadratic's column,
  // one Gauss-Newton step from the line's optimum, gives the parabola's fit exactly
  // (a linear problem): its coefficient, the line's coefficients' change and the
  // misfit it removes.
  Eigen::MatrixXd a(5, 2);
  a << 1, 0, 1, 1, 1, 2, 1, 3, 1, 4;
  Eigen::VectorXd quadratic(5);
  quadratic << 0, 1, 4, 9, 16;
  Eigen::VectorXd b(5);
  b << 1.0, 1.6, 3.1, 5.4, 8.2;
  const Eigen::Vector2d line = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  const Eigen::VectorXd r = a * line - b;
  Eigen::MatrixXd augmented(5, 3);
  augmented << a, quadratic;
  const Eigen::Vector3d parabola = (augmented.transpose() * augmented).ldlt().solve(augmented.transpose() * b);
  const least_squares::ExtraVariable extra = least_squares::extra_variable(a, r, quadratic);
  EXPECT_NEAR(extra.step, parabola(2), 1e-12);
  EXPECT_NEAR(extra.shift(0), parabola(0) - line(0), 1e-12);
  EXPECT_NEAR(extra.shift(1), parabola(1) - line(1), 1e-12);
  EXPECT_NEAR(extra.reduction, r.squaredNorm() - (augmented * parabola - b).squaredNorm(), 1e-12);
  // A column the line's already spans removes nothing.
  const least_squares::ExtraVariable spanned = least_squares::extra_variable(a, r, a.col(0) + 2.0 * a.col(1));
  EXPECT_EQ(spanned.reduction, 0.0);
  EXPECT_EQ(spanned.step, 0.0);
}

}  // namespace
}  // namespace stockbridge::identification
