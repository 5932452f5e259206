// The product's main job: the impedance sweep of examples/sauter2003.toml
// (200 frequencies log-spaced over 1-100 Hz at 0.05 and 0.2 m/s, harmonic
// balance at its defaults), on 1 and 2 threads, with and without continuation blocks,
// and at one amplitude; the same with slenderpy's Bouc-Wen damper
// (examples/slenderpy_damper.toml, 0.2 m/s over 5-100 Hz); one pass of harmonic
// balance over each damper's arm, driven by the tip kinematics as the solver drives
// it and, beside it, the same half period's loads applied directly; and the cost of
// one point per method.

#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/damper/harmonic_balance.hpp"
#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/damper_file.hpp"

namespace {

using namespace stockbridge::damper;

/// The points of a sweep that converged.
int converged_points(const std::vector<SweepRun>& runs) {
  int converged = 0;
  for (const SweepRun& run : runs) {
    for (const ImpedancePoint& p : run.points) converged += p.converged();
  }
  return converged;
}

Damper example() {
  return stockbridge::io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/sauter2003.toml");
}

/// Arguments: threads, amplitudes (2: 0.05 and 0.2 m/s; 1: 0.2 m/s), frequencies per
/// continuation block (SweepSpec::block_points; 0: one block per amplitude).
void BM_SauterSweep(benchmark::State& state) {
  const Damper damper = example();
  SweepSpec spec;
  spec.frequencies = log_spaced(1.0, 100.0, 200);
  spec.amplitudes = state.range(1) == 2 ? std::vector<double>{0.05, 0.2} : std::vector<double>{0.2};
  spec.threads = static_cast<int>(state.range(0));
  spec.block_points = static_cast<int>(state.range(2));
  int converged = 0;
  for (auto _ : state) converged = converged_points(run_sweep(damper, spec));
  state.counters["converged_points"] = converged;
}
BENCHMARK(BM_SauterSweep)
    ->ArgNames({"threads", "amplitudes", "block_points"})
    ->Args({1, 2, 50})
    ->Args({2, 2, 50})
    ->Args({1, 1, 50})
    ->Args({2, 1, 50})
    ->Args({1, 1, 34})
    ->Args({2, 1, 34})
    ->Args({1, 2, 0})
    ->Args({2, 2, 0})
    ->Args({1, 1, 0})
    ->Args({2, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

// One point from a cold start (no continuation), per method, at a slipping frequency.
/// A damper file of examples/: `points` frequencies log-spaced over 5-100 Hz at
/// 0.2 m/s, harmonic balance at its defaults, one thread.
void sweep_5_to_100_hz(benchmark::State& state, const std::string& file) {
  const Damper damper = stockbridge::io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/" + file);
  SweepSpec spec;
  spec.frequencies = log_spaced(5.0, 100.0, static_cast<int>(state.range(0)));
  spec.amplitudes = {0.2};
  spec.threads = 1;
  int converged = 0;
  for (auto _ : state) converged = converged_points(run_sweep(damper, spec));
  state.counters["converged_points"] = converged;
}
/// slenderpy's damper (the Bouc-Wen law).
void BM_SlenderpySweep(benchmark::State& state) { sweep_5_to_100_hz(state, "slenderpy_damper.toml"); }
/// The dissertation's damper (the Masing law, arms of the same geometry) on the same sweep.
void BM_SauterSameSweep(benchmark::State& state) { sweep_5_to_100_hz(state, "sauter2003.toml"); }
BENCHMARK(BM_SlenderpySweep)->ArgNames({"points"})->Arg(40)->Arg(400)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_SauterSameSweep)->ArgNames({"points"})->Arg(400)->Unit(benchmark::kMillisecond)->Iterations(3);

/// An arm's half-period pass at its periodic solution at 20 Hz, 0.2 m/s (harmonic
/// balance at its defaults): by the tip kinematics, as the solver drives it (a
/// cantilever state determination a sample), and (`by_loads`) the loads that pass
/// found, applied sample by sample (one cable evaluation a sample, no state
/// determination): what a pass driven by the loads' coefficients would cost.
void BM_HalfPeriodPass(benchmark::State& state, const std::string& file, bool by_loads) {
  const Damper damper = stockbridge::io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/" + file);
  const HarmonicBalance model(damper.arms()[0], HarmonicBalanceOptions{});
  const Excitation excitation = Excitation::from_velocity(20.0, 0.2);
  HarmonicBalanceMemory memory;
  HarmonicBalanceWorkspace workspace = model.make_workspace();
  const ArmSolution solution = model.solve(excitation, model.linear_guess(excitation), memory, workspace);
  if (!solution.summary.converged() || !memory.cable_state) {
    state.SkipWithError("the periodic solution at 20 Hz did not converge");
    return;
  }
  const stockbridge::cable::CableState& start = *memory.cable_state;
  const PeriodicStart mode = model.uses_periodic_newton() ? PeriodicStart::newton : PeriodicStart::chained;
  const stockbridge::cable::Cable& cable = model.arm().cable();
  const Eigen::Index samples = solution.period.loads.cols() / 2;  // the driven half
  std::vector<stockbridge::cable::CableState> states(2, start);  // the steps' targets, in turn
  stockbridge::cable::CableWorkspace cable_workspace;
  for (auto _ : state) {
    if (!by_loads) {
      benchmark::DoNotOptimize(
          model.evaluate(excitation, solution.unknowns, &start, 1, HarmonicBalance::kNone, workspace, mode));
      continue;
    }
    for (Eigen::Index j = 0; j < samples; ++j) {
      const double tip_force = solution.period.loads(0, j), tip_moment = solution.period.loads(1, j);
      stockbridge::cable::apply_loads(cable, j == 0 ? start : states[j % 2], tip_moment + tip_force * cable.length(),
                                      tip_force, states[(j + 1) % 2], cable_workspace);
    }
    benchmark::DoNotOptimize(states[samples % 2].rotation);
  }
  state.counters["samples"] = static_cast<double>(samples);
}
BENCHMARK_CAPTURE(BM_HalfPeriodPass, slenderpy_by_kinematics, "slenderpy_damper.toml", false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_HalfPeriodPass, slenderpy_by_loads, "slenderpy_damper.toml", true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_HalfPeriodPass, sauter_by_kinematics, "sauter2003.toml", false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_HalfPeriodPass, sauter_by_loads, "sauter2003.toml", true)->Unit(benchmark::kMicrosecond);

void BM_OnePoint(benchmark::State& state, Method method, double frequency_hz) {
  const Damper damper = example();
  SolverOptions options;
  options.method = method;
  const Excitation excitation = Excitation::from_velocity(frequency_hz, 0.2);
  bool converged = false;
  for (auto _ : state) converged = solve_steady_state(damper, excitation, options).point.converged();
  state.counters["converged"] = converged;
}
BENCHMARK_CAPTURE(BM_OnePoint, hb_15Hz, Method::harmonic_balance, 15.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, collocation_H40_15Hz, Method::collocation, 15.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, hb_50Hz, Method::harmonic_balance, 50.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, collocation_H40_50Hz, Method::collocation, 50.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, time_15Hz, Method::time_integration, 15.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, time_50Hz, Method::time_integration, 50.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, shooting_15Hz, Method::shooting, 15.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OnePoint, shooting_50Hz, Method::shooting, 50.0)->Unit(benchmark::kMillisecond);

}  // namespace
