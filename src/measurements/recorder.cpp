// A vibration recorder's counts against the span (docs/measurements.md): each bin
// judged by Miner on the span's S-N curve, the record predicted by the span's balance
// and climate, band by band; the counts' reading is in recorder_counts.cpp, the
// calibration of span parameters on them in recorder_calibration.cpp.
#include "stockbridge/measurements/recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "recorder_calibration.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::measurements {

namespace {

// Names here are unique among the library's files (unity batches).

constexpr double recorder_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double recorder_seconds_per_day = 86400.0;

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

}  // namespace

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

namespace {

/// The balance's point `next` at `frequency` (predict_record takes a balance at
/// recorder_frequencies), else InvalidParameter naming "balance".
void require_balance_point(const span::SpanBalance& balance, std::size_t next, double frequency) {
  if (next >= balance.points.size()) {
    throw InvalidParameter("balance", fmt::format(": {} points, expected more (one at each of recorder_frequencies: "
                                                  "the next at {} Hz)",
                                                  balance.points.size(), format_value(frequency)));
  }
  const double at = balance.points[next].frequency_hz;
  if (std::abs(at - frequency) > 1e-9 * frequency) {
    throw InvalidParameter("balance", fmt::format(".points[{}] at {} Hz, expected {} Hz (the balance is to be at "
                                                  "recorder_frequencies)",
                                                  next, format_value(at), format_value(frequency)));
  }
}

}  // namespace

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
        require_balance_point(balance, next, p.frequency);
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

}  // namespace stockbridge::measurements
