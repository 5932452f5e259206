// The cable with the Bouc-Wen section law (MODEL.md section 13): its moment-driven
// sections against the section law's closed form, the exact flexibility, energy
// dissipated against the work done at the tip, the mirror, and convergence in
// sections across slenderpy's zone boundaries.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "stockbridge/cable/bouc_wen_cable_law.hpp"
#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"
#include "cable/exp_minus_one.hpp"
#include "stockbridge/damper/periodic_cable.hpp"

namespace stockbridge::cable {
namespace {

constexpr double kMessengerLength = 0.1875;
const section::BoucWenParameters kNumbers{2.5, 25.0, 0.03};  // slenderpy's middle zone

CableDescription uniform_cable(int sections = 40) {
  return CableDescription::uniform(*cable::find_section_law("bouc-wen"), kMessengerLength, sections, {kNumbers.ei_min, kNumbers.ei_max, kNumbers.chi0});
}

/// slenderpy's messenger: three zones with ramps of 1e-7 m between them.
CableDescription slenderpy_cable(int sections) {
  CableDescription d = CableDescription::uniform(*cable::find_section_law("bouc-wen"), kMessengerLength, sections, {1.0, 1.0, 1.0});
  const double a = 0.2 * kMessengerLength, b = 0.92 * kMessengerLength, r = 1e-7;
  const std::vector<double> s{a, a + r, b - r, b};
  d.number("ei_max") = Profile::table(s, {40.0, 25.0, 25.0, 40.0}, "ei_max");
  d.number("ei_min") = Profile::table(s, {5.0, 2.5, 2.5, 5.0}, "ei_min");
  d.number("chi0") = Profile::table(s, {0.15, 0.03, 0.03, 0.15}, "chi0");
  return d;
}

// Under a pure moment (F = 0) every section carries T: the cable is the section law
// driven by its moment. Through loading, a reversal and reloading each section's
// curvature is the one at which the closed-form law (driven by curvature along the
// same monotone stretches) carries T, the rotation is l kappa and the energy
// dissipated l times the section's.
TEST(BoucWenCable, UnderAPureMomentEverySectionIsTheClosedFormLaw) {
  Cantilever cantilever{Cable(uniform_cable())};
  section::BoucWenState section = section::BoucWenState::virgin(kNumbers);
  for (const double moment : {0.5, 1.2, -0.4, -1.5, 0.3}) {
    cantilever.set_trial_loads(moment, 0.0);
    cantilever.commit();
    const CableState& state = cantilever.committed();
    const double kappa = state.curvature[7];
    for (const double k : state.curvature) ASSERT_NEAR(k, kappa, 1e-14 * std::abs(kappa));
    section = section::bouc_wen_update(kNumbers, section, kappa);
    EXPECT_NEAR(section.moment, moment, 1e-13 * std::abs(moment)) << "T = " << moment;
    EXPECT_NEAR(state.hysteretic[3], section.eta, 1e-13);
    EXPECT_NEAR(state.tangent[3], section.tangent, 1e-12 * section.tangent);
    EXPECT_NEAR(state.rotation, kMessengerLength * kappa, 1e-13 * std::abs(state.rotation));
    EXPECT_NEAR(state.dissipated, kMessengerLength * section.dissipated, 1e-12 * kMessengerLength * section.dissipated);
  }
}

// A short step's dissipation is summed from terms that cancel to round-off: whatever
// the step, from the virgin state and after a reversal, the cable's dissipation
// never goes down (a random cable of the fuzzer lost 1e-26 J from 0 here).
TEST(BoucWenCable, AShortStepNeverDissipatesLess) {
  Cantilever cantilever{Cable(slenderpy_cable(9))};
  for (int committed = 0; committed < 3; ++committed) {
    const double from = cantilever.committed().dissipated;
    for (double rotation = 1e-3; rotation > 1e-16; rotation *= 0.37) {
      for (const double sign : {1.0, -1.0}) {
        ASSERT_TRUE(cantilever.set_trial_rotation(cantilever.committed().rotation + sign * rotation).converged());
        EXPECT_GE(cantilever.trial().dissipated, from) << "step " << sign * rotation << " after " << committed;
      }
    }
    ASSERT_TRUE(cantilever.set_trial_rotation(committed == 1 ? -0.02 : 0.03).converged());
    cantilever.commit();
  }
}

// A state shifted in its periodic coordinates (T, F, eta_i: CableLaw::shift) is a
// state again: every section carries T - F s_i of the shifted loads (the law's moment
// is linear), the tip kinematics are the curvatures' integrals, and a section pushed
// beyond eta's bounds saturates. The Masing law offers no coordinates.
TEST(BoucWenCable, AShiftedStateIsAStateWithinEtasBounds) {
  Cantilever cantilever{Cable(slenderpy_cable(40))};
  ASSERT_TRUE(cantilever.set_trial_tip(0.004, 0.03).converged());
  cantilever.commit();
  const Cable& cable = cantilever.cable();
  const auto& law = dynamic_cast<const BoucWenCableLaw&>(cable.law());
  const auto n = static_cast<Eigen::Index>(cable.sections());
  ASSERT_EQ(static_cast<Eigen::Index>(law.periodic_coordinates(cable)), n + 2);
  Eigen::VectorXd dz(n + 2);
  dz(0) = 0.05;
  dz(1) = -0.3;
  for (Eigen::Index i = 0; i < n; ++i) dz(i + 2) = 0.02 * std::sin(0.3 * static_cast<double>(i));
  dz(5) = 3.0;  // beyond the bound
  CableState state = cantilever.committed();
  ASSERT_TRUE(law.shift(cable, state, dz));
  Eigen::VectorXd before, after;
  law.coordinates(cantilever.committed(), before);
  law.coordinates(state, after);
  const auto& s = cable.positions();
  const auto& w = cable.weights();
  double rotation = 0.0, deflection = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double moment = law.ei_min(k) * state.curvature[k] +
                          (law.ei_max(k) - law.ei_min(k)) * law.chi0(k) * state.hysteretic[k];
    ASSERT_NEAR(moment, state.clamp_moment - state.tip_force * s[k], 1e-12 * std::abs(state.clamp_moment)) << i;
    EXPECT_NEAR(after(i + 2), std::clamp(before(i + 2) + dz(i + 2), -1.0, 1.0), 1e-15) << i;
    rotation += w[k] * state.curvature[k];
    deflection += w[k] * (cable.length() - s[k]) * state.curvature[k];
  }
  EXPECT_EQ(after(5), 1.0);
  EXPECT_NEAR(after(0), before(0) + dz(0), 1e-15);
  EXPECT_NEAR(after(1), before(1) + dz(1), 1e-14);
  EXPECT_NEAR(state.rotation, rotation, 1e-12 * std::abs(rotation));
  EXPECT_NEAR(state.deflection, deflection, 1e-12 * std::abs(deflection));
  dz(0) = std::numeric_limits<double>::quiet_NaN();
  CableState refused = cantilever.committed();
  EXPECT_FALSE(law.shift(cable, refused, dz));
  EXPECT_EQ(refused.clamp_moment, cantilever.committed().clamp_moment);
  const Cable masing(CableDescription::uniform(kMessengerLength, 40, 2.5, {{100.0, 0.1}}));
  EXPECT_EQ(masing.law().periodic_coordinates(masing), 0u);
}

/// Two tip steps, the second a reversal: the committed state from which the
/// derivative tests load on in the direction of the last step.
void drive_through_a_reversal(Cantilever& cantilever) {
  for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.01, 0.08}, {-0.004, -0.03}}) {
    ASSERT_TRUE(cantilever.set_trial_tip(x, phi).converged());
    cantilever.commit();
  }
}

// d(phi, x)/d(T, F) equals central differences of the exact load evaluation.
TEST(BoucWenCable, FlexibilityMatchesFiniteDifferences) {
  Cantilever cantilever{Cable(slenderpy_cable(40))};
  ASSERT_NO_FATAL_FAILURE(drive_through_a_reversal(cantilever));
  const CableState base = cantilever.committed();
  // Continued loading in the direction of the last step (the tangent is one-sided).
  const double dT = -0.05, dF = -0.3;
  cantilever.set_trial_loads(base.clamp_moment + dT, base.tip_force + dF);
  const CableState at = cantilever.trial();
  const double h = 1e-6;
  auto kinematics = [&](double t, double f) {
    cantilever.set_trial_loads(base.clamp_moment + t, base.tip_force + f);
    return Eigen::Vector2d(cantilever.trial().rotation, cantilever.trial().deflection);
  };
  // Steps that keep every section loading the same way as from base to `at`.
  const Eigen::Vector2d by_t =
      (kinematics(dT * (1 + h), dF) - kinematics(dT * (1 - h), dF)) / (2 * h * dT);
  const Eigen::Vector2d by_f =
      (kinematics(dT, dF * (1 + h)) - kinematics(dT, dF * (1 - h))) / (2 * h * dF);
  EXPECT_NEAR(by_t(0), at.flexibility(0, 0), 1e-7 * std::abs(at.flexibility(0, 0)));
  EXPECT_NEAR(by_t(1), at.flexibility(1, 0), 1e-7 * std::abs(at.flexibility(1, 0)));
  EXPECT_NEAR(by_f(0), at.flexibility(0, 1), 1e-7 * std::abs(at.flexibility(0, 1)));
  EXPECT_NEAR(by_f(1), at.flexibility(1, 1), 1e-7 * std::abs(at.flexibility(1, 1)));
}

// The flexibility's change (CableState::flexibility_change) is the derivative of the
// flexibility along the loads' change: for d = (dT, dF), (G(p + h d) - G(p - h d)) d / 2h
// = sum w c dM^2 [1; l - s], dM = dT - dF s, in each direction that keeps every
// section loading the same way; and it turns with the mirror.
TEST(BoucWenCable, FlexibilityChangeMatchesFiniteDifferencesOfTheFlexibility) {
  Cantilever cantilever{Cable(slenderpy_cable(40))};
  ASSERT_NO_FATAL_FAILURE(drive_through_a_reversal(cantilever));
  const CableState base = cantilever.committed();
  const double dT = -0.05, dF = -0.3;
  cantilever.set_trial_loads(base.clamp_moment + dT, base.tip_force + dF);
  const CableState at = cantilever.trial();
  const Eigen::Matrix<double, 2, 3>& c = at.flexibility_change;
  ASSERT_GT(c.norm(), 0.0);
  const double h = 1e-5;
  for (const Eigen::Vector2d& d : {Eigen::Vector2d(dT, dF), Eigen::Vector2d(dT, 0.0), Eigen::Vector2d(0.0, dF),
                                   Eigen::Vector2d(dT, 0.5 * dF)}) {
    auto flexibility_times_d = [&](double t) {
      cantilever.set_trial_loads(at.clamp_moment + t * d(0), at.tip_force + t * d(1));
      return Eigen::Vector2d(cantilever.trial().flexibility * d);
    };
    const Eigen::Vector2d by_difference = (flexibility_times_d(h) - flexibility_times_d(-h)) / (2 * h);
    const Eigen::Vector2d from_sums(c(0, 0) * d(0) * d(0) - 2 * c(0, 1) * d(0) * d(1) + c(0, 2) * d(1) * d(1),
                                    c(1, 0) * d(0) * d(0) - 2 * c(1, 1) * d(0) * d(1) + c(1, 2) * d(1) * d(1));
    EXPECT_NEAR(from_sums(0), by_difference(0), 1e-6 * std::abs(by_difference(0))) << d.transpose();
    EXPECT_NEAR(from_sums(1), by_difference(1), 1e-6 * std::abs(by_difference(1))) << d.transpose();
  }
  CableState mirrored = at;
  mirrored.mirror();
  EXPECT_EQ(mirrored.flexibility_change, -at.flexibility_change);
}

// With the second order (Chebyshev's steps, Cantilever::solve) a cycle of the tip
// sampled as harmonic balance samples it (144 a period at its default 17 harmonics)
// takes about two cable evaluations a sample, the predictor and one correction (the
// first-order steps took 3.25), each sample within the tolerance; a third where a
// section turns.
TEST(BoucWenCable, SecondOrderStepsLandASampleInOneCorrection) {
  Cantilever cantilever{Cable(slenderpy_cable(40))};
  const int samples = 144;
  int evaluations = 0, solves = 0;
  for (int cycle = 0; cycle < 3; ++cycle) {
    for (int j = 1; j <= samples; ++j) {
      const double t = 2.0 * std::numbers::pi * j / samples;
      const StateDetermination solve = cantilever.set_trial_tip(0.006 * std::sin(t), 0.05 * std::sin(t + 0.4));
      ASSERT_TRUE(solve.converged()) << brief_report(solve);
      EXPECT_LE(solve.residual, cantilever.options().tolerance * 0.05 * 1.01);
      cantilever.commit();
      if (cycle > 0) {
        evaluations += solve.evaluations;
        ++solves;
      }
    }
  }
  EXPECT_LE(static_cast<double>(evaluations) / solves, 2.4);
}

// Around a closed path of the tip the work done on the cable, int F dx + Q dphi,
// is the energy its sections dissipated (the stored energy returns to its start
// once the cycle is steady): the trapezoid rule on 4000 steps, to 1e-5.
TEST(BoucWenCable, DissipationOverASteadyCycleIsTheWorkDoneAtTheTip) {
  Cantilever cantilever{Cable(slenderpy_cable(60))};
  const int steps = 4000;
  const double x_amplitude = 0.006, phi_amplitude = 0.05;
  double work = 0.0, dissipated_before = 0.0;
  for (int cycle = 0; cycle < 40; ++cycle) {
    if (cycle == 39) {
      work = 0.0;
      dissipated_before = cantilever.committed().dissipated;
    }
    for (int j = 1; j <= steps; ++j) {
      const double t = 2.0 * M_PI * j / steps;
      const CableState from = cantilever.committed();
      ASSERT_TRUE(cantilever.set_trial_tip(x_amplitude * std::sin(t), phi_amplitude * std::sin(t + 0.4)).converged());
      const CableState& to = cantilever.trial();
      const double f = 0.5 * (from.tip_force + to.tip_force);
      const double q = 0.5 * (from.tip_moment(kMessengerLength) + to.tip_moment(kMessengerLength));
      work += f * (to.deflection - from.deflection) + q * (to.rotation - from.rotation);
      cantilever.commit();
    }
  }
  const double dissipated = cantilever.committed().dissipated - dissipated_before;
  EXPECT_GT(dissipated, 0.0);
  EXPECT_NEAR(work, dissipated, 1e-5 * dissipated);
}

// The law is odd: from the mirror image of a state, the negative path gives the
// negative loads.
TEST(BoucWenCable, TheMirroredStateAnswersTheNegativePath) {
  Cantilever a{Cable(slenderpy_cable(40))};
  for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.01, 0.05}, {-0.003, 0.02}}) {
    ASSERT_TRUE(a.set_trial_tip(x, phi).converged());
    a.commit();
  }
  Cantilever b = a;
  b.mirror();
  ASSERT_TRUE(a.set_trial_tip(0.004, -0.01).converged());
  ASSERT_TRUE(b.set_trial_tip(-0.004, 0.01).converged());
  EXPECT_NEAR(b.trial().clamp_moment, -a.trial().clamp_moment, 1e-12);
  EXPECT_NEAR(b.trial().tip_force, -a.trial().tip_force, 1e-11);
  for (std::size_t i = 0; i < a.trial().hysteretic.size(); ++i) {
    EXPECT_NEAR(b.trial().hysteretic[i], -a.trial().hysteretic[i], 1e-13);
  }
}

// slenderpy's zones jump at 0.2 l and 0.92 l; the cable integrates each zone with
// its own rule, so the tip loads of a cycle converge fast in the number of sections:
// 40 sections within 3e-5 of 1280, each doubling at least 2x closer. (Checked: with
// one rule over the whole length, across the jumps, 40 sections were 3 % off and
// 320 were 0.8 %, no better than 160.)
TEST(BoucWenCable, LoadsConvergeInSectionsAcrossZoneBoundaries) {
  auto loads = [](int sections) {
    Cantilever cantilever{Cable(slenderpy_cable(sections))};
    for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.008, 0.06}, {-0.008, -0.06}, {0.008, 0.06}}) {
      EXPECT_TRUE(cantilever.set_trial_tip(x, phi).converged());
      cantilever.commit();
    }
    return Eigen::Vector2d(cantilever.committed().tip_force, cantilever.committed().clamp_moment);
  };
  const Eigen::Vector2d finest = loads(1280);
  double previous = std::numeric_limits<double>::infinity();
  for (const int n : {40, 80, 160, 320}) {
    const double error = (loads(n) - finest).norm() / finest.norm();
    EXPECT_LT(error, n == 40 ? 3e-5 : previous / 2.0) << n << " sections";
    previous = error;
  }
}

TEST(BoucWenCable, TheLawsNumbersAreCheckedAndNamed) {
  CableDescription d = uniform_cable();
  d.number("ei_max") = Profile::constant(2.0);
  try {
    Cable{d};
    FAIL() << "ei_max below ei_min was accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "ei_max");
    EXPECT_NE(std::string(e.what()).find("below ei_min"), std::string::npos) << e.what();
  }
  d = uniform_cable();
  d.ei = Profile::constant(2.8);
  try {
    Cable{d};
    FAIL() << "ei on a Bouc-Wen cable was accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.field(), "ei");
    EXPECT_NE(std::string(e.what()).find("ei_min, ei_max and chi0"), std::string::npos) << e.what();
  }
  d = uniform_cable();
  d.number("chi0") = Profile::constant(0.0);
  EXPECT_THROW(Cable{d}, InvalidParameter);
}

// The moment-driven solve is exact: the travel it returns carries the excess.
TEST(BoucWenCable, TravelSolvesTheMomentEquationToRoundOff) {
  for (const double eta : {-0.999, -0.3, 0.0, 0.6, 1.0}) {
    for (const double excess : {1e-9, 1e-3, 0.05, 0.8, 30.0, -1e-6, -0.4, -5.0}) {
      const BoucWenTravel travel = bouc_wen_travel(2.5, 22.5, 0.03, eta, excess);
      const double u = travel.u;
      EXPECT_NEAR(travel.decay_minus_one, std::expm1(-u), 4e-16 * (1.0 + std::abs(std::expm1(-u))));
      const double a = 1.0 - (excess > 0 ? 1.0 : -1.0) * eta;
      const double carried = 0.03 * (2.5 * u - 22.5 * a * std::expm1(-u));
      EXPECT_NEAR(carried, std::abs(excess), 4e-15 * std::abs(excess) + 1e-300) << eta << " " << excess;
    }
  }
}

// Where the solve starts does not change its result beyond round-off: from the
// travel of a nearby excess (within 1e-3 of the target there: the series ends the
// solve without an exponential; within 1e-6 of the travel, its short form to r^2),
// and from one far off (the start is not taken).
TEST(BoucWenCable, TravelDoesNotDependOnWhereItsSolveStarts) {
  for (const double eta : {-0.999, -0.3, 0.0, 0.6, 1.0}) {
    for (const double excess : {1e-9, 1e-3, 0.05, 0.8, 30.0, -1e-6, -0.4, -5.0}) {
      const BoucWenTravel cold = bouc_wen_travel(2.5, 22.5, 0.03, eta, excess);
      for (const double nearby : {1.0 + 1e-9, 1.0 - 3e-7, 1.0 + 1e-7, 1.0 - 1e-6, 1.0 + 3e-4, 0.5, 3.0}) {
        const BoucWenTravel start = bouc_wen_travel(2.5, 22.5, 0.03, eta, excess * nearby);
        const BoucWenTravel warm = bouc_wen_travel(2.5, 22.5, 0.03, eta, excess, start);
        EXPECT_NEAR(warm.u, cold.u, 4e-15 * cold.u + 1e-300) << eta << " " << excess << " " << nearby;
        EXPECT_NEAR(warm.decay_minus_one, cold.decay_minus_one, 4e-16 * (1.0 + std::abs(cold.decay_minus_one)));
      }
    }
  }
}

// The sections are solved four at a time: whatever the count (a group short of four
// at the end; each zone takes at least a section), every section carries the moment
// T - F s_i by the law, M = EI_min kappa + (EI_max - EI_min) chi0 eta, and the tip
// kinematics are the sums of its curvatures.
TEST(BoucWenCable, EverySectionCarriesItsMomentWhateverTheGroupsOfFour) {
  for (const int sections : {2, 3, 5, 7, 13}) {
    const CableDescription d = slenderpy_cable(sections);
    const Cable cable(d);
    Cantilever cantilever{Cable(d)};
    for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.006, 0.05}, {-0.002, 0.01}, {0.003, -0.04}}) {
      ASSERT_TRUE(cantilever.set_trial_tip(x, phi).converged()) << sections;
      cantilever.commit();
      const CableState& state = cantilever.committed();
      double rotation = 0.0, deflection = 0.0;
      for (std::size_t i = 0; i < cable.sections(); ++i) {
        const double s = cable.positions()[i], w = cable.weights()[i];
        const double at = d.profile_position(s);
        const double ei_min = d.number("ei_min").at(at), ei_max = d.number("ei_max").at(at);
        const double moment =
            ei_min * state.curvature[i] + (ei_max - ei_min) * d.number("chi0").at(at) * state.hysteretic[i];
        const double expected = state.clamp_moment - state.tip_force * s;
        EXPECT_NEAR(moment, expected, 1e-12 * std::abs(state.clamp_moment)) << sections << " sections, section " << i;
        rotation += w * state.curvature[i];
        deflection += w * (kMessengerLength - s) * state.curvature[i];
      }
      EXPECT_NEAR(state.rotation, rotation, 1e-14 * std::abs(phi)) << sections;
      EXPECT_NEAR(state.deflection, deflection, 1e-14 * std::abs(x)) << sections;
    }
  }
}

// The section loops are built for the x86-64 baseline and for AVX2 with FMA; a law
// made with BoucWenKernels::baseline runs the baseline's. Both builds give the same
// loads along a path and the same exact sensitivities of a period, to round-off (the
// AVX2 build fuses multiplies and adds).
TEST(BoucWenCable, TheBaselineAndAvx2BuildsAgree) {
  const CableDescription d = slenderpy_cable(41);  // a group short of four at the end
  const Cable baseline_cable(d, [](const CableDescription& description, std::span<const double> positions,
                                   std::span<const double>) {
    return std::make_shared<const BoucWenCableLaw>(description, positions, BoucWenKernels::baseline);
  });
  const Cable own_cable(d);
  const auto& baseline_law = dynamic_cast<const BoucWenCableLaw&>(baseline_cable.law());
  const auto& own_law = dynamic_cast<const BoucWenCableLaw&>(own_cable.law());
  EXPECT_FALSE(baseline_law.uses_avx2());
#if defined(__x86_64__)
  EXPECT_EQ(own_law.uses_avx2(), __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"));
#endif
  if (!own_law.uses_avx2()) GTEST_SKIP() << "this processor has no AVX2 with FMA: one build only";

  // A period of tip motion, its derivatives with respect to the coefficients of
  // (sin, cos) in x and phi, after a settling pass.
  const int samples = 64;
  Eigen::Matrix2Xd path(2, samples);
  Eigen::MatrixXd basis(samples, 2);
  for (int j = 0; j < samples; ++j) {
    const double t = 2.0 * std::numbers::pi * j / samples;
    basis(j, 0) = std::sin(t);
    basis(j, 1) = std::cos(t);
    path(0, j) = 0.006 * basis(j, 0) + 0.001 * basis(j, 1);
    path(1, j) = 0.04 * basis(j, 0) - 0.01 * basis(j, 1);
  }
  damper::PeriodicCable baseline(baseline_cable, CantileverOptions{});
  damper::PeriodicCable own(own_cable, CantileverOptions{});
  Eigen::MatrixXd baseline_sensitivity, own_sensitivity;
  const damper::PeriodicCableResult a = baseline.evaluate(path, 3, nullptr, &basis, &baseline_sensitivity);
  const damper::PeriodicCableResult b = own.evaluate(path, 3, nullptr, &basis, &own_sensitivity);
  ASSERT_TRUE(a.summary.converged());
  ASSERT_TRUE(b.summary.converged());
  const double load_scale = a.period.loads.cwiseAbs().maxCoeff();
  EXPECT_LT((a.period.loads - b.period.loads).cwiseAbs().maxCoeff(), 1e-11 * load_scale);
  EXPECT_NEAR(a.period.dissipated, b.period.dissipated, 1e-11 * a.period.dissipated);
  const double sensitivity_scale = baseline_sensitivity.cwiseAbs().maxCoeff();
  EXPECT_LT((baseline_sensitivity - own_sensitivity).cwiseAbs().maxCoeff(), 1e-9 * sensitivity_scale);
  for (std::size_t i = 0; i < own_cable.sections(); ++i) {
    EXPECT_NEAR(baseline.final_state().hysteretic[i], own.final_state().hysteretic[i], 1e-11) << i;
  }
}

// Newton on the periodic state: the derivatives of the end state's coordinates
// z = (T, F, eta_i) with respect to the path's coefficients and the start state's
// coordinates (PeriodicStart::newton) against central finite differences, over a
// half period and its mirror from a state the path left (not a periodic one), at
// an amplitude where some sections slip and some stay near stick.
TEST(BoucWenCable, ThePeriodicStatesDerivativesMatchFiniteDifferences) {
  const Cable cable(slenderpy_cable(12));
  const CableLaw& law = cable.law();
  const auto m = static_cast<Eigen::Index>(law.periodic_coordinates(cable));
  ASSERT_EQ(m, 14);
  const int samples = 32;  // a half period
  Eigen::MatrixXd basis(samples, 2);
  for (int j = 0; j < samples; ++j) {
    const double t = std::numbers::pi * j / samples;
    basis(j, 0) = std::sin(t);
    basis(j, 1) = std::cos(t);
  }
  const Eigen::Vector4d q0(0.004, 0.03, 0.001, -0.008);  // (x, phi) of sin, then of cos
  auto path_of = [&](const Eigen::Vector4d& q) {
    Eigen::Matrix2Xd path(2, samples);
    for (int j = 0; j < samples; ++j) {
      path(0, j) = q(0) * basis(j, 0) + q(2) * basis(j, 1);
      path(1, j) = q(1) * basis(j, 0) + q(3) * basis(j, 1);
    }
    return path;
  };
  damper::PeriodicCable periodic(cable, CantileverOptions{});
  // A start the path has shaped but not settled: one pass from virgin at 0.7 q.
  ASSERT_TRUE(periodic.evaluate(path_of(0.7 * q0), 1, nullptr, nullptr, nullptr, damper::PathSymmetry::half_wave,
                                damper::PeriodicStart::newton)
                  .summary.converged());
  const CableState start = periodic.final_state();
  auto end_coordinates = [&](const Eigen::Vector4d& q, const CableState& from) {
    const damper::PeriodicCableResult r = periodic.evaluate(path_of(q), 1, &from, nullptr, nullptr,
                                                            damper::PathSymmetry::half_wave,
                                                            damper::PeriodicStart::newton);
    EXPECT_TRUE(r.summary.converged());
    Eigen::VectorXd z;
    law.coordinates(periodic.final_state(), z);
    return z;
  };
  Eigen::MatrixXd sensitivity;
  const damper::PeriodicCableResult exact = periodic.evaluate(
      path_of(q0), 1, &start, &basis, &sensitivity, damper::PathSymmetry::half_wave, damper::PeriodicStart::newton);
  ASSERT_TRUE(exact.summary.converged());
  ASSERT_EQ(exact.state_jacobian.rows(), m);
  ASSERT_EQ(exact.state_jacobian.cols(), 4 + m);
  Eigen::VectorXd z_start, z_end;
  law.coordinates(start, z_start);
  law.coordinates(periodic.final_state(), z_end);
  for (Eigen::Index c = 0; c < 4 + m; ++c) {
    Eigen::VectorXd plus, minus;
    bool one_sided = false;
    if (c < 4) {
      const double h = 1e-7 * q0.cwiseAbs().maxCoeff();
      plus = end_coordinates(q0 + h * Eigen::Vector4d::Unit(c), start);
      minus = end_coordinates(q0 - h * Eigen::Vector4d::Unit(c), start);
      plus = (plus - minus) / (2.0 * h);
    } else {
      // Central differences; one-sided away from eta's bound where a section is
      // within the step of saturation (the shift stops it there).
      const Eigen::Index k = c - 4;
      const double h = 1e-7 * (k < 2 ? std::max(std::abs(z_start(k)), 0.1) : 1.0);
      const bool near_bound = k >= 2 && 1.0 - std::abs(z_start(k)) < 2.0 * h;
      one_sided = near_bound;
      const double up_step = near_bound ? -std::copysign(h, z_start(k)) : h;
      const double down_step = near_bound ? 0.0 : -h;
      CableState up = start, down = start;
      ASSERT_TRUE(law.shift(cable, up, up_step * Eigen::VectorXd::Unit(m, k)));
      ASSERT_TRUE(law.shift(cable, down, down_step * Eigen::VectorXd::Unit(m, k)));
      plus = (end_coordinates(q0, up) - end_coordinates(q0, down)) / (up_step - down_step);
    }
    // One-sided differences (a saturated section's eta) carry an error of order h;
    // each row's differences, the round-off of its coordinate over h (the loads').
    const double relative = one_sided ? 5e-3 : 1e-5;
    const double column_scale = exact.state_jacobian.col(c).cwiseAbs().maxCoeff();
    for (Eigen::Index r = 0; r < m; ++r) {
      const double tolerance = relative * column_scale + 1e-8 * std::max(1.0, std::abs(z_end(r)));
      EXPECT_NEAR(exact.state_jacobian(r, c), plus(r), tolerance) << "row " << r << ", column " << c;
    }
  }
}

// At fixed coefficients, Newton on the periodic state, z <- z - (G_z - I)^-1 G with G
// = z_end - z, converges quadratically from a state one pass from virgin (where
// repeating passes settles geometrically).
TEST(BoucWenCable, NewtonOnThePeriodicStateConvergesQuadratically) {
  const Cable cable(slenderpy_cable(12));
  const CableLaw& law = cable.law();
  const int samples = 32;
  Eigen::MatrixXd basis(samples, 1);
  Eigen::Matrix2Xd path(2, samples);
  for (int j = 0; j < samples; ++j) {
    basis(j, 0) = std::sin(std::numbers::pi * j / samples);
    path.col(j) = Eigen::Vector2d(0.004, 0.03) * basis(j, 0);
  }
  damper::PeriodicCable periodic(cable, CantileverOptions{});
  ASSERT_TRUE(periodic.evaluate(path, 1, nullptr, nullptr, nullptr, damper::PathSymmetry::half_wave,
                                damper::PeriodicStart::newton)
                  .summary.converged());
  CableState start = periodic.final_state();
  std::vector<double> gaps;
  for (int iteration = 0; iteration < 6; ++iteration) {
    Eigen::MatrixXd sensitivity;
    const damper::PeriodicCableResult r = periodic.evaluate(path, 1, &start, &basis, &sensitivity,
                                                            damper::PathSymmetry::half_wave,
                                                            damper::PeriodicStart::newton);
    ASSERT_TRUE(r.summary.converged());
    Eigen::VectorXd z_start, z_end;
    law.coordinates(start, z_start);
    law.coordinates(periodic.final_state(), z_end);
    const Eigen::VectorXd gap = z_end - z_start;
    gaps.push_back(gap.lpNorm<Eigen::Infinity>());
    Eigen::MatrixXd d = r.state_jacobian.rightCols(gap.size());
    d.diagonal().array() -= 1.0;
    ASSERT_TRUE(law.shift(cable, start, Eigen::VectorXd(-d.partialPivLu().solve(gap))));
  }
  EXPECT_LT(gaps[3], 1e-10 * gaps[0]);
}

// (GCC notes that functions returning four-lane types are called differently with and
// without AVX; here they are inline.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

// e^x - 1 on four lanes, against the library's, relative, from round-off-small
// arguments to the range where it is -1.
TEST(BoucWenCable, TheLanesExponentialIsTheLibrarysToAnUlpOrTwo) {
  std::vector<double> xs{0.0, -1e-300, -1e-17, -3e-9, -1e-4, -0.1, -0.3465, -0.3466, -0.5, -1.0,
                         -2.5, -10.0, -37.0, -40.0, -100.0, -699.0, -700.0, -745.0, -1e6};
  for (double x = -1e-6; x > -60.0; x *= 1.37) xs.push_back(x);
  for (std::size_t i = 0; i < xs.size(); i += 4) {
    Lanes x{};
    for (std::size_t k = 0; k < 4 && i + k < xs.size(); ++k) x[k] = xs[i + k];
    const Lanes y = exp_minus_one_of_nonpositive(x);
    for (std::size_t k = 0; k < 4 && i + k < xs.size(); ++k) {
      const double expected = std::expm1(x[k]);
      EXPECT_NEAR(y[k], expected, 3e-16 * std::abs(expected)) << "x = " << x[k];
    }
  }
}

}  // namespace
}  // namespace stockbridge::cable
