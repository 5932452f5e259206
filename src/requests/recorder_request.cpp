#include "stockbridge/requests/recorder_request.hpp"

#include <cmath>

#include "stockbridge/core/error.hpp"

namespace stockbridge::requests {

namespace {

using measurements::RecorderBinResult;
using RecorderQuantity = Quantity<RecorderBinResult>;

RecorderQuantity recorder_column(std::string name, std::string unit, std::string meaning,
                                 double (*value)(const RecorderBinResult&)) {
  return {std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
          [value](const RecorderBinResult& b, std::size_t) { return value(b); }, {}};
}

io::JsonObject recorder_figures_json(const measurements::DamageFigures& f) {
  io::JsonObject o;
  o.add("damage", f.damage)
      .add("damage_per_year", f.damage_per_year)
      .add("life_years", f.life_years)
      .add("max_yb_pp_mm", 1e3 * f.max_yb)
      .add("max_stress_mpa", megapascal_of(f.max_stress))
      .add("fraction_above_endurance", f.fraction_above_endurance)
      .add("cycles", f.cycles)
      .add("days", f.days);
  return o;
}

io::JsonObject recorder_prediction_json(const measurements::RecorderPrediction& p) {
  io::JsonObject o = recorder_figures_json(p.figures);
  std::vector<io::JsonObject> bands;
  for (const measurements::RecorderBand& b : p.bands) {
    io::JsonObject band;
    band.add("frequency_hz_low", b.frequency_low)
        .add("frequency_hz_high", b.frequency_high)
        .add("recorded_cycles", b.recorded_cycles)
        .add("predicted_cycles", b.predicted_cycles)
        .add("recorded_mean_ln_yb_mm", b.recorded_mean_ln_yb)
        .add("predicted_mean_ln_yb_mm", b.predicted_mean_ln_yb)
        .add("converged", b.converged);
    bands.push_back(std::move(band));
  }
  std::vector<double> f, yb;
  for (const measurements::PredictedPoint& q : p.points) {
    f.push_back(q.frequency);
    yb.push_back(1e3 * q.yb);
  }
  o.add("bands", bands).add("frequency_hz", f).add("yb_pp_mm", yb).add("failed_points", p.failed_points);
  return o;
}

}  // namespace

measurements::RecorderOptions recorder_options(const RecorderRequest& request) {
  measurements::RecorderOptions o;
  o.days = request.days;
  o.calibrate = request.calibrate;
  o.points_per_band = request.points_per_band;
  o.validate();
  return o;
}

measurements::RecorderCounts read_recorder_input(const std::filesystem::path& counts, const io::SpanFile& span,
                                                 const RecorderRequest& request, SlipPolicy policy) {
  const measurements::RecorderOptions options = recorder_options(request);
  if (!span.span.fatigue().life) {
    throw InvalidParameter("fatigue.wind_weibull",
                           ": the span file gives no climate; the prediction of a record needs [fatigue] wind_weibull "
                           "= { shape, scale } and aeolian_fraction");
  }
  for (const std::string& key : options.calibrate) {
    measurements::with_parameter(span.span, key, measurements::parameter_of(span.span, key));
  }
  measurements::RecorderCounts c = measurements::read_recorder_counts(counts, policy);
  measurements::check_recorder_band(c, span.span);
  return c;
}

measurements::RecorderResult run_recorder(const measurements::RecorderCounts& counts, const io::SpanFile& span,
                                          const RecorderRequest& request) {
  return measurements::analyse_record(counts, span.span, span.balance, recorder_options(request));
}

Table<RecorderBinResult> recorder_bins_table() {
  return Table<RecorderBinResult>({
      recorder_column("yb_pp_mm_low", "mm", "the bin's lower Yb edge, peak-to-peak at x_b",
                      [](const RecorderBinResult& b) { return 1e3 * b.bin.yb_low; }),
      recorder_column("yb_pp_mm_high", "mm", "the bin's upper Yb edge (its stress's)",
                      [](const RecorderBinResult& b) { return 1e3 * b.bin.yb_high; }),
      recorder_column("frequency_hz_low", "Hz", "the bin's lower frequency edge",
                      [](const RecorderBinResult& b) { return b.bin.frequency_low; }),
      recorder_column("frequency_hz_high", "Hz", "the bin's upper frequency edge",
                      [](const RecorderBinResult& b) { return b.bin.frequency_high; }),
      recorder_column("cycles", "", "cycles counted over the record",
                      [](const RecorderBinResult& b) { return b.bin.cycles; }),
      recorder_column("stress_ps_mpa", "MPa", "the Poffenberger-Swart stress K Yb at the upper edge (zero-to-peak)",
                      [](const RecorderBinResult& b) { return megapascal_of(b.stress); }),
      recorder_column("microstrain_pp", "microstrain", "that stress's peak-to-peak bending strain, 2 sigma / E_a",
                      [](const RecorderBinResult& b) { return b.microstrain_pp; }),
      recorder_column("cycles_to_failure", "", "N at that stress on the span's S-N curve (empty: infinite)",
                      [](const RecorderBinResult& b) {
                        return std::isfinite(b.cycles_to_failure) ? b.cycles_to_failure
                                                                   : std::numeric_limits<double>::quiet_NaN();
                      }),
      recorder_column("damage", "", "Miner's share of the bin, cycles / cycles_to_failure",
                      [](const RecorderBinResult& b) { return b.damage; }),
  });
}

io::JsonObject recorder_summary(const measurements::RecorderResult& r) {
  io::JsonObject o;
  o.add("measured", recorder_figures_json(r.measured)).add("predicted", recorder_prediction_json(r.predicted));
  if (r.calibration) {
    const measurements::RecorderCalibration& c = *r.calibration;
    io::JsonObject cal;
    for (const measurements::CalibratedValue& v : c.values) {
      io::JsonObject key;
      key.add("value", v.value).add("start", v.start).add("standard_error", v.standard_error);
      cal.add(v.key, key);
    }
    cal.add("residual_before", c.residual_before)
        .add("residual_after", c.residual_after)
        .add("iterations", c.iterations)
        .add("balances", c.balances)
        .add("converged", c.converged)
        .add("message", c.message)
        .add("predicted", recorder_prediction_json(c.prediction));
    o.add("calibrated", cal);
  } else {
    o.add_null("calibrated");
  }
  o.add("failed_points", r.predicted.failed_points + (r.calibration ? r.calibration->prediction.failed_points : 0))
      .add("seconds_per_balance", r.seconds_per_balance);
  return o;
}

}  // namespace stockbridge::requests
