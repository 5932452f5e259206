// The span analysis of examples/aster570_400m.toml (ASTER570, 400 m, the
// dissertation's damper 1 m from both ends) over 100 frequencies of the wind band,
// one core: the impedance tables, the balance with and without the direct-solve
// polish, and the whole analysis (tables and polished balance) with one, two (1.0
// and 2.0 m) and three (1.0, 2.2 and 3.6 m) dampers per end.

#include <string>

#include <benchmark/benchmark.h>

#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/analysis.hpp"

namespace {

using namespace stockbridge::span;

Span example() { return stockbridge::io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml").span; }

/// The example span with its damper at each of `positions` (m from the clamp, both ends).
Span with_dampers_at(const std::vector<double>& positions) {
  const Span base = example();
  std::vector<SpanDamper> dampers;
  for (const double a : positions) dampers.push_back({base.dampers().front().damper, a, true, "sauter2003", nullptr});
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

}  // namespace
