#include "stockbridge/measurements/fatigue_tests.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::measurements {

namespace {

using BasquinVector = std::array<double, 3>;
using BasquinMatrix = std::array<BasquinVector, 3>;

constexpr double fatigue_tests_pa_per_mpa = 1e6;

/// ln(1 - Phi(z)), accurate in the upper tail (Mills' series where erfc underflows).
double basquin_log_survival(double z) {
  if (z < 35.0) return std::log(0.5 * std::erfc(z / std::numbers::sqrt2));
  const double z2 = z * z;
  return -0.5 * z2 - std::log(z * std::sqrt(2.0 * std::numbers::pi)) + std::log1p(-1.0 / z2 + 3.0 / (z2 * z2));
}

/// phi(z) / (1 - Phi(z)): the normal hazard.
double basquin_hazard(double z) {
  if (z < 35.0) {
    const double log_phi = -0.5 * z * z - 0.5 * std::log(2.0 * std::numbers::pi);
    return std::exp(log_phi - basquin_log_survival(z));
  }
  return z + 1.0 / z - 2.0 / (z * z * z);
}

/// x solving M x = r for a symmetric positive definite M (Cholesky); false where M is not.
bool basquin_solve_spd(const BasquinMatrix& m, const BasquinVector& r, BasquinVector& x) {
  BasquinMatrix l{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) {
      double sum = m[i][j];
      for (int k = 0; k < j; ++k) sum -= l[i][k] * l[j][k];
      if (i == j) {
        if (!(sum > 0.0)) return false;
        l[i][i] = std::sqrt(sum);
      } else {
        l[i][j] = sum / l[j][j];
      }
    }
  }
  BasquinVector y{};
  for (int i = 0; i < 3; ++i) {
    double sum = r[i];
    for (int k = 0; k < i; ++k) sum -= l[i][k] * y[k];
    y[i] = sum / l[i][i];
  }
  for (int i = 2; i >= 0; --i) {
    double sum = y[i];
    for (int k = i + 1; k < 3; ++k) sum -= l[k][i] * x[k];
    x[i] = sum / l[i][i];
  }
  return true;
}

BasquinMatrix basquin_negated(const BasquinMatrix& m) {
  BasquinMatrix out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = -m[i][j];
  return out;
}

}  // namespace

FatigueTestPoint evaluate_fatigue_test(const FatigueTest& t) {
  require_positive("tension", t.tension, "N");
  require_positive("yb_pp", t.yb_pp, "m");
  require_positive("cycles", t.cycles, "");
  FatigueTestPoint p;
  p.stress = span::poffenberger_swart_stress(t.conductor, t.tension, t.yb_pp);
  p.microstrain_pp = span::bending_strain_pp_microstrain(t.conductor, p.stress);
  p.sbl_cycles = span::safe_border_curve(t.conductor.aluminium_layers).cycles_to_failure(p.stress);
  p.below_sbl = t.failed && t.cycles < p.sbl_cycles;
  return p;
}

BasquinLikelihood basquin_log_likelihood(std::span<const double> x, std::span<const double> y,
                                         const std::vector<bool>& failed, double a, double b, double s) {
  BasquinLikelihood out;
  const double half_log_two_pi = 0.5 * std::log(2.0 * std::numbers::pi);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double z = (y[i] - a - b * x[i]) / s;
    // dl/dz, d2l/dz2 of the test's own term; z's derivatives in (a, b, s).
    double g = 0.0, h = 0.0;
    if (failed[i]) {
      out.value += -half_log_two_pi - 0.5 * z * z - std::log(s);
      g = -z;
      h = -1.0;
    } else {
      out.value += basquin_log_survival(z);
      const double lambda = basquin_hazard(z);
      g = -lambda;
      h = -lambda * (lambda - z);
    }
    const BasquinVector dz{-1.0 / s, -x[i] / s, -z / s};
    const BasquinMatrix d2z{{{0.0, 0.0, 1.0 / (s * s)}, {0.0, 0.0, x[i] / (s * s)}, {1.0 / (s * s), x[i] / (s * s), 2.0 * z / (s * s)}}};
    for (int j = 0; j < 3; ++j) {
      out.gradient[j] += g * dz[j];
      for (int k = 0; k < 3; ++k) out.hessian[j][k] += h * dz[j] * dz[k] + g * d2z[j][k];
    }
    if (failed[i]) {  // -ln s
      out.gradient[2] -= 1.0 / s;
      out.hessian[2][2] += 1.0 / (s * s);
    }
  }
  return out;
}

double BasquinFit::cycles(double stress) const {
  return std::pow(10.0, a + b * std::log10(stress / fatigue_tests_pa_per_mpa));
}

double BasquinFit::design_cycles(double stress) const {
  return std::pow(10.0, design_a() + b * std::log10(stress / fatigue_tests_pa_per_mpa));
}

BasquinFit fit_basquin(std::span<const double> stress, std::span<const double> cycles, const std::vector<bool>& failed) {
  if (cycles.size() != stress.size() || failed.size() != stress.size()) {
    throw InvalidParameter("cycles", fmt::format(": {} cycles and {} failed flags for {} stresses: expected one each",
                                                 cycles.size(), failed.size(), stress.size()));
  }
  std::vector<double> x, y;
  BasquinFit fit;
  double stress_low = std::numeric_limits<double>::infinity(), stress_high = 0.0;
  for (std::size_t i = 0; i < stress.size(); ++i) {
    require_positive(fmt::format("stress[{}]", i), stress[i], "Pa");
    require_positive(fmt::format("cycles[{}]", i), cycles[i], "");
    x.push_back(std::log10(stress[i] / fatigue_tests_pa_per_mpa));
    y.push_back(std::log10(cycles[i]));
    if (failed[i]) {
      ++fit.failures;
      stress_low = std::min(stress_low, stress[i]);
      stress_high = std::max(stress_high, stress[i]);
    } else {
      ++fit.runouts;
    }
  }
  if (fit.failures < 3 || !(stress_high > stress_low)) {
    std::set<double> stresses;
    for (std::size_t i = 0; i < stress.size(); ++i) {
      if (failed[i]) stresses.insert(stress[i]);
    }
    throw InvalidParameter("failed", fmt::format(": {} failure(s) at {} stress(es): the fit needs 3 failures or more at "
                                                 "2 stresses or more",
                                                 fit.failures, stresses.size()));
  }
  // Start: least squares on the failures.
  double n = 0.0, mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (failed[i]) n += 1.0, mx += x[i], my += y[i];
  }
  mx /= n, my /= n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (failed[i]) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  }
  BasquinVector theta{my - sxy / sxx * mx, sxy / sxx, 0.0};
  double rss = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (failed[i]) rss += std::pow(y[i] - theta[0] - theta[1] * x[i], 2);
  }
  theta[2] = std::max(std::sqrt(rss / std::max(n - 2.0, 1.0)), 0.05);

  BasquinLikelihood here = basquin_log_likelihood(x, y, failed, theta[0], theta[1], theta[2]);
  // Newton's decrement g (-H)^-1 g where -H is positive definite (infinite elsewhere): twice
  // the rise a full step promises.
  const auto decrement = [](const BasquinLikelihood& l) {
    BasquinVector step{};
    if (!basquin_solve_spd(basquin_negated(l.hessian), l.gradient, step)) return std::numeric_limits<double>::infinity();
    return step[0] * l.gradient[0] + step[1] * l.gradient[1] + step[2] * l.gradient[2];
  };
  bool converged = false;
  for (int iteration = 0; iteration < 500 && theta[2] > 1e-9; ++iteration) {
    if (decrement(here) < 1e-14) {
      converged = true;
      break;
    }
    // Damped Newton (Levenberg-Marquardt on -H): the least damping that raises the likelihood.
    const BasquinMatrix information = basquin_negated(here.hessian);
    bool raised = false;
    for (double mu = 0.0; mu < 1e12 && !raised; mu = mu == 0.0 ? 1e-6 : 10.0 * mu) {
      BasquinMatrix damped = information;
      for (int j = 0; j < 3; ++j) damped[j][j] += mu * std::max(1.0, std::abs(information[j][j]));
      BasquinVector step{};
      if (!basquin_solve_spd(damped, here.gradient, step)) continue;
      const BasquinVector trial{theta[0] + step[0], theta[1] + step[1], theta[2] + step[2]};
      if (!(trial[2] > 0.0)) continue;
      const BasquinLikelihood there = basquin_log_likelihood(x, y, failed, trial[0], trial[1], trial[2]);
      if (std::isfinite(there.value) && there.value >= here.value) {
        theta = trial;
        here = there;
        raised = true;
        fit.iterations = iteration + 1;
      }
    }
    if (!raised) {  // no step rises in floating point: the maximum, if -H says so
      converged = decrement(here) < 1e-8;
      break;
    }
  }
  BasquinVector variance{};
  const BasquinMatrix information = basquin_negated(here.hessian);
  for (int j = 0; j < 3 && converged; ++j) {
    BasquinVector unit{}, column{};
    unit[j] = 1.0;
    converged = basquin_solve_spd(information, unit, column);
    variance[j] = column[j];
  }
  if (!converged || !(theta[2] > 1e-9)) {
    throw NumericalError(fmt::format("the censored Basquin fit found no maximum of the likelihood (s = {:.3g} after {} "
                                     "steps): the tests do not determine a, b and s",
                                     theta[2], fit.iterations));
  }
  fit.a = theta[0];
  fit.b = theta[1];
  fit.scatter = theta[2];
  fit.a_standard_error = std::sqrt(variance[0]);
  fit.b_standard_error = std::sqrt(variance[1]);
  fit.scatter_standard_error = std::sqrt(variance[2]);
  fit.log_likelihood = here.value;
  return fit;
}

SnTable design_curve_table(const BasquinFit& fit, double cycles_min, double cycles_max) {
  if (!(fit.b < 0.0)) {
    throw_invalid("b", fit.b, "a slope < 0 (cycles falling as the stress rises): the tests give no S-N curve");
  }
  SnTable table;
  for (double e = std::floor(std::log10(cycles_min)); e <= std::ceil(std::log10(cycles_max)) + 1e-9; e += 1.0) {
    table.cycles.push_back(std::pow(10.0, e));
    table.stress_mpa.push_back(std::pow(10.0, (e - fit.design_a()) / fit.b));
  }
  return table;
}

double FatigueTestsResult::below_sbl_fraction() const {
  return fit.failures > 0 ? static_cast<double>(below_sbl.size()) / fit.failures : 0.0;
}

FatigueTestsResult analyse_fatigue_tests(std::vector<FatigueTest> tests) {
  FatigueTestsResult result;
  std::vector<double> stress, cycles;
  std::vector<bool> failed;
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const FatigueTestPoint p = within_field(fmt::format("tests[{}]", i), [&] { return evaluate_fatigue_test(tests[i]); });
    result.points.push_back(p);
    if (p.below_sbl) result.below_sbl.push_back(i);
    stress.push_back(p.stress);
    cycles.push_back(tests[i].cycles);
    failed.push_back(tests[i].failed);
  }
  result.fit = fit_basquin(stress, cycles, failed);
  result.tests = std::move(tests);
  return result;
}

}  // namespace stockbridge::measurements
