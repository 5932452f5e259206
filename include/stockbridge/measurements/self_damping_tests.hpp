#pragma once
// Self-damping tests (IEEE 563, IEC 62567: the power method on a laboratory span)
// and the power law fitted to them, MODEL.md section 14.
//
// A test file (CSV) has one row per test point, columns
//
//   tension_n        T, the conductor's tension (N)
//   frequency_hz     f, the frequency of the standing wave (Hz)
//   amplitude_m      Y, the antinode amplitude (m, single peak: zero to peak)
//   power_w_per_m    P, the power the conductor dissipates per length (W/m)
//
// others ignored. The law is the span's `[self_damping] law = "power"`
// (span/self_damping.hpp), per length:
//
//     P = k Y^l f^m / (T / 1000)^n            (W/m; Y in m, f in Hz, T in N)
//
// k is the tested conductor's own (no diameter or mass factor: Lilien's k is only
// the default of a span without one). The fit is ordinary least squares on
//     ln P = ln k + l ln Y + m ln f - n ln(T / 1000)
// (a column-pivoting QR solve), standard errors from s^2 (X^T X)^-1 with
// s^2 = (residual sum of squares) / (points - parameters). At one tension n is not
// determined: it must be given, and k, l, m are fitted with it.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/span/self_damping.hpp"

namespace stockbridge::measurements {

/// One test point, SI units.
struct SelfDampingTest {
  double tension = 0.0;    ///< T, N
  double frequency = 0.0;  ///< f, Hz
  double amplitude = 0.0;  ///< Y, m (antinode, single peak)
  double power = 0.0;      ///< P, W/m
};

/// A test file as read, and its warning lines (values outside the typical ranges
/// under SlipPolicy::warn).
struct SelfDampingTests {
  std::vector<SelfDampingTest> tests;
  std::vector<std::string> warnings;
};

/// The CSV columns, in the order of SelfDampingTest.
inline const std::vector<std::string>& self_damping_test_columns() {
  static const std::vector<std::string> columns{"tension_n", "frequency_hz", "amplitude_m", "power_w_per_m"};
  return columns;
}

/// Reads a test file. Throws InputError with one line naming the file, line and
/// column (the CSV reader's errors; a value <= 0). A value outside its typical range
/// (core/typical_ranges.hpp: span_tension, frequency, self_damping_amplitude,
/// self_damping_power) that the range's unit slip explains (a tension in kN, an
/// amplitude in mm, a power in mW/m) is refused under SlipPolicy::refuse
/// (UnusualValueError naming the file, line and column); any other one outside, and
/// every one under SlipPolicy::warn, gives one warning per column.
SelfDampingTests load_self_damping_tests(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);

/// The same from arrays of one value per test (Python): InvalidParameter naming the
/// array and index ("tension[2]") for a value <= 0 or arrays of different lengths;
/// UnusualValueError naming them for a slip refused.
SelfDampingTests self_damping_tests_from_arrays(const std::vector<double>& tension, const std::vector<double>& frequency,
                                                const std::vector<double>& amplitude, const std::vector<double>& power,
                                                SlipPolicy policy = SlipPolicy::refuse);

/// A fitted number and its standard error (NaN where the number was given, not fitted).
struct Estimate {
  double value = 0.0;
  double standard_error = 0.0;
};

struct SelfDampingFit {
  Estimate k;      ///< k, its standard error k times ln k's (first order)
  Estimate ln_k;   ///< ln k, as fitted
  Estimate l, m;   ///< exponents of Y and f
  Estimate n;      ///< exponent of T / 1000; standard error NaN when given
  bool n_given = false;
  std::size_t points = 0;
  std::size_t parameters = 0;       ///< 4, or 3 with n given
  std::vector<double> tensions;     ///< the distinct tensions tested (N), increasing
  std::vector<double> frequencies;  ///< the distinct frequencies (Hz)
  std::vector<double> amplitudes;   ///< the distinct amplitudes (m)
  double residual_rms = 0.0;        ///< sqrt(mean squared residual of ln P)
  double residual_standard_error = 0.0;  ///< s = sqrt(SSR / (points - parameters))
  double r_squared = 0.0;           ///< 1 - SSR / (sum of squares of ln P about its mean)
  std::vector<double> residuals;    ///< ln P measured - ln P fitted, per test
  std::vector<std::string> notes;   ///< what the data leave undetermined or the user fixed

  /// The fitted law as a span file's [self_damping] takes it (law = "power", k, l, m, n).
  span::SelfDampingModel model() const;
  /// The fitted P (W/m) at a test's point.
  double power(const SelfDampingTest& test) const;
};

/// Values closer than this (relative) count as one level of the design: a tension
/// set twice to 28.0 and 28.01 kN is one tension.
inline constexpr double kSameLevel = 1e-3;

/// Fits the law. `n`: the tension exponent to fix (needed at one tension; with
/// several, it fixes n instead of fitting it, and a note says so). Throws
/// InvalidParameter naming
///   "n"          one tension and no n given (n is not determined);
///   "points"     fewer than parameters + 1 tests (no standard errors), or a design
///                whose columns ln Y, ln f, ln T are collinear;
///   "frequency_hz", "amplitude_m"   one level only (m, l not determined).
SelfDampingFit fit_self_damping(const std::vector<SelfDampingTest>& tests, std::optional<double> n = std::nullopt);

}  // namespace stockbridge::measurements
