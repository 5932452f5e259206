// Identification cost: the global fit on a cycle of experiment (a) sampled at 400
// points per cycle (40 sections, the dissertation's cable, 1 % noise;
// 541 samples (1.35 cycles), since the fit compares from the first extreme on over one full
// cycle, and a little beyond to see the last reversal), and a local fit of a moment-curvature record.

#include <random>

#include <benchmark/benchmark.h>

#include "stockbridge/identification/global_identification.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"

namespace {

using namespace stockbridge;
using namespace stockbridge::identification;

ExperimentMeasurement noisy_cycle_a() {
  cable::Cantilever cantilever{cable::Cable(cable::CableDescription::uniform(0.3, 40, 2.8, {{20.0, 0.7}}))};
  cable::ExperimentRecord record = cable::run_experiment(cantilever, {cable::Experiment::a, 0.03, 2, 400});
  record.samples.resize(541);
  ExperimentMeasurement m;
  std::mt19937 rng(1);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const cable::ExperimentSample& s : record.samples) {
    m.prescribed.push_back(s.deflection);
    m.measured.push_back(s.tip_force + 0.01 * 12.8 * gauss(rng));
  }
  return m;
}

void BM_GlobalFit(benchmark::State& state) {
  const ExperimentMeasurement m = noisy_cycle_a();
  GlobalIdentificationOptions options;
  options.length = 0.3;
  int evaluations = 0;
  for (auto _ : state) evaluations = identify_fit(m, options).evaluations;
  state.counters["cable_simulations"] = evaluations;
}
BENCHMARK(BM_GlobalFit)->Unit(benchmark::kMillisecond);

void BM_LocalFit(benchmark::State& state) {
  const section::MasingParameters p{2.8, {{20.0, 0.7}}};
  MomentCurvatureRecord record;
  section::SectionState a = section::SectionState::virgin(p), b = a;
  for (int k = 0; k <= 1200; ++k) {
    section::curvature_update(p, a, 0.08 * std::sin(2.0 * 3.141592653589793 * k / 400), b);
    std::swap(a, b);
    record.curvature.push_back(a.curvature);
    record.moment.push_back(a.moment);
  }
  int evaluations = 0;
  for (auto _ : state) evaluations = identify_local(record, LocalIdentificationOptions{}).evaluations;
  state.counters["model_runs"] = evaluations;
}
BENCHMARK(BM_LocalFit)->Unit(benchmark::kMillisecond);

// Identification from impedance on the shipped example (examples/measured_impedance.csv:
// 2 velocities x 16 frequencies, 1 % noise; examples/damper_to_identify.toml's
// starting values, 40 sections): one model run over the 32 points, and the whole fit.
const std::string kExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

void BM_ImpedanceModelRun(benchmark::State& state) {
  const damper::Damper damper = io::read_damper_file(kExamples + "damper_to_identify.toml");
  const ImpedanceMeasurement m = io::read_measured_impedance(kExamples + "measured_impedance.csv");
  for (auto _ : state) benchmark::DoNotOptimize(model_impedance(damper, m, {}));
}
BENCHMARK(BM_ImpedanceModelRun)->Unit(benchmark::kMillisecond);

void BM_ImpedanceFit(benchmark::State& state) {
  const damper::Damper damper = io::read_damper_file(kExamples + "damper_to_identify.toml");
  const ImpedanceMeasurement m = io::read_measured_impedance(kExamples + "measured_impedance.csv");
  ImpedanceIdentificationOptions options;
  options.threads = static_cast<int>(state.range(0));
  int runs = 0;
  for (auto _ : state) runs = identify_impedance(damper.description(), m, options).model_evaluations;
  state.counters["model_runs"] = runs;
}
BENCHMARK(BM_ImpedanceFit)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

}  // namespace
