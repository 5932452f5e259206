// The cable-law conformance suite (docs/architecture.md, "A third section law"):
// every registered section law, in a cable of the sauter damper's messenger, against
// what every law must give: its tangent (the cantilever's flexibility) against
// finite differences, oddness (the mirror), a steady cycle that settles, the energy
// it dissipates against the work done at the tip, its sensitivities (LoadSensitivity,
// through harmonic balance's Jacobian) against finite differences, and harmonic
// balance against time integration. A law registered without a case here fails.

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/cable/section_law_descriptor.hpp"
#include "stockbridge/damper/harmonic_balance.hpp"
#include "stockbridge/damper/steady_state.hpp"
#include "support/damper_fixtures.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::cable {
namespace {

constexpr double kConformanceLength = 0.1875;

/// A law's cable of the damper's size: constant numbers slipping within the tests'
/// amplitudes (tip deflections of a few mm, rotations of a few hundredths).
struct ConformanceCase {
  std::string law;
  std::function<CableDescription(int sections)> cable;
};

const std::vector<ConformanceCase>& conformance_cases() {
  static const std::vector<ConformanceCase> cases{
      {"masing", [](int n) { return CableDescription::uniform(kConformanceLength, n, 2.8, {{20.0, 0.7}}); }},
      {"bouc-wen",
       [](int n) { return CableDescription::uniform(*find_section_law("bouc-wen"), kConformanceLength, n, {2.5, 25.0, 0.03}); }},
      {"iwan",
       [](int n) {
         return CableDescription::uniform(*find_section_law("iwan"), kConformanceLength, n, {2.8, 0.7, 20.0, -0.5, 0.2});
       }},
  };
  return cases;
}

std::vector<std::string> conformance_laws() {
  std::vector<std::string> names;
  for (const SectionLawDescriptor* law : section_laws()) names.push_back(std::string(law->name()));
  return names;
}

CableDescription conformance_cable(const std::string& law, int sections = 40) {
  for (const ConformanceCase& c : conformance_cases()) {
    if (c.law == law) return c.cable(sections);
  }
  ADD_FAILURE() << "no conformance case for the registered law " << law;
  return CableDescription::uniform(kConformanceLength, sections, 2.8, {{20.0, 0.7}});
}

class CableLawConformance : public ::testing::TestWithParam<std::string> {};

/// Loading, a reversal and part of the way back.
void conformance_reversal(Cantilever& cantilever) {
  for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.004, 0.03}, {0.006, 0.05}, {0.001, 0.01}}) {
    ASSERT_TRUE(cantilever.set_trial_tip(x, phi).converged());
    cantilever.commit();
  }
}

// The flexibility (the tangents' integral) is the derivative of the tip's kinematics
// by the loads, along a continued loading (the tangent is one-sided).
TEST_P(CableLawConformance, TangentMatchesFiniteDifferences) {
  Cantilever cantilever{Cable(conformance_cable(GetParam()))};
  ASSERT_NO_FATAL_FAILURE(conformance_reversal(cantilever));
  const CableState base = cantilever.committed();
  const double dT = -0.05, dF = -0.3;
  cantilever.set_trial_loads(base.clamp_moment + dT, base.tip_force + dF);
  const CableState at = cantilever.trial();
  const double h = 1e-6;
  auto kinematics = [&](double t, double f) {
    cantilever.set_trial_loads(base.clamp_moment + t, base.tip_force + f);
    return Eigen::Vector2d(cantilever.trial().rotation, cantilever.trial().deflection);
  };
  const Eigen::Vector2d by_t = (kinematics(dT * (1 + h), dF) - kinematics(dT * (1 - h), dF)) / (2 * h * dT);
  const Eigen::Vector2d by_f = (kinematics(dT, dF * (1 + h)) - kinematics(dT, dF * (1 - h))) / (2 * h * dF);
  const double scale = at.flexibility.cwiseAbs().maxCoeff();
  EXPECT_NEAR(by_t(0), at.flexibility(0, 0), 1e-6 * scale);
  EXPECT_NEAR(by_t(1), at.flexibility(1, 0), 1e-6 * scale);
  EXPECT_NEAR(by_f(0), at.flexibility(0, 1), 1e-6 * scale);
  EXPECT_NEAR(by_f(1), at.flexibility(1, 1), 1e-6 * scale);
}

// The law is odd: from the mirror image of a state, the negative path gives the
// negative loads and internal variables.
TEST_P(CableLawConformance, TheMirroredStateAnswersTheNegativePath) {
  Cantilever a{Cable(conformance_cable(GetParam()))};
  for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.01, 0.05}, {-0.003, 0.02}}) {
    ASSERT_TRUE(a.set_trial_tip(x, phi).converged());
    a.commit();
  }
  Cantilever b = a;
  b.mirror();
  ASSERT_TRUE(a.set_trial_tip(0.004, -0.01).converged());
  ASSERT_TRUE(b.set_trial_tip(-0.004, 0.01).converged());
  EXPECT_NEAR(b.trial().clamp_moment, -a.trial().clamp_moment, 1e-11);
  EXPECT_NEAR(b.trial().tip_force, -a.trial().tip_force, 1e-10);
  for (std::size_t i = 0; i < a.trial().hysteretic.size(); ++i) {
    EXPECT_NEAR(b.trial().hysteretic[i], -a.trial().hysteretic[i], 1e-11);
  }
}

/// One cycle of a sinusoidal tip path in `steps` steps: the work done at the tip.
double conformance_cycle(Cantilever& cantilever, int steps) {
  const double x_amplitude = 0.006, phi_amplitude = 0.05;
  double work = 0.0;
  for (int j = 1; j <= steps; ++j) {
    const double t = 2.0 * M_PI * j / steps;
    const CableState from = cantilever.committed();
    EXPECT_TRUE(cantilever.set_trial_tip(x_amplitude * std::sin(t), phi_amplitude * std::sin(t + 0.4)).converged());
    const CableState& to = cantilever.trial();
    const double f = 0.5 * (from.tip_force + to.tip_force);
    const double q = 0.5 * (from.tip_moment(kConformanceLength) + to.tip_moment(kConformanceLength));
    work += f * (to.deflection - from.deflection) + q * (to.rotation - from.rotation);
    cantilever.commit();
  }
  return work;
}

// A periodic path settles: the state at the end of a cycle is the state at the end
// of the one before (the law's internal change and the loads).
TEST_P(CableLawConformance, ASteadyCycleSettles) {
  Cantilever cantilever{Cable(conformance_cable(GetParam()))};
  for (int cycle = 0; cycle < 6; ++cycle) conformance_cycle(cantilever, 400);
  const CableState before = cantilever.committed();
  conformance_cycle(cantilever, 400);
  const CableState& after = cantilever.committed();
  EXPECT_LT(cantilever.cable().law().internal_change(before, after), 1e-8);
  EXPECT_NEAR(after.clamp_moment, before.clamp_moment, 1e-9);
  EXPECT_NEAR(after.tip_force, before.tip_force, 1e-8);
  EXPECT_GT(after.dissipated, before.dissipated);
}

// Over a steady cycle the energy dissipated in the cable is the work done at its tip.
TEST_P(CableLawConformance, DissipationOverASteadyCycleIsTheWorkDoneAtTheTip) {
  Cantilever cantilever{Cable(conformance_cable(GetParam(), 60))};
  const int steps = 4000;
  for (int cycle = 0; cycle < 4; ++cycle) conformance_cycle(cantilever, steps);
  const double dissipated_before = cantilever.committed().dissipated;
  const double work = conformance_cycle(cantilever, steps);
  const double dissipated = cantilever.committed().dissipated - dissipated_before;
  EXPECT_GT(dissipated, 0.0);
  EXPECT_NEAR(work, dissipated, 1e-5 * dissipated);
}

// The sensitivities of the loads along a periodic path (the law's LoadSensitivity)
// are the derivatives of harmonic balance's residual: against central differences,
// over whole periods and under half-wave symmetry (the sensitivities mirrored).
TEST_P(CableLawConformance, SensitivitiesMatchFiniteDifferences) {
  for (const bool half_wave : {false, true}) {
    damper::ArmDescription description = testing::sauter_arm();
    description.cable = conformance_cable(GetParam());
    const damper::Arm arm(description);
    damper::HarmonicBalanceOptions options;
    options.half_wave = half_wave;
    damper::HarmonicBalance hb(arm, options);
    Eigen::VectorXd q = hb.linear_guess(damper::Excitation::from_velocity(15.0, 0.2));
    const damper::Excitation e{0.01, 1e-3};  // the inertia terms vanish: the cable's part alone
    const Eigen::Index s = half_wave ? 2 : 4, h = half_wave ? 6 : 8;
    q(s) *= 0.7;
    q(s + 1) *= 1.3;
    q(s - 1) = 0.2 * q(s);
    q(h) = 0.1 * q(s);
    q(s - 2) += 0.3 * q(s);
    damper::HarmonicBalanceWorkspace workspace = hb.make_workspace();
    const damper::HarmonicBalanceEvaluation at =
        hb.evaluate(e, q, nullptr, 2, damper::HarmonicBalance::kJacobian, workspace);
    ASSERT_TRUE(at.ok()) << brief_report(at.cable);
    const Eigen::MatrixXd jacobian = hb.jacobian(e, at.force_jacobian);
    Eigen::MatrixXd fd(jacobian.rows(), jacobian.cols());
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      const double step = 1e-8 * (std::abs(q(i)) + 1e-4);
      Eigen::VectorXd qp = q, qm = q;
      qp(i) += step;
      qm(i) -= step;
      const auto plus = hb.evaluate(e, qp, nullptr, 2, damper::HarmonicBalance::kNone, workspace);
      const auto minus = hb.evaluate(e, qm, nullptr, 2, damper::HarmonicBalance::kNone, workspace);
      ASSERT_TRUE(plus.ok() && minus.ok());
      fd.col(i) = (plus.residual - minus.residual) / (2.0 * step);
    }
    EXPECT_LT((jacobian - fd).norm(), 1e-5 * jacobian.norm()) << (half_wave ? "half wave" : "full period");
  }
}

// Harmonic balance and time integration reach the same steady state: Z within 0.5 %
// of |Z| below and above the arm's first mode.
TEST_P(CableLawConformance, HarmonicBalanceEqualsTimeIntegration) {
  damper::ArmDescription arm = testing::sauter_arm();
  arm.cable = conformance_cable(GetParam());
  const damper::Damper damper = testing::damper_of({arm});
  // Below and above the arm's resonance; under the sanitizers (short tests) below it
  // alone, the same paths (the Iwan law's march took a minute there for both).
  const std::vector<double> frequencies =
      stockbridge::testing::short_tests() ? std::vector<double>{12.0} : std::vector<double>{12.0, 40.0};
  for (const double f : frequencies) {
    const damper::Excitation e = damper::Excitation::from_velocity(f, 0.1);
    std::complex<double> z[2];
    int k = 0;
    for (const damper::Method method : {damper::Method::harmonic_balance, damper::Method::time_integration}) {
      damper::SolverOptions options;
      options.method = method;
      const damper::DamperSteadyState s = damper::solve_steady_state(damper, e, options);
      ASSERT_TRUE(s.point.converged()) << damper::method_name(method) << ": " << s.point.failure;
      z[k++] = s.point.impedance;
    }
    EXPECT_LT(std::abs(z[1] - z[0]), 5e-3 * std::abs(z[0])) << f << " Hz";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryLaw, CableLawConformance, ::testing::ValuesIn(conformance_laws()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace stockbridge::cable
