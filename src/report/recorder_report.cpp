#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/report/svg_chart.hpp"

namespace stockbridge::report {

namespace {

std::string recorder_life(double years) {
  return std::isfinite(years) ? parts::number(years, 3) + " years" : "unlimited";
}

/// The predicted Yb(f) as a curve, mm (NaN where a point did not converge).
Series recorder_curve(const measurements::RecorderPrediction& p, std::string label, LineStyle style, int colour) {
  Series s{std::move(label), {}, {}, style, colour};
  for (const measurements::PredictedPoint& q : p.points) {
    s.x.push_back(q.frequency);
    s.y.push_back(1e3 * q.yb);
  }
  return s;
}

std::vector<std::string> recorder_figures_row(const std::string& what, const measurements::DamageFigures& f) {
  return {what,
          fmt::format("{:.4g}", f.damage),
          fmt::format("{:.4g}", f.damage_per_year),
          recorder_life(f.life_years),
          fmt::format("{:.3g}", 1e3 * f.max_yb),
          fmt::format("{:.3g}", f.max_stress / 1e6),
          fmt::format("{:.4g}", f.cycles),
          fmt::format("{:.3g} %", 100.0 * f.fraction_above_endurance)};
}

std::string recorder_mm(double ln_yb) { return std::isfinite(ln_yb) ? fmt::format("{:.3g}", std::exp(ln_yb)) : "-"; }

}  // namespace

std::string recorder_report(const RecorderReportInput& input, const ReportContext& context) {
  const measurements::RecorderResult& r = *input.result;
  const span::Span& s = *input.span;
  const std::string name = fmt::format("{}{} m span", s.conductor().name.empty() ? "" : s.conductor().name + ", ",
                                       parts::number(s.length()));
  HtmlPage page({"Vibration recorder: " + name, context.generated_at, context.command});
  const measurements::DamageFigures& m = r.measured;
  const measurements::RecorderPrediction& best = r.calibration ? r.calibration->prediction : r.predicted;
  const double ratio = best.figures.damage_per_year > 0.0 ? m.damage_per_year / best.figures.damage_per_year : NAN;
  const bool worse = !(m.damage_per_year <= best.figures.damage_per_year);
  page.verdict(fmt::format("measured life {}", recorder_life(m.life_years)),
               fmt::format(" against {} predicted{}: the record's damage per year is {} the prediction's{}",
                           recorder_life(best.figures.life_years), r.calibration ? " after calibration" : "",
                           std::isfinite(ratio) ? fmt::format("{:.3g} times", ratio) : std::string("beside"),
                           best.failed_points > 0 ? " (some balance points did not converge)" : ""),
               best.failed_points > 0 ? Tone::unknown : worse ? Tone::bad : Tone::good);
  std::vector<Fact> key{{"measured damage per year", fmt::format("{:.3g}", m.damage_per_year)},
                        {"measured life", recorder_life(m.life_years)},
                        {"predicted life", recorder_life(r.predicted.figures.life_years)},
                        {"largest Yb recorded", fmt::format("{:.3g} mm", 1e3 * m.max_yb)}};
  if (r.calibration) key.push_back({"calibrated life", recorder_life(r.calibration->prediction.figures.life_years)});
  page.key_figures(key);

  page.section("Inputs");
  std::vector<Fact> inputs = parts::span_inputs(s, span::DamperModel::travelling);
  inputs.insert(inputs.begin(), {"recorder counts", fmt::format("{} ({} non-empty bins, {} frequency bands, {:.4g} days)",
                                                                input.counts, r.bins.size(), r.predicted.bands.size(), m.days)});
  page.facts(inputs);

  page.section("The record and the balance");
  Chart chart("Recorded cycles (colour) and the balance's Yb(f)", Axis("frequency (Hz)", true),
              Axis("Yb, peak-to-peak at x_b (mm)", true));
  HeatMap heat{"cycles", {}, true};
  for (const measurements::RecorderBinResult& b : r.bins) {
    heat.cells.push_back({b.bin.frequency_low, b.bin.frequency_high, 1e3 * std::max(b.bin.yb_low, 0.5 * b.bin.yb_high),
                          1e3 * b.bin.yb_high, b.bin.cycles});
  }
  chart.heat = heat;
  chart.series.push_back(recorder_curve(r.predicted, "predicted Yb(f), the span file", LineStyle::solid, 0));
  if (r.calibration) chart.series.push_back(recorder_curve(r.calibration->prediction, "calibrated", LineStyle::dashed, 2));
  Series means{"recorded mean Yb per band (geometric)", {}, {}, LineStyle::ring, 1};
  for (const measurements::RecorderBand& b : r.predicted.bands) {
    if (!std::isfinite(b.recorded_mean_ln_yb)) continue;
    means.x.push_back(std::sqrt(b.frequency_low * b.frequency_high));
    means.y.push_back(std::exp(b.recorded_mean_ln_yb));
  }
  chart.series.push_back(means);
  page.figure(svg(chart), "Each rectangle is a bin of the record (a bin from Yb = 0 drawn from half its upper edge), its "
                          "colour the cycles counted; the curves are the span's balance (Yb at 89 mm from the clamp), the "
                          "rings the count-weighted geometric mean of each band.");

  page.section("Damage");
  page.table({"", "damage", "per year", "life", "largest Yb (mm)", "largest stress (MPa)", "cycles", "above endurance"},
             [&] {
               std::vector<std::vector<std::string>> rows{recorder_figures_row("measured", m),
                                                          recorder_figures_row("predicted", r.predicted.figures)};
               if (r.calibration) rows.push_back(recorder_figures_row("calibrated", r.calibration->prediction.figures));
               return rows;
             }());
  std::vector<std::vector<std::string>> bands;
  for (std::size_t k = 0; k < r.predicted.bands.size(); ++k) {
    const measurements::RecorderBand& b = r.predicted.bands[k];
    std::vector<std::string> row{fmt::format("{:.4g} to {:.4g}", b.frequency_low, b.frequency_high),
                                 fmt::format("{:.4g}", b.recorded_cycles), fmt::format("{:.4g}", b.predicted_cycles),
                                 recorder_mm(b.recorded_mean_ln_yb), recorder_mm(b.predicted_mean_ln_yb)};
    row.push_back(r.calibration ? recorder_mm(r.calibration->prediction.bands[k].predicted_mean_ln_yb) : "-");
    row.push_back(b.converged ? "" : "not converged");
    bands.push_back(std::move(row));
  }
  page.table({"band (Hz)", "recorded cycles", "predicted cycles", "recorded Yb (mm)", "predicted Yb (mm)",
              "calibrated Yb (mm)", ""},
             bands);
  page.paragraph("Yb of a band: the geometric mean exp(mean ln Yb), the record's weighted by its counts (a bin's value: "
                 "the geometric mean of its edges), the prediction's by its cycles.");

  if (r.calibration) {
    const measurements::RecorderCalibration& c = *r.calibration;
    page.section("Calibration");
    std::vector<Fact> facts;
    for (const measurements::CalibratedValue& v : c.values) {
      facts.push_back({v.key, fmt::format("{:.4g} +- {:.2g} (the span file: {:.4g})", v.value, v.standard_error, v.start)});
    }
    facts.push_back({"residual (ln Yb, weighted RMS)", fmt::format("{:.3g} before, {:.3g} after", c.residual_before,
                                                                   c.residual_after)});
    facts.push_back({"fit", fmt::format("{}; {} balances", c.message, c.balances)});
    page.facts(facts);
  }

  page.section("Bins");
  std::vector<std::vector<std::string>> rows;
  for (const measurements::RecorderBinResult& b : r.bins) {
    rows.push_back({fmt::format("{:.4g} to {:.4g}", 1e3 * b.bin.yb_low, 1e3 * b.bin.yb_high),
                    fmt::format("{:.4g} to {:.4g}", b.bin.frequency_low, b.bin.frequency_high),
                    fmt::format("{:.4g}", b.bin.cycles), fmt::format("{:.3g}", b.stress / 1e6),
                    fmt::format("{:.4g}", b.microstrain_pp),
                    std::isfinite(b.cycles_to_failure) ? fmt::format("{:.3g}", b.cycles_to_failure) : "infinite",
                    fmt::format("{:.3g}", b.damage)});
  }
  page.table({"Yb (mm)", "frequency (Hz)", "cycles", "stress (MPa)", "microstrain pp", "N", "damage"}, rows);

  page.section("Assumptions");
  page.list({"A bin's stress is the Poffenberger-Swart stress K Yb at its upper Yb edge (conservative); N from the span's "
             "S-N curve (the CIGRE Safe Border Line of its aluminium layers); Miner's rule.",
             "Per year: the record's damage times 365.25 / days; the record's season stands for the year.",
             "Predicted: one cycle per period at the balance's Yb for the wind speeds that shed at each frequency "
             "(Weibull climate, aeolian share), over the record's frequency bands only."});
  page.section("Warnings");
  std::vector<std::string> warnings = context.warnings;
  if (r.predicted.failed_points > 0) {
    warnings.push_back(fmt::format("{} balance points did not converge: their bands are flagged and left out of the sums",
                                   r.predicted.failed_points));
  }
  page.list(warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
