// One cycle of experiment (a): 400 points, 40 sections, one Jenkin element (the
// dissertation's cable), from a steady state; and a single state determination.

#include <benchmark/benchmark.h>

#include "stockbridge/cable/experiment.hpp"

namespace {

using namespace stockbridge::cable;

Cantilever dissertation_cable(int sections) {
  return Cantilever(Cable(CableDescription::uniform(0.3, sections, 2.8, {{20.0, 0.7}})));
}

void BM_ExperimentACycle(benchmark::State& state) {
  Cantilever cantilever = dissertation_cable(static_cast<int>(state.range(0)));
  const ExperimentDrive drive{Experiment::a, 0.03, 1, 400};
  run_experiment(cantilever, drive);  // reach the steady loop
  double iterations = 0.0, evaluations = 0.0;
  for (auto _ : state) {
    const ExperimentRecord record = run_experiment(cantilever, drive);
    for (const ExperimentSample& s : record.samples) {
      iterations += s.solve.newton_iterations;
      evaluations += s.solve.evaluations;
    }
    benchmark::DoNotOptimize(record.summary.slider_dissipation);
  }
  const double determinations = 401.0 * static_cast<double>(state.iterations());
  state.counters["newton_iterations_mean"] = iterations / determinations;
  state.counters["evaluations_mean"] = evaluations / determinations;
}
BENCHMARK(BM_ExperimentACycle)->Arg(40)->Arg(160)->Unit(benchmark::kMillisecond);

void BM_ExperimentBCycle(benchmark::State& state) {
  Cantilever cantilever = dissertation_cable(40);
  const ExperimentDrive drive{Experiment::b, 0.15, 1, 400};
  run_experiment(cantilever, drive);
  for (auto _ : state) benchmark::DoNotOptimize(run_experiment(cantilever, drive).summary.slider_dissipation);
}
BENCHMARK(BM_ExperimentBCycle)->Unit(benchmark::kMillisecond);

// The inner kernel: loads in, state out (40 sections, one element).
void BM_ApplyLoads(benchmark::State& state) {
  const Cable cable(CableDescription::uniform(0.3, 40, 2.8, {{20.0, 0.7}}));
  const CableState from = CableState::virgin(cable);
  CableState to = from;
  CableWorkspace workspace;
  double force = 0.0;
  for (auto _ : state) {
    force = force > 20.0 ? -20.0 : force + 0.37;
    apply_loads(cable, from, force * 0.3, force, to, workspace);
    benchmark::DoNotOptimize(to.deflection);
  }
}
BENCHMARK(BM_ApplyLoads);

}  // namespace
