// The cantilever's state determination: exact flexibility, Newton convergence on
// random paths, the trial/commit protocol, convergence in the number of sections.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/cable/experiment.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {
namespace {

CableDescription two_element_cable(int sections = 40) {
  return CableDescription::uniform(0.3, sections, 2.8, {{20.0, 0.7}, {6.0, 0.15}});
}

/// A hysteretic state: load, reverse, and stop part way.
Cantilever loaded_cantilever() {
  Cantilever cantilever{Cable(two_element_cable())};
  for (const auto& [x, phi] : std::vector<std::pair<double, double>>{{0.02, 0.05}, {-0.01, -0.02}, {0.004, 0.01}}) {
    EXPECT_TRUE(cantilever.set_trial_tip(x, phi).converged());
    cantilever.commit();
  }
  return cantilever;
}

// d(phi, x)/d(T, F) equals finite differences of the exact load evaluation.
TEST(Cantilever, FlexibilityMatchesFiniteDifferences) {
  Cantilever cantilever = loaded_cantilever();
  const CableState base = cantilever.committed();
  int checked = 0;
  for (const auto& [dT, dF] : std::vector<std::pair<double, double>>{{0.3, 1.0}, {-0.2, -0.5}, {0.05, -0.4}, {-0.6, 2.0}}) {
    const double T = base.clamp_moment + dT;
    const double F = base.tip_force + dF;
    cantilever.set_trial_loads(T, F);
    const CableState at = cantilever.trial();
    const double h = 1e-7;
    cantilever.set_trial_loads(T + h * dT / std::abs(dT), F);
    const CableState dt = cantilever.trial();
    cantilever.set_trial_loads(T, F + h * dF / std::abs(dF));
    const CableState df = cantilever.trial();
    if (dt.tangent != at.tangent || df.tangent != at.tangent) continue;  // a breakpoint in between
    const double sT = dT / std::abs(dT), sF = dF / std::abs(dF);
    const double tol = 1e-6;
    EXPECT_NEAR((dt.rotation - at.rotation) / (h * sT), at.flexibility(0, 0), tol * std::abs(at.flexibility(0, 0)));
    EXPECT_NEAR((dt.deflection - at.deflection) / (h * sT), at.flexibility(1, 0), tol * std::abs(at.flexibility(1, 0)));
    EXPECT_NEAR((df.rotation - at.rotation) / (h * sF), at.flexibility(0, 1), tol * std::abs(at.flexibility(0, 1)));
    EXPECT_NEAR((df.deflection - at.deflection) / (h * sF), at.flexibility(1, 1), tol * std::abs(at.flexibility(1, 1)));
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

// The tip stiffness d(F, Q)/d(x, phi) inverts the flexibility with Q = T - F l.
TEST(Cantilever, TipStiffnessOfAnElasticCable) {
  const double ei = 5.0, l = 0.2;
  Cantilever cantilever{Cable(CableDescription::uniform(l, 8, ei, {}))};
  const Eigen::Matrix2d k = cantilever.committed().tip_stiffness(l);
  // Classical beam: F = 12 EI/l^3 x - 6 EI/l^2 phi, Q = -6 EI/l^2 x + 4 EI/l phi.
  EXPECT_NEAR(k(0, 0), 12.0 * ei / std::pow(l, 3), 1e-9 * k(0, 0));
  EXPECT_NEAR(k(0, 1), -6.0 * ei / std::pow(l, 2), 1e-9 * std::abs(k(0, 1)));
  EXPECT_NEAR(k(1, 0), -6.0 * ei / std::pow(l, 2), 1e-9 * std::abs(k(1, 0)));
  EXPECT_NEAR(k(1, 1), 4.0 * ei / l, 1e-9 * k(1, 1));
}

// Newton with the exact flexibility and a line search converges on random
// paths with reversals, for every kind of prescription, in a few iterations.
TEST(Cantilever, NewtonConvergesOnRandomPaths) {
  Cantilever cantilever{Cable(two_element_cable())};
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> dx(-0.01, 0.01), dphi(-0.05, 0.05);
  std::uniform_int_distribution<int> kind(0, 2);
  double x = 0.0, phi = 0.0;
  int total_iterations = 0, max_iterations = 0;
  const int steps = 3000;
  for (int i = 0; i < steps; ++i) {
    StateDetermination r;
    switch (kind(rng)) {
      case 0: x += dx(rng); phi += dphi(rng); r = cantilever.set_trial_tip(x, phi); break;
      case 1: x += dx(rng); r = cantilever.set_trial_deflection(x); break;
      default: phi += dphi(rng); r = cantilever.set_trial_rotation(phi); break;
    }
    ASSERT_TRUE(r.converged()) << "step " << i << " residual " << r.residual;
    total_iterations += r.newton_iterations;
    max_iterations = std::max(max_iterations, r.newton_iterations);
    const CableState& s = cantilever.trial();
    x = s.deflection;
    phi = s.rotation;
    cantilever.commit();
  }
  EXPECT_LE(max_iterations, 8);
  EXPECT_LT(static_cast<double>(total_iterations) / steps, 3.0);
}

TEST(Cantilever, MixedFormsHoldTheirConstraints) {
  Cantilever cantilever{Cable(two_element_cable())};
  ASSERT_TRUE(cantilever.set_trial_deflection(0.03).converged());
  EXPECT_NEAR(cantilever.trial().tip_moment(0.3), 0.0, 1e-12);
  EXPECT_NEAR(cantilever.trial().deflection, 0.03, 1e-13);
  cantilever.commit();
  ASSERT_TRUE(cantilever.set_trial_rotation(-0.1).converged());
  EXPECT_NEAR(cantilever.trial().deflection, 0.0, 1e-13);
  EXPECT_NEAR(cantilever.trial().rotation, -0.1, 1e-12);
}

// The law is odd: from the mirrored state, the negated path gives the negated loads
// and states (what half-wave symmetry relies on), with the same dissipation.
TEST(Cantilever, TheMirroredCableAnswersTheNegatedPathWithNegatedLoads) {
  Cantilever original = loaded_cantilever();
  Cantilever mirrored = loaded_cantilever();
  mirrored.mirror();
  EXPECT_EQ(mirrored.committed().clamp_moment, -original.committed().clamp_moment);
  const std::vector<std::pair<double, double>> path{{0.012, 0.02}, {0.03, 0.06}, {-0.02, -0.01}, {0.001, 0.03}};
  const double dissipated_before = original.committed().dissipated;
  for (const auto& [x, phi] : path) {
    ASSERT_TRUE(original.set_trial_tip(x, phi).converged());
    ASSERT_TRUE(mirrored.set_trial_tip(-x, -phi).converged());
    original.commit();
    mirrored.commit();
    const CableState &a = original.committed(), &b = mirrored.committed();
    EXPECT_NEAR(b.clamp_moment, -a.clamp_moment, 1e-12 * std::abs(a.clamp_moment));
    EXPECT_NEAR(b.tip_force, -a.tip_force, 1e-12 * std::abs(a.tip_force));
    for (std::size_t i = 0; i < a.hysteretic.size(); ++i) EXPECT_NEAR(b.hysteretic[i], -a.hysteretic[i], 1e-12);
    for (std::size_t i = 0; i < a.curvature.size(); ++i) EXPECT_NEAR(b.curvature[i], -a.curvature[i], 1e-12);
  }
  EXPECT_GT(original.committed().dissipated, dissipated_before);
  EXPECT_NEAR(mirrored.committed().dissipated, original.committed().dissipated, 1e-15);
}

TEST(Cantilever, NonConvergenceIsAResultNotANumber) {
  // A tolerance below round-off cannot be met: the solver must say so.
  CantileverOptions options;
  options.max_iterations = 3;
  options.tolerance = 1e-30;
  Cantilever cantilever{Cable(two_element_cable()), options};
  cantilever.set_trial_tip(0.05, 0.1);
  cantilever.commit();
  const StateDetermination r = cantilever.set_trial_tip(-0.04, 0.3);
  EXPECT_FALSE(r.converged());
  // Either the iteration limit or a line search that can no longer reduce the residual ends it.
  EXPECT_TRUE(r.termination == Termination::max_iterations || r.termination == Termination::line_search_failed)
      << termination_name(r.termination);
  EXPECT_LE(r.newton_iterations, 3);
  EXPECT_TRUE(std::isfinite(r.residual));
  cantilever.revert_to_last_commit();
  EXPECT_EQ(cantilever.trial().deflection, cantilever.committed().deflection);
}

TEST(Cantilever, DissipationOnlyGrowsAndRevertRestores) {
  Cantilever cantilever{Cable(two_element_cable())};
  double previous = 0.0;
  for (int k = 0; k <= 400; ++k) {
    ASSERT_TRUE(cantilever.set_trial_deflection(0.04 * std::sin(2 * M_PI * k / 100.0)).converged());
    ASSERT_GE(cantilever.trial().dissipated, previous);
    cantilever.commit();
    previous = cantilever.committed().dissipated;
  }
  EXPECT_GT(previous, 0.0);
  const CableState committed = cantilever.committed();
  cantilever.set_trial_tip(0.1, 0.4);
  cantilever.revert_to_last_commit();
  EXPECT_EQ(cantilever.trial().hysteretic, committed.hysteretic);
  EXPECT_EQ(cantilever.trial().tip_force, committed.tip_force);
}

/// Tip force after a loading, unloading and reloading path, with n sections.
double force_after_path(int sections) {
  Cantilever cantilever{Cable(two_element_cable(sections))};
  for (const double x : {0.01, 0.02, 0.03, 0.015, 0.0, -0.01, 0.005}) {
    EXPECT_TRUE(cantilever.set_trial_deflection(x).converged());
    cantilever.commit();
  }
  return cantilever.committed().tip_force;
}

// The curvature has kinks at stick-slip boundaries, so Gauss-Legendre converges
// as n^-2 (not spectrally): the observed order over n = 10 .. 160 is about 2.
TEST(Cantilever, ConvergesInSectionsAtSecondOrder) {
  const double reference = force_after_path(2560);
  std::vector<double> n, error;
  for (const int sections : {10, 20, 40, 80, 160}) {
    n.push_back(std::log(sections));
    error.push_back(std::log(std::abs(force_after_path(sections) - reference)));
  }
  // Least-squares slope of log error over log n.
  double mean_n = 0, mean_e = 0;
  for (std::size_t i = 0; i < n.size(); ++i) mean_n += n[i] / n.size(), mean_e += error[i] / n.size();
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n.size(); ++i) sxy += (n[i] - mean_n) * (error[i] - mean_e), sxx += (n[i] - mean_n) * (n[i] - mean_n);
  const double order = -sxy / sxx;
  RecordProperty("observed_order", std::to_string(order));
  EXPECT_GT(order, 1.7);
  EXPECT_LT(order, 3.0);
  EXPECT_LT(std::exp(error[2]), 1e-3 * std::abs(reference));  // 40 sections: better than 0.1 %
}

// With smooth parameters and no slip the rule is spectral: an elastic cable with a
// linearly varying ei is exact to round-off with a handful of points.
TEST(Cantilever, SmoothProfileConvergesSpectrally) {
  auto force = [](int sections) {
    CableDescription d = CableDescription::uniform(0.3, sections, 1.0, {});
    d.ei = Profile::table({0.0, 0.3}, {4.0, 1.5}, "ei");
    Cantilever cantilever{Cable(d)};
    EXPECT_TRUE(cantilever.set_trial_deflection(0.01).converged());
    return cantilever.trial().tip_force;
  };
  const double reference = force(200);
  EXPECT_GT(std::abs(force(3) - reference), 1e-6 * reference);
  EXPECT_LT(std::abs(force(16) - reference), 1e-12 * reference);
}

// The closed-form one-element path of apply_loads against the general one: two
// identical half elements (c/2, h/2) slip together and behave as one (c, h), but go
// through the general active-set solve.
TEST(Cantilever, OneElementFastPathEqualsTheGeneralPath) {
  Cantilever one{Cable(CableDescription::uniform(0.3, 40, 2.8, {{20.0, 0.7}}))};
  Cantilever halves{Cable(CableDescription::uniform(0.3, 40, 2.8, {{10.0, 0.35}, {10.0, 0.35}}))};
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> dx(-0.01, 0.01), dphi(-0.05, 0.05);
  double x = 0.0, phi = 0.0;
  for (int i = 0; i < 500; ++i) {
    x += dx(rng);
    phi += dphi(rng);
    ASSERT_TRUE(one.set_trial_tip(x, phi).converged());
    ASSERT_TRUE(halves.set_trial_tip(x, phi).converged());
    const CableState& a = one.trial();
    const CableState& b = halves.trial();
    ASSERT_NEAR(a.tip_force, b.tip_force, 1e-10 * (1.0 + std::abs(a.tip_force))) << "step " << i;
    ASSERT_NEAR(a.clamp_moment, b.clamp_moment, 1e-10 * (1.0 + std::abs(a.clamp_moment)));
    ASSERT_NEAR(a.dissipated, b.dissipated, 1e-10 * (1.0 + a.dissipated));
    ASSERT_LT((a.flexibility - b.flexibility).norm(), 1e-9 * a.flexibility.norm());
    for (std::size_t k = 0; k < a.curvature.size(); ++k) {
      ASSERT_NEAR(a.curvature[k], b.curvature[k], 1e-10 * (1.0 + std::abs(a.curvature[k])));
      ASSERT_NEAR(a.hysteretic[k], b.hysteretic[2 * k] + b.hysteretic[2 * k + 1], 1e-10);
    }
    one.commit();
    halves.commit();
  }
}

// The coarsest cable allowed (two sections) is guided at the tip as in (b): finite
// loads, the rotation met (with one section this returned NaN; see above).
TEST(Cantilever, TwoSectionsCarryAGuidedTip) {
  Cantilever cantilever{Cable(CableDescription::uniform(1.0, 2, 0.05, {}))};
  const StateDetermination d = cantilever.set_trial_rotation(-1.0);
  ASSERT_TRUE(d.converged());
  EXPECT_NEAR(cantilever.trial().rotation, -1.0, 1e-10);
  EXPECT_NEAR(cantilever.trial().deflection, 0.0, 1e-10);
  EXPECT_NEAR(cantilever.trial().clamp_moment, -2.0 * 0.05 * (-1.0) / 1.0, 1e-9);  // T = -2 EI phi / l
}

// Numerical trust in the experiments: with one Newton iteration per sample the
// slipping samples of (a) fail; they are flagged, and the last cycle's energies,
// which would be integrated across the gaps, are NaN rather than a wrong number.
TEST(Experiment, FailedSamplesLeaveNoEnergies) {
  CantileverOptions options;
  options.max_iterations = 1;
  Cantilever cantilever(Cable(CableDescription::uniform(0.3, 40, 2.8, {{20.0, 0.7}})), options);
  const ExperimentRecord record = run_experiment(cantilever, {Experiment::a, 0.03, 2, 200});
  EXPECT_GT(record.summary.failed_samples, 0);
  EXPECT_TRUE(std::isnan(record.summary.slider_dissipation));
  EXPECT_TRUE(std::isnan(record.summary.loop_work));
  EXPECT_TRUE(std::isnan(record.summary.measured_loop_area));
  Cantilever converging{Cable(CableDescription::uniform(0.3, 40, 2.8, {{20.0, 0.7}}))};
  const ExperimentSummary ok = run_experiment(converging, {Experiment::a, 0.03, 2, 200}).summary;
  EXPECT_EQ(ok.failed_samples, 0);
  EXPECT_GT(ok.slider_dissipation, 0.0);
}

TEST(Cantilever, RejectsBadDescriptions) {
  EXPECT_THROW(Cable(CableDescription::uniform(0.0, 40, 2.8, {})), InvalidParameter);
  EXPECT_THROW(Cable(CableDescription::uniform(0.3, 0, 2.8, {})), InvalidParameter);
  // Fuzzing finding: with one section x = phi l / 2 always, and (b) returned NaN loads.
  EXPECT_THROW(Cable(CableDescription::uniform(0.3, 1, 2.8, {})), InvalidParameter);
  EXPECT_THROW(Cable(CableDescription::uniform(0.3, 40, 0.0, {{20.0, 0.7}})), InvalidParameter);  // ei > 0 on a cable
  EXPECT_THROW(Cable(CableDescription::uniform(0.3, 40, 2.8, {{20.0, -0.7}})), InvalidParameter);
  CantileverOptions options;
  options.tolerance = 0.0;
  EXPECT_THROW(Cantilever(Cable(two_element_cable()), options), InvalidParameter);
  Cantilever cantilever{Cable(two_element_cable())};
  EXPECT_THROW(cantilever.set_trial_tip(NAN, 0.0), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::cable
