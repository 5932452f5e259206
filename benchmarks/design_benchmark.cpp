// The design search of examples/design_aster570.toml: one candidate (the base
// damper: its impedance table and the polished balance over the span's 100
// frequencies, one core), and a sample of 8 candidates without polish on 1 and 2
// threads (the threads' speed-up; the MPI ranks' is measured with mpirun,
// benchmarks/README.md).

#include <string>

#include <benchmark/benchmark.h>

#include "stockbridge/design/search.hpp"
#include "stockbridge/io/design_file.hpp"

namespace {

using namespace stockbridge::design;

stockbridge::io::DesignFile example() {
  return stockbridge::io::load_design_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/design_aster570.toml");
}

void BM_DesignCandidate(benchmark::State& state) {
  const stockbridge::io::DesignFile file = example();
  Evaluation e;
  for (auto _ : state) e = evaluate(file.study, file.study.base_values());
  state.counters["converged"] = e.converged();
  state.counters["objective"] = e.objective;
}
BENCHMARK(BM_DesignCandidate)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_DesignSample(benchmark::State& state) {
  const stockbridge::io::DesignFile file = example();
  SearchOptions options = file.search;
  options.samples = 8;
  options.polish = 0;
  ThreadRunner runner(static_cast<int>(state.range(0)));
  std::size_t evaluations = 0;
  for (auto _ : state) evaluations = run_search(file.study, options, runner).evaluations.size();
  state.counters["candidates"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_DesignSample)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
