#pragma once
// Vibration recorders (MODEL.md section 14; docs/measurements.md, "Vibration
// recorders"): a recorder's count matrix turned into a fatigue judgement, the
// span's own balance and climate predicting the same record, and a parameter of
// the span calibrated so that the balance meets the record.
//
// A recorder counts cycles of Yb (peak-to-peak at x_b from the clamp) in bins of Yb
// and of frequency over `days` of recording. Per bin:
//   * the stress at the bin's UPPER Yb edge (conservative): Poffenberger-Swart,
//     sigma = K Yb (span/fatigue.hpp);
//   * the cycles to failure N(sigma) of the span's S-N curve (sn_cycles_to_failure);
//   * Miner's damage n / N.
// Per frequency band of the record (its distinct frequency bins) the bin value is
// the geometric mean of the Yb edges, sqrt(Yb_low Yb_high), and the band's mean
// ln Yb is weighted by the counts.
//
// Predicted: the balance (span/balance.hpp) at `points_per_band` frequencies inside
// each band (the band cut to the wind band, split into equal intervals of ln f, a
// frequency at each interval's geometric centre). An interval [f_a, f_b] holds
//     n = days 86400 q (F(U_b) - F(U_a)) f,   U = f D / St,
// cycles at the balance's Yb(f) (F the Weibull CDF, q the aeolian fraction). A point
// that did not converge never enters a sum: its band is flagged.
//
// Calibration: `wind.turbulence_intensity` (law foti), `wind.power_scale` (any law)
// or `self_damping.k` (a power law), one or two of them, fitted so that per band
// the predicted mean ln Yb meets the record's, least squares weighted by the band's
// recorded cycles (Levenberg-Marquardt, the Jacobian by central differences of the
// balance; the dampers' impedance tables made once); the standard errors from
// s^2 (J^T W J)^-1 with the weights scaled to a mean of 1.
//
// Units: SI inside (Yb in m, stresses in Pa); the files' Yb in mm.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/span.hpp"

namespace stockbridge::measurements {

/// One bin of a recorder's counts.
struct RecorderBin {
  double yb_low = 0.0;          ///< m, peak-to-peak
  double yb_high = 0.0;         ///< m
  double frequency_low = 0.0;   ///< Hz
  double frequency_high = 0.0;  ///< Hz
  double cycles = 0.0;          ///< counted over the record
  std::string where;            ///< "counts.csv:5" or "counts.csv:5, column '10-20 hz'"
};

/// A recorder's counts as read.
struct RecorderCounts {
  std::vector<RecorderBin> bins;  ///< non-empty bins only
  /// The frequency bands (distinct frequency bins; a matrix's every column), increasing.
  std::vector<std::pair<double, double>> bands;
  bool matrix_form = false;
  std::vector<std::string> warnings;  ///< located: values outside the typical Yb range
};

/// Reads COUNTS.csv in either form (docs/measurements.md): the neutral form, one
/// row per non-empty bin with columns yb_pp_mm_low, yb_pp_mm_high, frequency_hz_low,
/// frequency_hz_high, cycles; or the matrix form, first column `yb_pp_mm` with the
/// Yb bins as "low-high" (mm), the other columns' headers the frequency bins as
/// "low-high hz", cells the cycles (empty: 0). InputError in one line naming the
/// file, the line (and the column): an inverted or overlapping bin, a negative or
/// non-numeric count, a Yb that a unit slip explains (m or um: typical::recorder_yb,
/// refused under SlipPolicy::refuse), no cycles at all.
RecorderCounts read_recorder_counts(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);

/// InputError naming the bin's row where a bin lies outside the span's wind band
/// (St speed_min / D to St speed_max / D: no overlap).
void check_recorder_band(const RecorderCounts& counts, const span::Span& span);

/// The span's S-N curve as the recorder uses it: the cycles to failure at a
/// zero-to-peak stress (Pa), by the curve in force (Span::sn_curve: the CIGRE Safe
/// Border Line of the conductor's aluminium layers, or the span file's `[fatigue]
/// curve`), as the span life inverts it (span/fatigue.hpp).
double sn_cycles_to_failure(const span::Span& span, double stress);

/// A bin as judged.
struct RecorderBinResult {
  RecorderBin bin;
  double stress = 0.0;              ///< Poffenberger-Swart at yb_high, Pa
  double microstrain_pp = 0.0;
  double cycles_to_failure = 0.0;   ///< infinite below the curve's reach
  double damage = 0.0;              ///< cycles / cycles_to_failure
};

/// Damage figures over a record (measured) or its prediction.
struct DamageFigures {
  double damage = 0.0;              ///< Miner's sum over the record's days
  double damage_per_year = 0.0;     ///< damage 365.25 / days
  double life_years = 0.0;          ///< 1 / damage_per_year (infinite for none)
  double max_yb = 0.0;              ///< m (measured: the largest bin's upper edge)
  double max_stress = 0.0;          ///< Pa
  double fraction_above_endurance = 0.0;  ///< of the cycles, stress > Span::endurance_limit()
  double cycles = 0.0;
  double days = 0.0;
};

/// One balance frequency of the prediction, standing for an interval of its band.
struct PredictedPoint {
  double frequency = 0.0;       ///< Hz
  double frequency_low = 0.0;   ///< its interval, Hz
  double frequency_high = 0.0;
  double cycles = 0.0;          ///< over the record's days
  double yb = 0.0;              ///< the balance's Yb, m (NaN: not converged)
  double stress = 0.0;          ///< Pa
  bool converged = false;
};

/// A frequency band of the record, recorded and predicted side by side.
struct RecorderBand {
  double frequency_low = 0.0, frequency_high = 0.0;  ///< Hz, as recorded
  double recorded_cycles = 0.0;
  double recorded_mean_ln_yb = 0.0;  ///< count-weighted mean of ln(Yb / 1 mm); NaN without cycles
  double predicted_cycles = 0.0;     ///< of the converged points
  double predicted_mean_ln_yb = 0.0; ///< cycle-weighted mean of ln(Yb / 1 mm); NaN where not known
  bool converged = true;             ///< every balance point of the band converged
};

/// The prediction of a record by a span's balance and climate.
struct RecorderPrediction {
  DamageFigures figures;
  std::vector<RecorderBand> bands;
  std::vector<PredictedPoint> points;
  int failed_points = 0;
};

/// A calibrated key.
struct CalibratedValue {
  std::string key;  ///< "wind.turbulence_intensity", "wind.power_scale", "self_damping.k"
  double start = 0.0;
  double value = 0.0;
  double standard_error = 0.0;  ///< NaN: not determined (no more bands than keys)
};

struct RecorderCalibration {
  std::vector<CalibratedValue> values;
  double residual_before = 0.0;  ///< sqrt(sum w r^2 / sum w), r in ln Yb
  double residual_after = 0.0;
  int iterations = 0;
  int balances = 0;  ///< balance runs of the fit
  bool converged = false;
  std::string message;
  std::optional<span::Span> span;  ///< the span with the fitted values
  RecorderPrediction prediction;   ///< of the calibrated span
};

struct RecorderOptions {
  double days = 0.0;         ///< the record's length (> 0)
  int points_per_band = 3;   ///< balance frequencies per band (1 to 50)
  std::vector<std::string> calibrate;  ///< keys (at most two, distinct)
  int max_iterations = 30;

  /// InvalidParameter naming "days", "points_per_band" or "calibrate".
  void validate() const;
};

struct RecorderResult {
  std::vector<RecorderBinResult> bins;
  DamageFigures measured;
  RecorderPrediction predicted;
  std::optional<RecorderCalibration> calibration;
  std::vector<double> frequencies;  ///< the balance's, Hz
  double seconds_per_balance = 0.0;
};

/// The measured figures of the counts alone.
std::vector<RecorderBinResult> judge_bins(const RecorderCounts& counts, const span::Span& span);
DamageFigures measured_figures(const std::vector<RecorderBinResult>& bins, const span::Span& span, double days);

/// The balance frequencies for the counts' bands (each cut to the wind band).
std::vector<double> recorder_frequencies(const RecorderCounts& counts, const span::Span& span, int points_per_band);

/// The prediction from a balance at recorder_frequencies (the span needs a climate:
/// InvalidParameter naming "fatigue.wind_weibull" otherwise; a balance at other
/// frequencies: InvalidParameter naming "balance", its point and frequency).
RecorderPrediction predict_record(const RecorderCounts& counts, const span::Span& span,
                                  const span::SpanBalance& balance, int points_per_band, double days);

/// The span with a key set (InvalidParameter naming the key where the span's law
/// has no such parameter, or the value is out of its range).
span::Span with_parameter(const span::Span& span, const std::string& key, double value);
/// The key's value in the span (Lilien's k where the file gives none).
double parameter_of(const span::Span& span, const std::string& key);

/// Everything: the bins, the measured figures, the prediction, the calibration
/// where asked. The span must have a climate. Non-convergence is in the result.
RecorderResult analyse_record(const RecorderCounts& counts, const span::Span& span,
                              const span::BalanceOptions& balance, const RecorderOptions& options);

/// Writes the span file `source` with the calibrated values: each key's line
/// replaced (its comment kept), or the key added below its table's header; the rest
/// of the file as it is. The text returned; InputError where the file cannot be
/// edited so (the table written inline).
std::string calibrated_span_text(const std::filesystem::path& source, const std::vector<CalibratedValue>& values);

}  // namespace stockbridge::measurements
