// The span analysis of examples/aster570_400m.toml (ASTER570, 400 m, the
// dissertation's damper 1 m from both ends) over 100 frequencies of the wind band,
// one core: the impedance tables, the balance with and without the direct-solve
// polish, one balance of a position search (40 frequencies on its finer tables),
// and the whole analysis (tables and polished balance) with one, two (1.0
// and 2.0 m) and three (1.0, 2.2 and 3.6 m) dampers per end; and the analysis with
// the damper known by a measured sheet of its own Z (13 velocities x 150
// frequencies), the sheet's error estimate included; the span in time: ten seconds
// of the example span at 30 Hz under the EBM's wind, with a dashpot at each end
// (902 elements, 40 steps a period: 12,000 steps).

#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "stockbridge/io/span_file.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/conductor_in_time.hpp"
#include "stockbridge/span/undamped.hpp"

namespace {

using namespace stockbridge::span;

Span example() { return stockbridge::io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml").span; }

/// The example span with its damper at each of `positions` (m from the clamp, both ends).
Span with_dampers_at(const std::vector<double>& positions) {
  const Span base = example();
  std::vector<SpanDamper> dampers;
  for (const double a : positions) dampers.push_back({base.dampers().front().damper, a, true, "sauter2003", nullptr, std::nullopt});
  return Span(base.conductor(), base.length(), base.tension(), base.wind(), base.self_damping(), dampers, base.fatigue());
}

void BM_SpanTable(benchmark::State& state) {
  const Span span = example();
  const std::vector<double> f = band_frequencies(span, 100);
  for (auto _ : state) benchmark::DoNotOptimize(SpanTables(span, f, ImpedanceTableOptions{}));
}
BENCHMARK(BM_SpanTable)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_SpanBalance(benchmark::State& state) {
  const Span span = example();
  BalanceOptions options;
  options.polish = state.range(0) != 0;
  const SpanTables tables(span, band_frequencies(span, 100), options.table);
  BalanceSummary summary;
  for (auto _ : state) summary = run_balance(span, tables, options).summary;
  state.counters["converged_points"] = summary.converged;
  state.counters["direct_solves"] = summary.direct_solves;
}
BENCHMARK(BM_SpanBalance)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

/// One balance on the position search's tables (40 frequencies, no polish) with 1, 2
/// or 3 dampers per end: what a search repeats for every arrangement it tries (its
/// tables and the span's undamped figures made once, before the timing).
void BM_SearchBalance(benchmark::State& state) {
  const std::vector<std::vector<double>> layouts{{1.0}, {1.0, 2.0}, {1.0, 2.2, 3.6}};
  const Span span = with_dampers_at(layouts.at(static_cast<std::size_t>(state.range(0) - 1)));
  BalanceOptions options;
  options.polish = false;
  const SpanTables tables(span, band_frequencies(span, 40), options.table.for_position_search());
  const UndampedFigures undamped(span, tables, options);
  BalanceSummary summary;
  for (auto _ : state) summary = run_balance(span, tables, options, &undamped).summary;
  state.counters["converged_points"] = summary.converged;
}
BENCHMARK(BM_SearchBalance)->DenseRange(1, 3)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The whole analysis (tables and the polished balance) with 1, 2 or 3 dampers per end.
void BM_SpanDampersPerEnd(benchmark::State& state) {
  const std::vector<std::vector<double>> layouts{{1.0}, {1.0, 2.0}, {1.0, 2.2, 3.6}};
  const Span span = with_dampers_at(layouts.at(static_cast<std::size_t>(state.range(0) - 1)));
  const std::vector<double> f = band_frequencies(span, 100);
  BalanceSummary summary;
  for (auto _ : state) summary = analyse_span(span, f, AnalysisOptions{}).balance.summary;
  state.counters["converged_points"] = summary.converged;
  state.counters["direct_solves"] = summary.direct_solves;
}
BENCHMARK(BM_SpanDampersPerEnd)->DenseRange(1, 3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

/// The whole analysis with the damper known by a measured sheet: the example damper's
/// own Z at 13 velocities (0.01-1 m/s) x 150 frequencies (4-60 Hz), made once outside
/// the timing; the balance on the sheet and its two every-other-curve balances.
void BM_SpanMeasuredSheet(benchmark::State& state) {
  const Span model = example();
  stockbridge::damper::SweepSpec spec;
  spec.frequencies = stockbridge::damper::log_spaced(4.0, 60.0, 150);
  spec.amplitudes = stockbridge::damper::log_spaced(0.01, 1.0, 13);
  stockbridge::damper::ImpedanceMeasurement m;
  for (const auto& run : stockbridge::damper::run_sweep(*model.dampers()[0].damper, spec)) {
    for (const auto& p : run.points) {
      if (p.converged()) m.points.push_back({stockbridge::damper::Excitation::from_velocity(p.frequency_hz, run.amplitude), p.impedance});
    }
  }
  const auto sheet = std::make_shared<const ImpedanceSheet>(std::move(m), "sheet");
  std::vector<SpanDamper> dampers = model.dampers();
  for (SpanDamper& d : dampers) {
    d.damper.reset();
    d.sheet = sheet;
  }
  const Span span = model.with_dampers(std::move(dampers));
  const std::vector<double> f = band_frequencies(span, 100);
  SpanAnalysis a = analyse_span(span, f, AnalysisOptions{});
  for (auto _ : state) a = analyse_span(span, f, AnalysisOptions{});
  state.counters["converged_points"] = a.balance.summary.converged;
  state.counters["error_estimate"] = a.sheet_error_estimate;
}
BENCHMARK(BM_SpanMeasuredSheet)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ConductorInTime(benchmark::State& state) {
  const Span span = example();
  EbmWindOptions options;
  options.frequency_hz = 30.0;
  options.duration_s = 10.0;
  options.settled_change = options.settled_mean_change = 1e-12;  // the whole 10 s
  options.start_amplitude_m = 0.5 * *undamped_amplitude(span.wind(), span.self_damping(), span.conductor(), span.tension(),
                                                         span.length(), 30.0);
  const std::vector<PointDashpot> dashpots{{1.0, 30.0}, {span.length() - 1.0, 30.0}};
  EbmWindHistory history;
  for (auto _ : state) history = settle_on_ebm_wind(span.without_dampers(), BeamEnds::clamped, options, dashpots);
  state.counters["elements"] = history.elements;
  state.counters["steps"] = history.time_s / history.dt_s;
  state.counters["us_per_step"] = benchmark::Counter(history.time_s / history.dt_s, benchmark::Counter::kIsIterationInvariantRate |
                                                                                      benchmark::Counter::kInvert);
}
BENCHMARK(BM_ConductorInTime)->Unit(benchmark::kMillisecond)->UseRealTime();

// The case, shortened: the example span (400 m of ASTER570) at 30 Hz with n of
// Sauter's dampers per end (1 m, and 2 m for the second; none: the conductor alone),
// each by its own model in time, at `stockbridge simulate`'s mesh and step (30 elements a wavelength, 160 steps
// a period), 10 s simulated (the 60 s costs six times this); the second
// argument 0 for the balance's wind, 1 for the wake oscillator's (one per element).
void BM_SpanInTime(benchmark::State& state) {
  const Span model = example();
  std::vector<SpanDamper> dampers;
  for (int i = 0; i < state.range(0); ++i) {
    SpanDamper d = model.dampers().front();
    d.position = 1.0 + i;
    dampers.push_back(d);
  }
  const Span span = model.with_dampers(std::move(dampers));
  EbmWindOptions options;
  options.frequency_hz = 30.0;
  options.duration_s = 10.0;
  options.settled_change = options.settled_mean_change = 1e-12;  // the whole 10 s
  options.elements_per_wavelength = 30;
  options.steps_per_period = 160;
  options.start_amplitude_m = 0.001;  // about the balance's with these dampers
  options.wind = state.range(1) == 1 ? WindInTime::wake : WindInTime::ebm;
  EbmWindHistory history;
  for (auto _ : state) history = settle_on_ebm_wind(span, BeamEnds::clamped, options);
  state.counters["elements"] = history.elements;
  state.counters["steps"] = history.time_s / history.dt_s;
  state.counters["us_per_step"] = benchmark::Counter(history.time_s / history.dt_s, benchmark::Counter::kIsIterationInvariantRate |
                                                                                      benchmark::Counter::kInvert);
}
BENCHMARK(BM_SpanInTime)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({2, 0})
    ->Args({0, 1})
    ->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
