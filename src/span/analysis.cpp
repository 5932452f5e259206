#include "stockbridge/span/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "balance_run.hpp"
#include "balance_summary.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

void AnalysisOptions::validate() const {
  balance.validate();
  if (positions) positions->validate();
}

namespace {

/// The span with every measured damper's sheet cut to every other curve; none where a
/// sheet has too few curves for it.
std::optional<Span> with_every_other_curve(const Span& span, int parity) {
  std::vector<SpanDamper> dampers = span.dampers();
  for (SpanDamper& d : dampers) {
    if (!d.measured()) continue;
    std::optional<ImpedanceSheet> cut = d.sheet->every_other(parity);
    if (!cut) return std::nullopt;
    d.sheet = std::make_shared<const ImpedanceSheet>(std::move(*cut));
  }
  return span.with_dampers(std::move(dampers));
}

std::string measured_names(const Span& span) {
  std::string names;
  for (const SpanDamper& d : span.dampers()) {
    if (!d.measured() || (", " + names + ", ").find(", " + d.name + ", ") != std::string::npos) continue;
    names += fmt::format("{}{}", names.empty() ? "" : ", ", d.name);
  }
  return names;
}

/// The band each point's stress lies in for the sheets' interpolation, and the
/// warnings a user of measured sheets needs.
void add_sheet_band(SpanAnalysis& out, const SpanTables& tables, const BalanceOptions& options) {
  const std::string names = measured_names(out.span);
  if (names.empty()) return;
  std::vector<SpanBalance> cut;
  for (const int parity : {0, 1}) {
    if (const std::optional<Span> span = with_every_other_curve(out.span, parity)) {
      cut.push_back(run_balance(*span, SpanTables(tables, *span), options));
    }
  }
  double worst = std::numeric_limits<double>::quiet_NaN(), worst_f = 0.0;
  int below = 0;
  for (std::size_t i = 0; i < out.balance.points.size(); ++i) {
    const BalancePoint& p = out.balance.points[i];
    if (!p.converged()) continue;
    if (p.below_sheet) ++below;
    if (!(p.stress_fymax > 0.0)) continue;  // no vibration (Y = 0): no relative change to take
    for (const SpanBalance& b : cut) {
      const BalancePoint& q = b.points[i];
      if (!q.converged()) continue;
      const double relative = std::abs(q.stress_fymax - p.stress_fymax) / p.stress_fymax;
      if (std::isfinite(relative) && !(relative <= worst)) worst = relative, worst_f = p.frequency_hz;
    }
  }
  // The band: the worst relative change over the band at every point. Near a kink of
  // Z(v) (the last sticking curve next to the first slipping one) every interpolant
  // errs alike, so the change at the point itself can be small where the error is not.
  for (BalancePoint& p : out.balance.points) {
    if (!p.converged() || std::isnan(worst)) continue;
    p.stress_fymax_low = p.stress_fymax * std::max(0.0, 1.0 - worst);
    p.stress_fymax_high = p.stress_fymax * (1.0 + worst);
  }
  out.sheet_error_estimate = cut.empty() ? std::numeric_limits<double>::quiet_NaN() : worst;
  refresh_summary(out.span, out.balance);
  if (cut.empty()) {
    out.warnings.push_back(fmt::format("the measured sheet of {} has too few curves to estimate its interpolation "
                                       "error (every other curve leaves fewer than two): the stresses may be off by "
                                       "tens of percent where a resonance moves with the amplitude",
                                       names));
  } else if (worst > sheet_error_warning) {
    out.warnings.push_back(fmt::format("the measured sheet of {} is too coarse for this span: leaving out every other "
                                       "curve moves the fymax stress by up to {:.0f} % (at {:.4g} Hz); the CSV's "
                                       "stress_fymax_low_mpa and stress_fymax_high_mpa show the band, and more clamp "
                                       "velocities measured would narrow it",
                                       names, 100.0 * worst, worst_f));
  }
  if (below > 0) {
    out.warnings.push_back(fmt::format("at {} of the frequencies a measured damper's clamp velocity lay below its sheet's "
                                       "lowest curve: Z held at that curve's there (the points' notes say where)",
                                       below));
  }
}

/// A warning where the largest judged stress lies at an edge of the frequencies
/// balanced: the stress still rises there, and a larger one may lie beyond.
void add_edge_warning(SpanAnalysis& out) {
  const BalanceSummary& s = out.balance.summary;
  const std::vector<double>& f = out.frequencies;
  if (s.converged == 0 || f.size() < 3 || !(s.max_judged_stress > 0.0)) return;
  const double at = s.max_judged_stress_frequency_hz;
  if (at != f.front() && at != f.back()) return;
  out.warnings.push_back(fmt::format("the largest stress lies at the {} edge of the frequencies balanced ({:.4g} Hz, "
                                     "wind {:.3g} m/s): a larger one may lie beyond it ([wind] speed_min and "
                                     "speed_max bound the band)",
                                     at == f.front() ? "low" : "high", at,
                                     out.span.wind().wind_speed(at, out.span.conductor().diameter)));
}

}  // namespace

SpanAnalysisRun::SpanAnalysisRun(const Span& span, std::vector<double> frequencies, const AnalysisOptions& options,
                                 const damper::SweepProgress& progress, const TableSource& tables)
    : options_(options), out_{span, std::nullopt, {}, {}, std::numeric_limits<double>::quiet_NaN(), {}} {
  options.validate();
  if (options.positions && span.dampers().empty()) {
    throw InvalidParameter("damper", ": the span has no damper to place");
  }
  const ImpedanceTableOptions table =
      options.positions ? options.balance.table.for_position_search() : options.balance.table;
  tables_ = tables ? tables(span, frequencies, table) : std::make_shared<const SpanTables>(span, frequencies, table, progress);
  out_.frequencies = tables_->frequencies();
  if (options.positions) {
    out_.position = optimise_positions(span, *tables_, options.balance, *options.positions);
    std::vector<SpanDamper> placed = span.dampers();
    for (std::size_t j = 0; j < placed.size(); ++j) placed[j].position = out_.position->positions[j];
    out_.span = span.with_dampers(std::move(placed));
  }
  hold_ = !options.take_point || !measured_names(out_.span).empty();  // a sheet's band needs every point
  std::function<void(BalancePoint&&)> take;
  if (!hold_) take = [this](BalancePoint&& p) { options_.take_point(out_.span, std::move(p)); };
  run_ = std::make_unique<BalanceRun>(out_.span, *tables_, options_.balance, nullptr, std::move(take));
}

SpanAnalysisRun::~SpanAnalysisRun() = default;

bool SpanAnalysisRun::done() const { return run_->done(); }

const BalancePoint& SpanAnalysisRun::next() { return run_->next(); }

SpanAnalysis SpanAnalysisRun::finish() {
  out_.balance = run_->finish();
  if (!out_.stopped_early()) {
    add_sheet_band(out_, *tables_, options_.balance);
    add_edge_warning(out_);
  }
  if (hold_ && options_.take_point) {
    for (BalancePoint& p : out_.balance.points) options_.take_point(out_.span, std::move(p));
    out_.balance.points.clear();
  }
  return std::move(out_);
}

SpanAnalysis analyse_span(const Span& span, std::vector<double> frequencies, const AnalysisOptions& options,
                          const damper::SweepProgress& progress, const TableSource& tables) {
  SpanAnalysisRun run(span, std::move(frequencies), options, progress, tables);
  while (!run.done()) run.next();
  return run.finish();
}

}  // namespace stockbridge::span
