#include "stockbridge/measurements/self_damping_tests.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_reader.hpp"

namespace stockbridge::measurements {

namespace {

/// The typical range of each column, in the order of self_damping_test_columns().
const std::array<const TypicalRange*, 4> sdt_ranges{&typical::span_tension, &typical::frequency,
                                                    &typical::self_damping_amplitude, &typical::self_damping_power};

/// One column's values outside its typical range, `field(row)` naming a value where
/// it lies ("t.csv:3: column 'tension_n'", "tension[2]"): under SlipPolicy::refuse the
/// first one a unit slip explains is an UnusualValueError; the others (and all under
/// warn) one warning naming the first and counting the rest.
void sdt_judge_column(const std::vector<double>& values, const TypicalRange& range, SlipPolicy policy,
                      const std::function<std::string(std::size_t)>& field, std::vector<std::string>& warnings) {
  std::size_t outside = 0, first = 0;
  for (std::size_t r = 0; r < values.size(); ++r) {
    if (range.contains(values[r])) continue;
    if (outside++ == 0) first = r;
    const UnusualValue u{field(r), values[r], range, ""};
    if (policy == SlipPolicy::refuse && u.slip_explained()) {
      throw UnusualValueError(u.message() + "; a self-damping test's values lie within it");
    }
  }
  if (outside == 0) return;
  const std::string more =
      outside > 1 ? fmt::format("; {} more row{} of the column outside it", outside - 1, outside > 2 ? "s" : "") : "";
  warnings.push_back(UnusualValue{field(first), values[first], range, ""}.message() + more);
}

/// The distinct levels of `values` (within kSameLevel, relative), increasing: each
/// level the first value of its group.
std::vector<double> sdt_levels(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::vector<double> levels;
  for (double v : values) {
    if (levels.empty() || v > levels.back() * (1.0 + kSameLevel)) levels.push_back(v);
  }
  return levels;
}

}  // namespace

SelfDampingTests load_self_damping_tests(const std::filesystem::path& path, SlipPolicy policy) {
  const std::string file = path.string();
  const std::vector<std::string>& names = self_damping_test_columns();
  const io::CsvRows rows = io::read_csv_rows(path, names, 1);
  for (std::size_t c = 0; c < names.size(); ++c) {
    for (std::size_t r = 0; r < rows.lines.size(); ++r) {
      const double v = rows.columns[c][r];
      if (!(v > 0.0)) {
        throw InputError(fmt::format("{}:{}: column '{}' = {}: expected > 0", file, rows.lines[r], names[c],
                                     format_value(v)));
      }
    }
  }
  SelfDampingTests out;
  for (std::size_t c = 0; c < names.size(); ++c) {
    sdt_judge_column(
        rows.columns[c], *sdt_ranges[c], policy,
        [&](std::size_t r) { return fmt::format("{}:{}: column '{}'", file, rows.lines[r], names[c]); }, out.warnings);
  }
  for (std::size_t r = 0; r < rows.lines.size(); ++r) {
    out.tests.push_back({rows.columns[0][r], rows.columns[1][r], rows.columns[2][r], rows.columns[3][r]});
  }
  return out;
}

SelfDampingTests self_damping_tests_from_arrays(const std::vector<double>& tension, const std::vector<double>& frequency,
                                                const std::vector<double>& amplitude, const std::vector<double>& power,
                                                SlipPolicy policy) {
  const std::array<const std::vector<double>*, 4> columns{&tension, &frequency, &amplitude, &power};
  const std::array<std::string_view, 4> names{"tension", "frequency", "amplitude", "power"};
  for (std::size_t c = 1; c < columns.size(); ++c) {
    if (columns[c]->size() != tension.size()) {
      throw InvalidParameter(std::string(names[c]), fmt::format(": {} values for {} tensions: expected one per test",
                                                                columns[c]->size(), tension.size()));
    }
  }
  for (std::size_t c = 0; c < columns.size(); ++c) {
    for (std::size_t r = 0; r < columns[c]->size(); ++r) {
      const double v = (*columns[c])[r];
      if (!(v > 0.0) || !std::isfinite(v)) throw_invalid(fmt::format("{}[{}]", names[c], r), v, "a finite value > 0");
    }
  }
  SelfDampingTests out;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    sdt_judge_column(
        *columns[c], *sdt_ranges[c], policy, [&](std::size_t r) { return fmt::format("{}[{}]", names[c], r); },
        out.warnings);
  }
  for (std::size_t r = 0; r < tension.size(); ++r) out.tests.push_back({tension[r], frequency[r], amplitude[r], power[r]});
  return out;
}

span::SelfDampingModel SelfDampingFit::model() const {
  span::SelfDampingModel sd;
  sd.law = span::SelfDampingLaw::power;
  sd.k = k.value;
  sd.l = l.value;
  sd.m = m.value;
  sd.n = n.value;
  return sd;
}

double SelfDampingFit::power(const SelfDampingTest& t) const {
  return span::power_law_self_damping(k.value, {l.value, m.value, n.value}, t.amplitude, t.frequency, t.tension);
}

SelfDampingFit fit_self_damping(const std::vector<SelfDampingTest>& tests, std::optional<double> n) {
  if (n) require_finite("n", *n, "");
  SelfDampingFit fit;
  std::vector<double> tensions, frequencies, amplitudes;
  for (const SelfDampingTest& t : tests) {
    tensions.push_back(t.tension);
    frequencies.push_back(t.frequency);
    amplitudes.push_back(t.amplitude);
  }
  fit.tensions = sdt_levels(tensions);
  fit.frequencies = sdt_levels(frequencies);
  fit.amplitudes = sdt_levels(amplitudes);
  fit.n_given = n.has_value();
  fit.points = tests.size();
  fit.parameters = n ? 3 : 4;
  if (fit.tensions.size() == 1 && !n) {
    throw InvalidParameter("n", fmt::format(": not determined: every test is at one tension ({} N); give the tension "
                                            "exponent n to fit k, l and m with it",
                                            format_value(fit.tensions.front())));
  }
  if (fit.points < fit.parameters + 1) {
    throw InvalidParameter("points", fmt::format(" = {}: expected {} tests or more ({} parameters{}, and one more for "
                                                 "their standard errors)",
                                                 fit.points, fit.parameters + 1, fit.parameters,
                                                 n ? ": k, l, m with n given" : ": k, l, m, n"));
  }
  if (fit.frequencies.size() == 1) {
    throw InvalidParameter("frequency_hz", fmt::format(": every test is at one frequency ({} Hz): m is not determined; "
                                                       "expected tests at two frequencies or more",
                                                       format_value(fit.frequencies.front())));
  }
  if (fit.amplitudes.size() == 1) {
    throw InvalidParameter("amplitude_m", fmt::format(": every test is at one amplitude ({} m): l is not determined; "
                                                      "expected tests at two amplitudes or more",
                                                      format_value(fit.amplitudes.front())));
  }
  const Eigen::Index rows = static_cast<Eigen::Index>(tests.size());
  const Eigen::Index cols = static_cast<Eigen::Index>(fit.parameters);
  Eigen::MatrixXd x(rows, cols);
  Eigen::VectorXd y(rows), ln_p(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const SelfDampingTest& t = tests[static_cast<std::size_t>(i)];
    const double ln_t = std::log(t.tension / 1000.0);
    ln_p(i) = std::log(t.power);
    x(i, 0) = 1.0;
    x(i, 1) = std::log(t.amplitude);
    x(i, 2) = std::log(t.frequency);
    if (n) {
      y(i) = ln_p(i) + *n * ln_t;  // ln P + n ln(T/1000) = ln k + l ln Y + m ln f
    } else {
      x(i, 3) = -ln_t;
      y(i) = ln_p(i);
    }
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x);
  if (qr.rank() < cols) {
    throw InvalidParameter("points", fmt::format(": the tests' ln Y, ln f{} are collinear (rank {} of {}): the design "
                                                 "does not separate the exponents; expected amplitudes, frequencies{} "
                                                 "varied independently",
                                                 n ? "" : " and ln T", qr.rank(), cols, n ? "" : " and tensions"));
  }
  const Eigen::VectorXd beta = qr.solve(y);
  const Eigen::VectorXd residual = y - x * beta;
  const double ssr = residual.squaredNorm();
  const double dof = static_cast<double>(rows - cols);
  const double s2 = ssr / dof;
  const Eigen::MatrixXd xtx_inverse = (x.transpose() * x).inverse();
  const auto se = [&](Eigen::Index j) { return std::sqrt(s2 * xtx_inverse(j, j)); };
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  fit.ln_k = {beta(0), se(0)};
  fit.k = {std::exp(beta(0)), std::exp(beta(0)) * se(0)};
  fit.l = {beta(1), se(1)};
  fit.m = {beta(2), se(2)};
  fit.n = n ? Estimate{*n, nan} : Estimate{beta(3), se(3)};
  fit.residuals.assign(residual.data(), residual.data() + residual.size());
  fit.residual_rms = std::sqrt(ssr / static_cast<double>(rows));
  fit.residual_standard_error = std::sqrt(s2);
  const double sst = (ln_p.array() - ln_p.mean()).square().sum();
  fit.r_squared = sst > 0.0 ? 1.0 - ssr / sst : nan;
  if (fit.tensions.size() == 1) {
    fit.notes.push_back(fmt::format("one tension only ({} N): n is not determined by the tests; n = {} as given, k, l "
                                    "and m fitted with it",
                                    format_value(fit.tensions.front()), format_value(*n)));
  } else if (n) {
    fit.notes.push_back(fmt::format("n = {} as given, not fitted, although the tests span {} tensions", format_value(*n),
                                    fit.tensions.size()));
  }
  return fit;
}

}  // namespace stockbridge::measurements
