// The span balance of examples/aster570_400m.toml (ASTER570, 400 m, the
// dissertation's damper 1 m from both ends) over 100 frequencies of the wind band,
// one core: the impedance table (100 frequencies x 25 velocities) and the balance
// with and without the direct-solve polish.

#include <string>

#include <benchmark/benchmark.h>

#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/balance.hpp"

namespace {

using namespace stockbridge::span;

Span example() { return stockbridge::io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml").span; }

void BM_SpanTable(benchmark::State& state) {
  const Span span = example();
  const std::vector<double> f = band_frequencies(span, 100);
  for (auto _ : state) benchmark::DoNotOptimize(impedance_tables(span, f, BalanceOptions{}));
}
BENCHMARK(BM_SpanTable)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_SpanBalance(benchmark::State& state) {
  const Span span = example();
  const std::vector<double> f = band_frequencies(span, 100);
  BalanceOptions options;
  options.polish = state.range(0) != 0;
  const std::vector<ImpedanceTable> tables = impedance_tables(span, f, options);
  BalanceSummary summary;
  for (auto _ : state) summary = run_balance(span, f, tables, options).summary;
  state.counters["converged_points"] = summary.converged;
  state.counters["direct_solves"] = summary.direct_solves;
}
BENCHMARK(BM_SpanBalance)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
