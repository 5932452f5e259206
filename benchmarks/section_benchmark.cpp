// Cost of the exact section update: one trial + commit, curvature-driven and
// moment-driven, for 1 and 4 Jenkin elements, along a sinusoidal path (reversals
// included, so every branch of the return mapping is exercised).

#include <cmath>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/regularised_section.hpp"

namespace {

using stockbridge::section::Jenkin;
using stockbridge::section::MasingParameters;
using stockbridge::section::MasingSection;

MasingParameters parameters_with(int elements) {
  MasingParameters p{2.8, {}};
  for (int j = 0; j < elements; ++j) p.jenkin.push_back(Jenkin{20.0 / (j + 1), 0.7 / (j + 1)});
  return p;
}

std::vector<double> sinusoid(double amplitude, int points) {
  std::vector<double> path(points);
  for (int k = 0; k < points; ++k) path[k] = amplitude * std::sin(2.0 * std::numbers::pi * k / points);
  return path;
}

void BM_CurvatureDrivenTrialCommit(benchmark::State& state) {
  MasingSection section(parameters_with(static_cast<int>(state.range(0))));
  const std::vector<double> path = sinusoid(0.1, 400);
  std::size_t k = 0;
  for (auto _ : state) {
    section.set_trial_curvature(path[k]);
    section.commit();
    benchmark::DoNotOptimize(section.moment());
    k = k + 1 == path.size() ? 0 : k + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CurvatureDrivenTrialCommit)->Arg(1)->Arg(4);

void BM_MomentDrivenTrialCommit(benchmark::State& state) {
  const MasingParameters p = parameters_with(static_cast<int>(state.range(0)));
  MasingSection section(p);
  const std::vector<double> path = sinusoid(1.5 * p.total_slip_moment() + 0.2, 400);
  std::size_t k = 0;
  for (auto _ : state) {
    section.set_trial_moment(path[k]);
    section.commit();
    benchmark::DoNotOptimize(section.curvature());
    k = k + 1 == path.size() ? 0 : k + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MomentDrivenTrialCommit)->Arg(1)->Arg(4);

// The raw kernel without the section object (what the cable's inner loop calls).
void BM_JenkinKernel(benchmark::State& state) {
  const MasingParameters p = parameters_with(static_cast<int>(state.range(0)));
  std::vector<double> h_state(p.jenkin.size(), 0.0);
  const std::vector<double> path = sinusoid(0.1, 400);
  double kappa = 0.0;
  std::size_t k = 0;
  for (auto _ : state) {
    const auto step = stockbridge::section::jenkin_step(p.jenkin, h_state, path[k] - kappa, h_state);
    kappa = path[k];
    benchmark::DoNotOptimize(step.moment);
    k = k + 1 == path.size() ? 0 : k + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_JenkinKernel)->Arg(1)->Arg(4);

void BM_RegularisedTrialCommit(benchmark::State& state) {
  stockbridge::section::RegularisedSection section(parameters_with(1),
                                                   stockbridge::section::RegularisedOptions{10.0});
  const std::vector<double> path = sinusoid(0.1, 400);
  std::size_t k = 0;
  for (auto _ : state) {
    section.set_trial_curvature(path[k]);
    section.commit();
    benchmark::DoNotOptimize(section.moment());
    k = k + 1 == path.size() ? 0 : k + 1;
  }
}
BENCHMARK(BM_RegularisedTrialCommit);

}  // namespace
