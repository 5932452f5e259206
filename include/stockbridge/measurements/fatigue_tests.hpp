#pragma once
// Conductor fatigue tests (MODEL.md section 14; docs/measurements.md, "Fatigue
// tests"): resonance or bielle benches break a conductor, or stop (a runout),
// after N cycles at a bending amplitude Yb (peak-to-peak, 89 mm from the clamp).
//   * stress: Poffenberger-Swart, sigma = K(T) Yb (span/fatigue.hpp), zero-to-peak;
//   * against the Safe Border Line of the conductor's aluminium layers: its cycles
//     at that stress, and whether a failure came before them;
//   * Basquin's curve log10 N = a + b log10 sigma_MPa + e, e ~ N(0, s^2), by maximum
//     likelihood with the runouts right-censored at their cycles:
//         l = sum_failed [ln phi(z) - ln s] + sum_runouts ln(1 - Phi(z)),
//         z = (log10 N - a - b log10 sigma) / s,
//     from least squares on the failures, Newton's steps on the analytic gradient and
//     Hessian (damped where the Hessian is not negative definite), the standard
//     errors from the inverse of the observed information -H at the maximum;
//   * the design curve: the mean minus 2 s in log10 N (about the 2.3 % quantile).

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "stockbridge/span/conductor.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::measurements {

/// One test as a fatigue-test file gives it.
struct FatigueTest {
  std::string test;            ///< the test's name
  std::string conductor_name;  ///< as given: a catalogue type or a conductor file
  span::Conductor conductor;
  double tension = 0.0;        ///< N
  double yb_pp = 0.0;          ///< Yb, peak-to-peak at x_b = 89 mm, m
  double cycles = 0.0;         ///< reached: to the failure, or where a runout stopped
  bool failed = false;         ///< false: a runout
  std::size_t line = 0;        ///< the file's line (0: not from a file)
};

/// A test's stress and its place against the Safe Border Line.
struct FatigueTestPoint {
  double stress = 0.0;          ///< sigma = K(T) Yb, Pa, zero-to-peak
  double microstrain_pp = 0.0;  ///< the outer wires' peak-to-peak strain 2 sigma / E_a, microstrain
  double sbl_cycles = 0.0;      ///< the Safe Border Line's cycles at sigma (the conductor's layers)
  bool below_sbl = false;       ///< a failure before sbl_cycles
};
/// Throws InvalidParameter naming "tension", "yb_pp" or "cycles" (each > 0).
FatigueTestPoint evaluate_fatigue_test(const FatigueTest& test);

/// The censored log-likelihood of Basquin's curve at (a, b, s), with its gradient and
/// Hessian in (a, b, s) (analytic).
struct BasquinLikelihood {
  double value = 0.0;
  std::array<double, 3> gradient{};
  std::array<std::array<double, 3>, 3> hessian{};
};
/// x: log10 of the stresses in MPa, y: log10 of the cycles, `failed` per test (false:
/// a runout, censored); s > 0.
BasquinLikelihood basquin_log_likelihood(std::span<const double> x, std::span<const double> y,
                                         const std::vector<bool>& failed, double a, double b, double s);

/// Basquin's curve fitted by maximum likelihood.
struct BasquinFit {
  double a = 0.0;        ///< log10 N = a + b log10 sigma_MPa
  double b = 0.0;
  double scatter = 0.0;  ///< s, the standard deviation of log10 N
  double a_standard_error = 0.0;
  double b_standard_error = 0.0;
  double scatter_standard_error = 0.0;
  int failures = 0;
  int runouts = 0;
  double log_likelihood = 0.0;
  int iterations = 0;    ///< Newton's steps

  /// The design curve's a: the mean minus 2 s in log10 N (same b).
  double design_a() const { return a - 2.0 * scatter; }
  /// The mean curve's cycles at `stress` (Pa).
  double cycles(double stress) const;
  /// The design curve's cycles at `stress` (Pa).
  double design_cycles(double stress) const;
};
/// Fits Basquin's curve to tests at `stress` (Pa, > 0) with `cycles` (> 0), runouts
/// where `failed` is false. Needs 3 failures or more at 2 stresses or more:
/// InvalidParameter naming "failed" otherwise; NumericalError where the likelihood
/// has no maximum (it grows without bound).
BasquinFit fit_basquin(std::span<const double> stress, std::span<const double> cycles, const std::vector<bool>& failed);

/// The design curve as an S-N table (stresses in MPa at the decades of cycles from
/// `cycles_min` to `cycles_max`): the single power law sigma = 10^((log10 N - a_d) / b).
/// InvalidParameter naming "b" where the fit's b is not < 0 (no S-N curve).
struct SnTable {
  std::vector<double> stress_mpa;
  std::vector<double> cycles;
};
SnTable design_curve_table(const BasquinFit& fit, double cycles_min = 1e5, double cycles_max = 1e10);

/// Every test evaluated, the fit over them all, and the failures below the Safe Border Line.
struct FatigueTestsResult {
  std::vector<FatigueTest> tests;
  std::vector<FatigueTestPoint> points;  ///< one per test
  BasquinFit fit;
  std::vector<std::size_t> below_sbl;    ///< the failures below the Safe Border Line, by index
  /// Of the failures, the share below the Safe Border Line.
  double below_sbl_fraction() const;
};
FatigueTestsResult analyse_fatigue_tests(std::vector<FatigueTest> tests);

}  // namespace stockbridge::measurements
