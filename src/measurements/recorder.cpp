#include "stockbridge/measurements/recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::measurements {

namespace {

// Names here are unique among the library's files (unity batches).

constexpr double recorder_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double recorder_seconds_per_day = 86400.0;

/// A number filling the whole text (trimmed), or none.
std::optional<double> recorder_number(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return std::nullopt;
  const std::size_t last = text.find_last_not_of(" \t");
  const std::string s(text.substr(first, last - first + 1));
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// "low-high" (a '-' not after an exponent's e), both numbers; none otherwise.
std::optional<std::pair<double, double>> recorder_range(std::string_view text) {
  for (std::size_t p = 1; p < text.size(); ++p) {
    if (text[p] != '-' || text[p - 1] == 'e' || text[p - 1] == 'E') continue;
    const auto lo = recorder_number(text.substr(0, p));
    const auto hi = recorder_number(text.substr(p + 1));
    if (lo && hi) return std::make_pair(*lo, *hi);
    return std::nullopt;
  }
  return std::nullopt;
}

/// Judges a Yb edge (mm) against the typical range: a value in um or in m is a slip.
void judge_recorder_yb(const std::string& where, std::string_view column, double value_mm, SlipPolicy policy,
                       std::vector<std::string>& warnings) {
  if (value_mm == 0.0) return;  // a lowest bin from zero
  TypicalRange range = typical::recorder_yb;
  if (value_mm < range.min) range.slip = {1e3, "m"};
  if (const std::optional<UnusualValue> u = unusual(std::string(column), value_mm, range)) {
    judge_unusual(*u, where + ": ", policy, warnings);
  }
}

/// Checks a bin's edges and count; `where` names its place.
void check_recorder_bin(const RecorderBin& b, const std::string& where, std::string_view yb_column,
                        std::string_view frequency_column, std::string_view cycles_column) {
  if (!(b.yb_low >= 0.0) || !(b.yb_high > b.yb_low)) {
    throw InputError(fmt::format("{}: {} = {} to {} mm: an inverted or empty Yb bin; expected 0 <= low < high",
                                 where, yb_column, format_value(1e3 * b.yb_low), format_value(1e3 * b.yb_high)));
  }
  if (!(b.frequency_low > 0.0) || !(b.frequency_high > b.frequency_low)) {
    throw InputError(fmt::format("{}: {} = {} to {} Hz: an inverted or empty frequency bin; expected 0 < low < high",
                                 where, frequency_column, format_value(b.frequency_low),
                                 format_value(b.frequency_high)));
  }
  if (!(b.cycles >= 0.0)) {
    throw InputError(fmt::format("{}: {} = {}: a negative count; expected cycles >= 0", where, cycles_column,
                                 format_value(b.cycles)));
  }
}

bool recorder_overlap(double a_lo, double a_hi, double b_lo, double b_hi) {
  return std::max(a_lo, b_lo) < std::min(a_hi, b_hi);
}

/// The distinct frequency bins, increasing; InputError where two overlap without being the same.
std::vector<std::pair<double, double>> recorder_bands(const std::vector<RecorderBin>& bins) {
  std::vector<std::pair<double, double>> bands;
  for (const RecorderBin& b : bins) {
    const std::pair<double, double> band{b.frequency_low, b.frequency_high};
    if (std::find(bands.begin(), bands.end(), band) != bands.end()) continue;
    for (const auto& other : bands) {
      if (recorder_overlap(band.first, band.second, other.first, other.second)) {
        throw InputError(fmt::format("{}: frequency bin {} to {} Hz overlaps the bin {} to {} Hz of another row; "
                                     "expected one set of disjoint frequency bins",
                                     b.where, format_value(band.first), format_value(band.second),
                                     format_value(other.first), format_value(other.second)));
      }
    }
    bands.push_back(band);
  }
  std::sort(bands.begin(), bands.end());
  return bands;
}

RecorderCounts read_neutral_counts(const std::filesystem::path& path, SlipPolicy policy) {
  const std::string file = path.string();
  const io::CsvRows rows = io::read_csv_rows(
      path, {"yb_pp_mm_low", "yb_pp_mm_high", "frequency_hz_low", "frequency_hz_high", "cycles"}, 1);
  RecorderCounts counts;
  std::vector<RecorderBin> all;
  for (std::size_t i = 0; i < rows.lines.size(); ++i) {
    RecorderBin b{1e-3 * rows.columns[0][i], 1e-3 * rows.columns[1][i], rows.columns[2][i], rows.columns[3][i],
                  rows.columns[4][i], fmt::format("{}:{}", file, rows.lines[i])};
    judge_recorder_yb(b.where, "yb_pp_mm_low", rows.columns[0][i], policy, counts.warnings);
    judge_recorder_yb(b.where, "yb_pp_mm_high", rows.columns[1][i], policy, counts.warnings);
    check_recorder_bin(b, b.where, "yb_pp_mm_low, yb_pp_mm_high", "frequency_hz_low, frequency_hz_high", "cycles");
    for (const RecorderBin& other : all) {
      if (recorder_overlap(b.yb_low, b.yb_high, other.yb_low, other.yb_high) &&
          recorder_overlap(b.frequency_low, b.frequency_high, other.frequency_low, other.frequency_high)) {
        throw InputError(fmt::format("{}: the bin Yb {} to {} mm, {} to {} Hz overlaps the bin of line {}; expected "
                                     "disjoint bins, each counted once",
                                     b.where, format_value(1e3 * b.yb_low), format_value(1e3 * b.yb_high),
                                     format_value(b.frequency_low), format_value(b.frequency_high),
                                     other.where.substr(file.size() + 1)));
      }
    }
    all.push_back(b);
  }
  counts.bands = recorder_bands(all);
  for (RecorderBin& b : all) {
    if (b.cycles > 0.0) counts.bins.push_back(std::move(b));
  }
  return counts;
}

RecorderCounts read_matrix_counts(const std::filesystem::path& path, SlipPolicy policy) {
  const std::string file = path.string();
  const io::CsvCells cells = io::read_csv_cells(path);
  RecorderCounts counts;
  counts.matrix_form = true;
  if (cells.header.size() < 2) {
    throw InputError(fmt::format("{}: header: only the column yb_pp_mm; expected frequency bins as further columns, "
                                 "e.g. '5-10 hz'",
                                 file));
  }
  if (cells.rows.empty()) throw InputError(fmt::format("{}: no rows: expected one row per Yb bin", file));
  std::vector<std::pair<double, double>> columns;
  for (std::size_t j = 1; j < cells.header.size(); ++j) {
    std::string text = cells.header[j];
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    std::optional<std::pair<double, double>> band;
    if (lower.size() > 2 && lower.ends_with("hz")) band = recorder_range(std::string_view(lower).substr(0, lower.size() - 2));
    if (!band || !(band->first > 0.0) || !(band->second > band->first)) {
      throw InputError(fmt::format("{}: header, column {} '{}': expected a frequency bin as 'low-high hz' with 0 < "
                                   "low < high, e.g. '5-10 hz'",
                                   file, j + 1, printable(text)));
    }
    for (std::size_t k = 0; k < columns.size(); ++k) {
      if (recorder_overlap(band->first, band->second, columns[k].first, columns[k].second)) {
        throw InputError(fmt::format("{}: header, column {} '{}': overlaps column {} '{}'; expected disjoint "
                                     "frequency bins",
                                     file, j + 1, printable(text), k + 2, printable(cells.header[k + 1])));
      }
    }
    columns.push_back(*band);
  }
  std::vector<std::pair<double, double>> rows_yb;
  for (std::size_t i = 0; i < cells.rows.size(); ++i) {
    const std::vector<std::string>& row = cells.rows[i];
    const std::string where = fmt::format("{}:{}", file, cells.lines[i]);
    const std::optional<std::pair<double, double>> yb = recorder_range(row[0]);
    if (!yb) {
      throw InputError(fmt::format("{}, column yb_pp_mm: '{}': expected a Yb bin as 'low-high' in mm, e.g. "
                                   "'0.1-0.2'",
                                   where, printable(row[0])));
    }
    judge_recorder_yb(where, "yb_pp_mm (low)", yb->first, policy, counts.warnings);
    judge_recorder_yb(where, "yb_pp_mm (high)", yb->second, policy, counts.warnings);
    for (std::size_t k = 0; k < rows_yb.size(); ++k) {
      if (recorder_overlap(yb->first, yb->second, rows_yb[k].first, rows_yb[k].second)) {
        throw InputError(fmt::format("{}, column yb_pp_mm: the Yb bin {} overlaps that of line {}; expected disjoint "
                                     "Yb bins",
                                     where, printable(row[0]), cells.lines[k]));
      }
    }
    rows_yb.push_back(*yb);
    for (std::size_t j = 1; j < row.size(); ++j) {
      const std::string at = fmt::format("{}, column '{}'", where, printable(cells.header[j]));
      double cycles = 0.0;
      if (!row[j].empty()) {
        const std::optional<double> n = recorder_number(row[j]);
        if (!n) throw InputError(fmt::format("{}: '{}': expected a count of cycles (a number >= 0; empty: 0)", at, printable(row[j])));
        cycles = *n;
      }
      RecorderBin b{1e-3 * yb->first, 1e-3 * yb->second, columns[j - 1].first, columns[j - 1].second, cycles, at};
      check_recorder_bin(b, at, "yb_pp_mm", "the column's bin", "cycles");
      if (b.cycles > 0.0) counts.bins.push_back(std::move(b));
    }
  }
  counts.bands = columns;
  std::sort(counts.bands.begin(), counts.bands.end());
  return counts;
}

/// The band [lo, hi] cut to the wind band; none where they do not overlap.
std::optional<span::Interval> recorder_cut(const std::pair<double, double>& band, const span::Span& span) {
  const span::Interval wind = span.wind().frequency_band(span.conductor().diameter);
  const double lo = std::max(band.first, wind.lo);
  const double hi = std::min(band.second, wind.hi);
  if (!(hi > lo)) return std::nullopt;
  return span::Interval{lo, hi};
}

/// The points of a band's intervals: equal in ln f, each at its geometric centre.
std::vector<PredictedPoint> recorder_band_points(const span::Interval& cut, int n) {
  std::vector<PredictedPoint> points(static_cast<std::size_t>(n));
  const double ratio = std::log(cut.hi / cut.lo);
  for (int k = 0; k < n; ++k) {
    PredictedPoint& p = points[static_cast<std::size_t>(k)];
    p.frequency_low = cut.lo * std::exp(ratio * k / n);
    p.frequency_high = cut.lo * std::exp(ratio * (k + 1) / n);
    p.frequency = std::sqrt(p.frequency_low * p.frequency_high);
  }
  return points;
}

const span::LifeModel& recorder_climate(const span::Span& span) {
  if (!span.fatigue().life) {
    throw InvalidParameter("fatigue.wind_weibull",
                           ": the span file gives no climate; the prediction of a record needs [fatigue] wind_weibull = "
                           "{ shape, scale } and aeolian_fraction");
  }
  return *span.fatigue().life;
}

/// Figures of (stress, cycles, Yb) items.
struct RecorderItem {
  double stress = 0.0, cycles = 0.0, yb = 0.0;
};

DamageFigures recorder_figures(const std::vector<RecorderItem>& items, const span::Span& span, double days) {
  DamageFigures f;
  f.days = days;
  double above = 0.0;
  const double limit = span.endurance_limit();
  for (const RecorderItem& it : items) {
    if (!(it.cycles > 0.0)) continue;
    f.cycles += it.cycles;
    f.damage += it.cycles / sn_cycles_to_failure(span, it.stress);
    f.max_yb = std::max(f.max_yb, it.yb);
    f.max_stress = std::max(f.max_stress, it.stress);
    if (it.stress > limit) above += it.cycles;
  }
  f.fraction_above_endurance = f.cycles > 0.0 ? above / f.cycles : 0.0;
  f.damage_per_year = f.damage * 365.25 / days;
  f.life_years = f.damage_per_year > 0.0 ? 1.0 / f.damage_per_year : std::numeric_limits<double>::infinity();
  return f;
}

// ---- calibration ---------------------------------------------------------

bool recorder_log_key(const std::string& key) { return key != "wind.turbulence_intensity"; }

/// The bands of the fit: recorded cycles and a known mean (a prediction is checked per evaluation).
struct RecorderFit {
  const RecorderCounts& counts;
  const span::Span& span;
  const span::SpanTables& tables;
  const span::BalanceOptions& balance;
  const RecorderOptions& options;
  std::vector<std::size_t> bands;  // indices into the prediction's bands
  std::vector<double> target, weight;
  int balances = 0;

  span::Span span_at(const std::vector<double>& u) const {
    span::Span s = span;
    for (std::size_t i = 0; i < options.calibrate.size(); ++i) {
      const std::string& key = options.calibrate[i];
      s = with_parameter(s, key, recorder_log_key(key) ? std::exp(u[i]) : u[i]);
    }
    return s;
  }

  RecorderPrediction predict(const std::vector<double>& u) {
    const span::Span s = span_at(u);
    ++balances;
    const span::SpanBalance b = span::run_balance(s, tables, balance);
    return predict_record(counts, s, b, options.points_per_band, options.days);
  }

  /// The residuals (predicted - recorded mean ln Yb), none where a fit band is not known.
  std::optional<std::vector<double>> residuals(const std::vector<double>& u) {
    const RecorderPrediction p = predict(u);
    std::vector<double> r;
    for (std::size_t k = 0; k < bands.size(); ++k) {
      const RecorderBand& band = p.bands[bands[k]];
      if (!band.converged || !std::isfinite(band.predicted_mean_ln_yb)) return std::nullopt;
      r.push_back(band.predicted_mean_ln_yb - target[k]);
    }
    return r;
  }

  double cost(const std::vector<double>& r) const {
    double c = 0.0;
    for (std::size_t k = 0; k < r.size(); ++k) c += weight[k] * r[k] * r[k];
    return c;
  }
};

double recorder_clamp(const std::string& key, double u) {
  return key == "wind.turbulence_intensity" ? std::clamp(u, 0.0, 1.0) : u;
}

/// Solves the p x p (p <= 2) system A x = b; false where singular.
bool recorder_solve(const std::vector<std::vector<double>>& a, const std::vector<double>& b, std::vector<double>& x) {
  if (b.size() == 1) {
    if (!(std::abs(a[0][0]) > 0.0)) return false;
    x = {b[0] / a[0][0]};
    return true;
  }
  const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) return false;
  x = {(b[0] * a[1][1] - a[0][1] * b[1]) / det, (a[0][0] * b[1] - a[1][0] * b[0]) / det};
  return true;
}

RecorderCalibration calibrate_record(const RecorderCounts& counts, const span::Span& span,
                                     const span::SpanTables& tables, const span::BalanceOptions& balance,
                                     const RecorderOptions& options, const RecorderPrediction& before) {
  RecorderFit fit{counts, span, tables, balance, options, {}, {}, {}, 0};
  for (std::size_t k = 0; k < before.bands.size(); ++k) {
    const RecorderBand& b = before.bands[k];
    if (b.recorded_cycles > 0.0 && std::isfinite(b.recorded_mean_ln_yb) && b.converged &&
        std::isfinite(b.predicted_mean_ln_yb)) {
      fit.bands.push_back(k);
      fit.target.push_back(b.recorded_mean_ln_yb);
      fit.weight.push_back(b.recorded_cycles);
    }
  }
  const std::size_t p = options.calibrate.size();
  RecorderCalibration c;
  std::vector<double> u(p);
  for (std::size_t i = 0; i < p; ++i) {
    const double v = parameter_of(span, options.calibrate[i]);
    c.values.push_back({options.calibrate[i], v, v, recorder_nan});
    u[i] = recorder_log_key(options.calibrate[i]) ? std::log(v) : v;
  }
  const std::size_t nb = fit.bands.size();
  double weight_sum = 0.0;
  for (const double w : fit.weight) weight_sum += w;
  if (nb == 0) {
    c.message = "no band with recorded cycles and a converged prediction: nothing to fit";
    c.residual_before = c.residual_after = recorder_nan;
    c.prediction = before;
    c.span = span;
    return c;
  }
  std::vector<double> r(nb);
  for (std::size_t k = 0; k < nb; ++k) r[k] = before.bands[fit.bands[k]].predicted_mean_ln_yb - fit.target[k];
  double cost = fit.cost(r);
  c.residual_before = std::sqrt(cost / weight_sum);

  // The Jacobian of the residuals by central differences (one-sided at a bound).
  const auto jacobian = [&](const std::vector<double>& at) -> std::optional<std::vector<std::vector<double>>> {
    std::vector<std::vector<double>> j(nb, std::vector<double>(p));
    for (std::size_t i = 0; i < p; ++i) {
      const std::string& key = options.calibrate[i];
      const double h = recorder_log_key(key) ? 1e-3 : std::max(1e-4, 1e-2 * at[i]);
      std::vector<double> up = at, down = at;
      up[i] = recorder_clamp(key, at[i] + h);
      down[i] = recorder_clamp(key, at[i] - h);
      const auto ru = fit.residuals(up);
      const auto rd = fit.residuals(down);
      if (!ru || !rd || !(up[i] > down[i])) return std::nullopt;
      for (std::size_t k = 0; k < nb; ++k) j[k][i] = ((*ru)[k] - (*rd)[k]) / (up[i] - down[i]);
    }
    return j;
  };
  const auto normal = [&](const std::vector<std::vector<double>>& j, const std::vector<double>& w) {
    std::vector<std::vector<double>> a(p, std::vector<double>(p, 0.0));
    for (std::size_t k = 0; k < nb; ++k) {
      for (std::size_t i = 0; i < p; ++i) {
        for (std::size_t m = 0; m < p; ++m) a[i][m] += w[k] * j[k][i] * j[k][m];
      }
    }
    return a;
  };

  double lambda = 1e-3;
  std::optional<std::vector<std::vector<double>>> j_at_u;
  for (c.iterations = 0; c.iterations < options.max_iterations; ++c.iterations) {
    j_at_u = jacobian(u);
    if (!j_at_u) {
      c.message = "the balance did not converge next to the parameters: no Jacobian";
      break;
    }
    const std::vector<std::vector<double>>& j = *j_at_u;
    const std::vector<std::vector<double>> a = normal(j, fit.weight);
    std::vector<double> g(p, 0.0);
    for (std::size_t k = 0; k < nb; ++k) {
      for (std::size_t i = 0; i < p; ++i) g[i] -= fit.weight[k] * j[k][i] * r[k];
    }
    bool accepted = false;
    double step = 0.0;
    while (lambda < 1e10) {
      std::vector<std::vector<double>> damped = a;
      for (std::size_t i = 0; i < p; ++i) damped[i][i] *= 1.0 + lambda;
      std::vector<double> delta;
      if (!recorder_solve(damped, g, delta)) {
        lambda *= 10.0;
        continue;
      }
      std::vector<double> trial = u;
      for (std::size_t i = 0; i < p; ++i) trial[i] = recorder_clamp(options.calibrate[i], u[i] + delta[i]);
      const auto rt = fit.residuals(trial);
      if (rt && fit.cost(*rt) <= cost) {
        step = 0.0;
        for (std::size_t i = 0; i < p; ++i) step = std::max(step, std::abs(trial[i] - u[i]));
        const double decrease = cost - fit.cost(*rt);
        u = trial;
        r = *rt;
        cost = fit.cost(r);
        lambda = std::max(lambda / 10.0, 1e-12);
        accepted = true;
        if (step < 1e-6 || decrease <= 1e-12 * std::max(cost, 1e-300)) c.converged = true;
        break;
      }
      lambda *= 10.0;
    }
    if (!accepted) {
      c.converged = true;  // no step lowers the cost: a minimum to the step's resolution
      break;
    }
    if (c.converged) {
      j_at_u.reset();
      break;
    }
  }
  if (!c.converged && c.message.empty()) c.message = fmt::format("{} iterations without convergence", c.iterations);
  if (c.converged) c.message = fmt::format("converged in {} iterations", c.iterations);
  // A value held at its bound is no fit: the record asks for more than the key can give.
  for (std::size_t i = 0; i < p; ++i) {
    if (options.calibrate[i] == "wind.turbulence_intensity" && (u[i] <= 0.0 || u[i] >= 1.0)) {
      c.converged = false;
      c.message = fmt::format("{} ran to its bound, {}: the record lies beyond what it can explain (the weighted RMS "
                              "of ln Yb is still {:.3g}); check the record's units and days, the dampers, or calibrate "
                              "another key",
                              options.calibrate[i], u[i], std::sqrt(cost / weight_sum));
    }
  }
  if (!j_at_u) j_at_u = jacobian(u);
  if (j_at_u && nb > p) {
    std::vector<double> w(nb);
    for (std::size_t k = 0; k < nb; ++k) w[k] = fit.weight[k] * static_cast<double>(nb) / weight_sum;
    double s2 = 0.0;
    for (std::size_t k = 0; k < nb; ++k) s2 += w[k] * r[k] * r[k];
    s2 /= static_cast<double>(nb - p);
    const std::vector<std::vector<double>> a = normal(*j_at_u, w);
    for (std::size_t i = 0; i < p; ++i) {
      std::vector<double> e(p, 0.0), col;
      e[i] = 1.0;
      if (!recorder_solve(a, e, col)) continue;
      const double se_u = std::sqrt(s2 * col[i]);
      const double value = recorder_log_key(options.calibrate[i]) ? std::exp(u[i]) : u[i];
      c.values[i].standard_error = recorder_log_key(options.calibrate[i]) ? value * se_u : se_u;
    }
  }
  for (std::size_t i = 0; i < p; ++i) {
    c.values[i].value = recorder_log_key(options.calibrate[i]) ? std::exp(u[i]) : u[i];
  }
  c.residual_after = std::sqrt(cost / weight_sum);
  c.span = fit.span_at(u);
  const span::SpanBalance b = span::run_balance(*c.span, tables, balance);
  ++fit.balances;
  c.prediction = predict_record(counts, *c.span, b, options.points_per_band, options.days);
  c.balances = fit.balances;
  return c;
}

// ---- the span file's text ---------------------------------------------------

std::string recorder_value_text(double value) { return fmt::format("{:.10g}", value); }

}  // namespace

RecorderCounts read_recorder_counts(const std::filesystem::path& path, SlipPolicy policy) {
  const std::vector<std::string> header = io::read_csv_header(path);
  const bool neutral = std::find(header.begin(), header.end(), "yb_pp_mm_low") != header.end();
  RecorderCounts counts;
  if (neutral) {
    counts = read_neutral_counts(path, policy);
  } else if (!header.empty() && header.front() == "yb_pp_mm") {
    counts = read_matrix_counts(path, policy);
  } else {
    throw InputError(fmt::format("{}: header '{}': expected the neutral form's columns yb_pp_mm_low, yb_pp_mm_high, "
                                 "frequency_hz_low, frequency_hz_high, cycles, or the matrix form's first column "
                                 "yb_pp_mm followed by frequency bins 'low-high hz'",
                                 path.string(), printable(header.empty() ? std::string() : header.front())));
  }
  if (counts.bins.empty()) {
    throw InputError(fmt::format("{}: no cycles counted in any bin; expected at least one bin with cycles > 0",
                                 path.string()));
  }
  return counts;
}

void check_recorder_band(const RecorderCounts& counts, const span::Span& span) {
  const span::Interval wind = span.wind().frequency_band(span.conductor().diameter);
  for (const RecorderBin& b : counts.bins) {
    if (!recorder_cut({b.frequency_low, b.frequency_high}, span)) {
      throw InputError(fmt::format("{}: frequency bin {} to {} Hz: outside the span's wind band {:.4g} to {:.4g} Hz "
                                   "(St U / D for U from speed_min to speed_max); expected a bin that overlaps it",
                                   b.where, format_value(b.frequency_low), format_value(b.frequency_high), wind.lo,
                                   wind.hi));
    }
  }
}

double sn_cycles_to_failure(const span::Span& span, double stress) {
  return span.sn_curve().cycles_to_failure(stress);
}

void RecorderOptions::validate() const {
  require_positive("days", days, "days");
  require_in_range("points_per_band", points_per_band, 1, 50);
  require_in_range("max_iterations", max_iterations, 1, 1000);
  if (calibrate.size() > 2) {
    throw InvalidParameter("calibrate", fmt::format(": {} keys; expected one or two of wind.turbulence_intensity, "
                                                    "wind.power_scale, self_damping.k",
                                                    calibrate.size()));
  }
  for (std::size_t i = 0; i < calibrate.size(); ++i) {
    const std::string& key = calibrate[i];
    if (key != "wind.turbulence_intensity" && key != "wind.power_scale" && key != "self_damping.k") {
      throw InvalidParameter("calibrate", fmt::format(" = '{}': expected wind.turbulence_intensity, wind.power_scale or "
                                                      "self_damping.k",
                                                      printable(key)));
    }
    if (i == 1 && key == calibrate[0]) {
      throw InvalidParameter("calibrate", fmt::format(" = '{}' twice: expected distinct keys", key));
    }
  }
  if (calibrate.size() == 2 && calibrate[0] != "self_damping.k" && calibrate[1] != "self_damping.k") {
    throw InvalidParameter("calibrate", ": wind.turbulence_intensity and wind.power_scale both scale the wind's power "
                                        "(one factor): expected one of them, alone or with self_damping.k");
  }
}

std::vector<RecorderBinResult> judge_bins(const RecorderCounts& counts, const span::Span& span) {
  std::vector<RecorderBinResult> out;
  const double x_b = span.fatigue().yb_distance;
  for (const RecorderBin& b : counts.bins) {
    RecorderBinResult r{b};
    r.stress = span::poffenberger_swart_stress(span.conductor(), span.tension(), b.yb_high, x_b);
    r.microstrain_pp = span::bending_strain_pp_microstrain(span.conductor(), r.stress);
    r.cycles_to_failure = sn_cycles_to_failure(span, r.stress);
    r.damage = b.cycles / r.cycles_to_failure;
    out.push_back(std::move(r));
  }
  return out;
}

DamageFigures measured_figures(const std::vector<RecorderBinResult>& bins, const span::Span& span, double days) {
  std::vector<RecorderItem> items;
  for (const RecorderBinResult& b : bins) items.push_back({b.stress, b.bin.cycles, b.bin.yb_high});
  return recorder_figures(items, span, days);
}

std::vector<double> recorder_frequencies(const RecorderCounts& counts, const span::Span& span, int points_per_band) {
  std::vector<double> f;
  for (const auto& band : counts.bands) {
    if (const auto cut = recorder_cut(band, span)) {
      for (const PredictedPoint& p : recorder_band_points(*cut, points_per_band)) f.push_back(p.frequency);
    }
  }
  return f;
}

RecorderPrediction predict_record(const RecorderCounts& counts, const span::Span& span,
                                  const span::SpanBalance& balance, int points_per_band, double days) {
  const span::LifeModel& climate = recorder_climate(span);
  const double diameter = span.conductor().diameter;
  RecorderPrediction out;
  std::size_t next = 0;
  std::vector<RecorderItem> items;
  for (const auto& band : counts.bands) {
    RecorderBand rb;
    rb.frequency_low = band.first;
    rb.frequency_high = band.second;
    double sum_ln = 0.0;
    for (const RecorderBin& b : counts.bins) {
      if (b.frequency_low != band.first || b.frequency_high != band.second) continue;
      rb.recorded_cycles += b.cycles;
      sum_ln += b.cycles * std::log(1e3 * std::sqrt(b.yb_low * b.yb_high));
    }
    rb.recorded_mean_ln_yb = rb.recorded_cycles > 0.0 ? sum_ln / rb.recorded_cycles : recorder_nan;
    const auto cut = recorder_cut(band, span);
    double predicted_ln = 0.0;
    bool known = cut.has_value();
    if (cut) {
      for (PredictedPoint p : recorder_band_points(*cut, points_per_band)) {
        if (next >= balance.points.size() || std::abs(balance.points[next].frequency_hz - p.frequency) > 1e-9 * p.frequency) {
          throw std::invalid_argument("predict_record: the balance is not at recorder_frequencies");
        }
        const span::BalancePoint& bp = balance.points[next++];
        const double u_lo = span.wind().wind_speed(p.frequency_low, diameter);
        const double u_hi = span.wind().wind_speed(p.frequency_high, diameter);
        p.cycles = days * recorder_seconds_per_day * climate.aeolian_fraction *
                   std::max(0.0, climate.wind_weibull.cdf(u_hi) - climate.wind_weibull.cdf(u_lo)) * p.frequency;
        p.converged = bp.converged();
        p.yb = p.converged ? bp.bending_amplitude : recorder_nan;
        p.stress = p.converged ? bp.stress_poffenberger_swart : recorder_nan;
        if (p.converged) {
          rb.predicted_cycles += p.cycles;
          items.push_back({p.stress, p.cycles, p.yb});
          if (p.yb > 0.0) {
            predicted_ln += p.cycles * std::log(1e3 * p.yb);
          } else if (p.cycles > 0.0) {
            known = false;  // no vibration: ln Yb has no mean
          }
        } else {
          rb.converged = false;
          known = false;
          ++out.failed_points;
        }
        out.points.push_back(p);
      }
    }
    rb.predicted_mean_ln_yb = known && rb.predicted_cycles > 0.0 ? predicted_ln / rb.predicted_cycles : recorder_nan;
    out.bands.push_back(rb);
  }
  out.figures = recorder_figures(items, span, days);
  return out;
}

span::Span with_parameter(const span::Span& s, const std::string& key, double value) {
  span::WindModel wind = s.wind();
  span::SelfDampingModel sd = s.self_damping();
  if (key == "wind.turbulence_intensity") {
    if (wind.law != span::WindLaw::foti) {
      throw InvalidParameter(key, fmt::format(": the span's wind law is '{}'; only law = 'foti' has a turbulence "
                                              "intensity (wind.power_scale scales any law)",
                                              span::wind_law_name(wind.law)));
    }
    wind.turbulence_intensity = value;
    wind.turbulence_terrain.reset();
  } else if (key == "wind.power_scale") {
    wind.power_scale = value;
  } else if (key == "self_damping.k") {
    if (sd.law == span::SelfDampingLaw::foti) {
      throw InvalidParameter(key, ": the span's self-damping law is 'foti', which has no factor k; expected a power "
                                  "law (noiseux-1991, ..., power)");
    }
    sd.k = value;
  } else {
    throw InvalidParameter("calibrate", fmt::format(" = '{}': expected wind.turbulence_intensity, wind.power_scale or "
                                                    "self_damping.k",
                                                    printable(key)));
  }
  return within_field(key.substr(0, key.find('.')), [&] {
    return span::Span(s.conductor(), s.length(), s.tension(), std::move(wind), std::move(sd), s.dampers(), s.fatigue(),
                      s.terrain());
  });
}

double parameter_of(const span::Span& s, const std::string& key) {
  if (key == "wind.turbulence_intensity") return s.wind().turbulence_intensity;
  if (key == "wind.power_scale") return s.wind().power_scale;
  if (key == "self_damping.k") return s.self_damping().factor(s.conductor());
  throw InvalidParameter("calibrate", fmt::format(" = '{}': not a calibrated key", printable(key)));
}

RecorderResult analyse_record(const RecorderCounts& counts, const span::Span& span,
                              const span::BalanceOptions& balance, const RecorderOptions& options) {
  options.validate();
  recorder_climate(span);
  for (const std::string& key : options.calibrate) with_parameter(span, key, parameter_of(span, key));  // the law has it
  RecorderResult result;
  result.bins = judge_bins(counts, span);
  result.measured = measured_figures(result.bins, span, options.days);
  result.frequencies = recorder_frequencies(counts, span, options.points_per_band);
  if (result.frequencies.empty()) {
    throw InvalidParameter("counts", ": no frequency bin overlaps the span's wind band");
  }
  const span::SpanTables tables(span, result.frequencies, balance.table);
  const auto start = std::chrono::steady_clock::now();
  const span::SpanBalance b = span::run_balance(span, tables, balance);
  result.seconds_per_balance = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.predicted = predict_record(counts, span, b, options.points_per_band, options.days);
  if (!options.calibrate.empty()) {
    result.calibration = calibrate_record(counts, span, tables, balance, options, result.predicted);
  }
  return result;
}

std::string calibrated_span_text(const std::filesystem::path& source, const std::vector<CalibratedValue>& values) {
  const std::string file = source.string();
  std::ifstream in(source, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot be read", file));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<std::string> lines;
  {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t nl = text.find('\n', start);
      if (nl == std::string::npos) {
        if (start < text.size()) lines.push_back(text.substr(start));
        break;
      }
      lines.push_back(text.substr(start, nl - start + 1));
      start = nl + 1;
    }
  }
  toml::table document;
  try {
    document = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: {}", file, e.source().begin.line, e.description()));
  }
  std::vector<std::string> appended;
  std::vector<std::pair<std::size_t, std::string>> inserts;  // after line (1-based), text
  for (const CalibratedValue& v : values) {
    const std::size_t dot = v.key.find('.');
    const std::string table_name = v.key.substr(0, dot);
    const std::string key = v.key.substr(dot + 1);
    const std::string value = recorder_value_text(v.value);
    const toml::table* table = document[table_name].as_table();
    if (!table) {
      appended.push_back(fmt::format("\n[{}]\n{} = {}  # calibrated on a vibration recorder's counts\n", table_name, key, value));
      continue;
    }
    if (table->is_inline()) {
      throw InputError(fmt::format("{}:{}: [{}] is an inline table: expected a [{}] table whose key {} can be set",
                                   file, table->source().begin.line, table_name, table_name, key));
    }
    if (const toml::node* node = table->get(key)) {
      const std::size_t line = node->source().begin.line;
      if (line == 0 || line > lines.size()) {
        throw InputError(fmt::format("{}: {}.{}: its line is not known; expected 'key = value' on one line", file,
                                     table_name, key));
      }
      std::string& l = lines[line - 1];
      const std::size_t eq = l.find('=');
      if (eq == std::string::npos) {
        throw InputError(fmt::format("{}:{}: {}.{}: expected 'key = value' on one line", file, line, table_name, key));
      }
      const bool crlf = l.ends_with("\r\n");
      const std::string rest = l.substr(eq + 1);
      const std::size_t hash = rest.find('#');
      std::string comment = hash == std::string::npos ? std::string() : "  " + rest.substr(hash);
      while (!comment.empty() && (comment.back() == '\n' || comment.back() == '\r')) comment.pop_back();
      l = l.substr(0, eq + 1) + " " + value + comment + (crlf ? "\r\n" : "\n");
    } else {
      inserts.emplace_back(table->source().begin.line,
                           fmt::format("{} = {}  # calibrated on a vibration recorder's counts\n", key, value));
    }
  }
  std::sort(inserts.begin(), inserts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [after, line] : inserts) {
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(std::min(after, lines.size())), line);
  }
  std::string out;
  for (const std::string& l : lines) out += l;
  if (!out.empty() && out.back() != '\n') out += '\n';
  for (const std::string& a : appended) out += a;
  return out;
}

}  // namespace stockbridge::measurements
