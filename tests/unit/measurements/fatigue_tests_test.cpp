// Fatigue tests (measurements/fatigue_tests.hpp): the censored log-likelihood's
// analytic gradient and Hessian against finite differences; the fit without runouts
// is least squares in closed form (s the maximum-likelihood sqrt(RSS / n)); the fit
// recovers a, b and s from synthetic tests with known values and censoring; a test's
// stress and its place against the Safe Border Line; the refusals.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/measurements/fatigue_tests.hpp"

namespace stockbridge::measurements {
namespace {

using stockbridge::testing::invalid_parameter_message;
using span::testing::aster570;
using span::testing::aster570_tension;
using span::testing::expect_relative;

constexpr double kMpa = 1e6;

/// A small set with failures and runouts, some runouts far above the line (z large).
struct Sample {
  std::vector<double> x{1.2, 1.3, 1.4, 1.5, 1.25, 1.45, 1.1, 1.35};
  std::vector<double> y{7.4, 6.9, 6.5, 6.0, 7.6, 6.8, 9.5, 6.2};
  std::vector<bool> failed{true, true, true, true, false, false, false, true};
};

TEST(FatigueTests, GradientAndHessianEqualFiniteDifferences) {
  const Sample s;
  const double a = 12.3, b = -4.1, sd = 0.21;
  const BasquinLikelihood at = basquin_log_likelihood(s.x, s.y, s.failed, a, b, sd);
  const auto value = [&](std::array<double, 3> t) { return basquin_log_likelihood(s.x, s.y, s.failed, t[0], t[1], t[2]); };
  for (int j = 0; j < 3; ++j) {
    const double h = 1e-6;
    std::array<double, 3> up{a, b, sd}, down{a, b, sd};
    up[j] += h;
    down[j] -= h;
    const BasquinLikelihood u = value(up), d = value(down);
    EXPECT_NEAR(at.gradient[j], (u.value - d.value) / (2.0 * h), 1e-5 * (1.0 + std::abs(at.gradient[j]))) << j;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(at.hessian[j][k], (u.gradient[k] - d.gradient[k]) / (2.0 * h), 1e-4 * (1.0 + std::abs(at.hessian[j][k])))
          << j << ", " << k;
    }
  }
}

TEST(FatigueTests, WithoutRunoutsTheFitIsLeastSquares) {
  const std::vector<double> mpa{15.0, 18.0, 22.0, 27.0, 33.0, 40.0};
  const std::vector<double> n{9e7, 2.1e7, 1.4e7, 3.9e6, 2.8e6, 7.1e5};
  std::vector<double> stress, x, y;
  for (std::size_t i = 0; i < mpa.size(); ++i) {
    stress.push_back(mpa[i] * kMpa), x.push_back(std::log10(mpa[i])), y.push_back(std::log10(n[i]));
  }
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / 6.0, my += y[i] / 6.0;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  const double b = sxy / sxx, a = my - b * mx;
  double rss = 0;
  for (std::size_t i = 0; i < x.size(); ++i) rss += std::pow(y[i] - a - b * x[i], 2);
  const double s = std::sqrt(rss / 6.0);
  const BasquinFit fit = fit_basquin(stress, n, std::vector<bool>(6, true));
  expect_relative(fit.a, a, 1e-9);
  expect_relative(fit.b, b, 1e-9);
  expect_relative(fit.scatter, s, 1e-7);
  // The observed information of the normal model at its maximum: var(b) = s^2 / Sxx, var(s) = s^2 / (2 n).
  expect_relative(fit.b_standard_error, s / std::sqrt(sxx), 1e-7);
  expect_relative(fit.scatter_standard_error, s / std::sqrt(12.0), 1e-7);
  EXPECT_EQ(fit.runouts, 0);
  expect_relative(fit.design_a(), a - 2.0 * s, 1e-9);
  expect_relative(fit.cycles(20.0 * kMpa), std::pow(10.0, a + b * std::log10(20.0)), 1e-12);
}

TEST(FatigueTests, TheFitRecoversKnownValuesFromCensoredTests) {
  // log10 N = 13 - 4.5 log10 sigma + N(0, 0.2^2), tests stopped at 2e7 cycles (runouts).
  constexpr double a = 13.0, b = -4.5, s = 0.2, stop = 2e7;
  std::mt19937_64 random(20240611);
  std::normal_distribution<double> scatter(0.0, s);
  std::vector<double> stress, cycles;
  std::vector<bool> failed;
  for (int i = 0; i < 600; ++i) {
    const double mpa = 12.0 + 28.0 * (i % 15) / 14.0;
    const double n = std::pow(10.0, a + b * std::log10(mpa) + scatter(random));
    stress.push_back(mpa * kMpa);
    cycles.push_back(std::min(n, stop));
    failed.push_back(n < stop);
  }
  const BasquinFit fit = fit_basquin(stress, cycles, failed);
  EXPECT_GT(fit.runouts, 100);  // a real share censored
  EXPECT_LT(std::abs(fit.a - a), 4.0 * fit.a_standard_error) << fit.a << " ± " << fit.a_standard_error;
  EXPECT_LT(std::abs(fit.b - b), 4.0 * fit.b_standard_error) << fit.b << " ± " << fit.b_standard_error;
  EXPECT_LT(std::abs(fit.scatter - s), 4.0 * fit.scatter_standard_error) << fit.scatter;
  EXPECT_LT(fit.b_standard_error, 0.2);
  // Ignoring the runouts would bias the curve down: the censored fit lies above the failures' own.
  std::vector<double> fs, fc;
  for (std::size_t i = 0; i < failed.size(); ++i) {
    if (failed[i]) fs.push_back(stress[i]), fc.push_back(cycles[i]);
  }
  const BasquinFit failures_only = fit_basquin(fs, fc, std::vector<bool>(fs.size(), true));
  EXPECT_GT(fit.cycles(15.0 * kMpa), failures_only.cycles(15.0 * kMpa));
}

TEST(FatigueTests, ATestsStressAndTheSafeBorderLine) {
  FatigueTest t{"t", "AAAC ASTER570", aster570(), aster570_tension, 0.5e-3, 1e7, true, 0};
  const FatigueTestPoint p = evaluate_fatigue_test(t);
  // K = 3.113210e10 Pa/m (span fatigue_test's hand numbers): 15.56605 MPa at Yb = 0.5 mm;
  // the several-layer line: 263 N^-0.17 below 15.74 MPa, N = (15.56605 / 263)^(-1/0.17).
  expect_relative(p.stress, 15.56605e6, 1e-6);
  expect_relative(p.microstrain_pp, 2.0 * p.stress / 68e9 * 1e6, 1e-12);
  expect_relative(p.sbl_cycles, std::pow(15.56605 / 263.0, -1.0 / 0.17), 1e-5);
  EXPECT_TRUE(p.below_sbl);  // 1e7 cycles, the line's ~1.7e7
  t.failed = false;
  EXPECT_FALSE(evaluate_fatigue_test(t).below_sbl);  // a runout is never below it
  t.failed = true;
  t.cycles = 2e7;
  EXPECT_FALSE(evaluate_fatigue_test(t).below_sbl);
}

TEST(FatigueTests, TooFewFailuresAreRefused) {
  const std::vector<double> stress{20e6, 25e6, 30e6, 35e6};
  const std::vector<double> cycles{1e7, 5e6, 2e6, 1e6};
  EXPECT_EQ(invalid_parameter_message([&] { fit_basquin(stress, cycles, {true, true, false, false}); }),
            "failed: 2 failure(s) at 2 stress(es): the fit needs 3 failures or more at 2 stresses or more");
  const std::vector<double> one{20e6, 20e6, 20e6};
  const std::vector<double> three{1e7, 5e6, 2e6};
  EXPECT_EQ(invalid_parameter_message([&] { fit_basquin(one, three, {true, true, true}); }),
            "failed: 3 failure(s) at 1 stress(es): the fit needs 3 failures or more at 2 stresses or more");
}

TEST(FatigueTests, TheDesignCurvesTableLiesOnMeanMinusTwoS) {
  BasquinFit fit;
  fit.a = 13.0, fit.b = -4.5, fit.scatter = 0.2;
  const SnTable t = design_curve_table(fit, 1e5, 1e9);
  ASSERT_EQ(t.cycles.size(), 5u);
  for (std::size_t i = 0; i < t.cycles.size(); ++i) {
    expect_relative(std::log10(t.cycles[i]), 12.6 - 4.5 * std::log10(t.stress_mpa[i]), 1e-12);
  }
  fit.b = 0.1;
  EXPECT_EQ(invalid_parameter_message([&] { design_curve_table(fit); }),
            "b = 0.1: expected a slope < 0 (cycles falling as the stress rises): the tests give no S-N curve");
}

}  // namespace
}  // namespace stockbridge::measurements
