#include "stockbridge/cable/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

Experiment parse_experiment(std::string_view name) {
  if (name == "a") return Experiment::a;
  if (name == "b") return Experiment::b;
  throw InvalidParameter("experiment", fmt::format(" = '{}': expected a (tip force) or b (tip rotation)", name));
}

void ExperimentDrive::validate() const {
  require_non_negative("amplitude", amplitude, experiment == Experiment::a ? "m" : "rad");
  require_in_range("cycles", cycles, 1, 100000);
  require_in_range("points", points, 4, 10000000);
  if (static_cast<long long>(cycles) * points > 10000000LL) {
    throw InvalidParameter("points", fmt::format(": cycles * points = {}: expected at most 10000000 samples",
                                       static_cast<long long>(cycles) * points));
  }
}

double ExperimentDrive::prescribed(int k) const {
  return amplitude * std::sin(2.0 * std::numbers::pi * static_cast<double>(k % points) / points);
}

namespace {

ExperimentSample sample_of(const Cantilever& cantilever, const StateDetermination& solve) {
  const CableState& s = cantilever.trial();
  return {s.deflection, s.rotation, s.tip_force, s.clamp_moment, s.tip_moment(cantilever.cable().length()),
          s.dissipated, solve};
}

ExperimentSummary summarise(const std::vector<ExperimentSample>& samples, const ExperimentDrive& drive) {
  ExperimentSummary summary;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  summary.max_tip_force = summary.max_clamp_moment = summary.max_deflection = summary.max_rotation = -kInf;
  summary.min_tip_force = summary.min_clamp_moment = summary.min_deflection = summary.min_rotation = kInf;
  long long iterations = 0;
  for (const ExperimentSample& s : samples) {
    iterations += s.solve.newton_iterations;
    summary.max_iterations = std::max(summary.max_iterations, s.solve.newton_iterations);
    if (!s.solve.converged()) {
      ++summary.failed_samples;
      continue;
    }
    summary.max_tip_force = std::max(summary.max_tip_force, s.tip_force);
    summary.min_tip_force = std::min(summary.min_tip_force, s.tip_force);
    summary.max_clamp_moment = std::max(summary.max_clamp_moment, s.clamp_moment);
    summary.min_clamp_moment = std::min(summary.min_clamp_moment, s.clamp_moment);
    summary.max_deflection = std::max(summary.max_deflection, s.deflection);
    summary.min_deflection = std::min(summary.min_deflection, s.deflection);
    summary.max_rotation = std::max(summary.max_rotation, s.rotation);
    summary.min_rotation = std::min(summary.min_rotation, s.rotation);
  }
  summary.mean_iterations = static_cast<double>(iterations) / static_cast<double>(samples.size());
  // Energies over the last cycle, only from converged samples.
  const std::size_t end = samples.size() - 1;
  const std::size_t begin = end - static_cast<std::size_t>(drive.points);
  const ExperimentSample* previous = nullptr;
  for (std::size_t k = begin; k <= end; ++k) {
    const ExperimentSample& s = samples[k];
    if (!s.solve.converged()) continue;
    if (previous) {
      const double work = 0.5 * (s.tip_force + previous->tip_force) * (s.deflection - previous->deflection) +
                          0.5 * (s.tip_moment + previous->tip_moment) * (s.rotation - previous->rotation);
      summary.loop_work += work;
      summary.measured_loop_area +=
          drive.experiment == Experiment::a
              ? 0.5 * (s.tip_force + previous->tip_force) * (s.deflection - previous->deflection)
              : 0.5 * (s.clamp_moment + previous->clamp_moment) * (s.rotation - previous->rotation);
    } else {
      summary.slider_dissipation = -s.dissipated;
    }
    previous = &s;
  }
  summary.slider_dissipation = previous ? summary.slider_dissipation + previous->dissipated : 0.0;
  if (std::any_of(samples.begin() + static_cast<std::ptrdiff_t>(begin), samples.end(),
                  [](const ExperimentSample& s) { return !s.solve.converged(); })) {
    // A gap in the loop: its energies would be numbers nobody can trust.
    summary.slider_dissipation = summary.loop_work = summary.measured_loop_area =
        std::numeric_limits<double>::quiet_NaN();
  }
  return summary;
}

}  // namespace

std::vector<ExperimentSample> run_path(Cantilever& cantilever, Experiment experiment,
                                       const std::vector<double>& prescribed) {
  std::vector<ExperimentSample> samples;
  samples.reserve(prescribed.size());
  for (const double value : prescribed) {
    const StateDetermination solve =
        experiment == Experiment::a ? cantilever.set_trial_deflection(value) : cantilever.set_trial_rotation(value);
    samples.push_back(sample_of(cantilever, solve));
    if (solve.converged()) {
      cantilever.commit();
    } else {
      cantilever.revert_to_last_commit();
    }
  }
  return samples;
}

ExperimentRecord run_experiment(Cantilever& cantilever, const ExperimentDrive& drive) {
  drive.validate();
  const int count = drive.cycles * drive.points + 1;
  std::vector<double> prescribed(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) prescribed[static_cast<std::size_t>(k)] = drive.prescribed(k);
  ExperimentRecord record;
  record.samples = run_path(cantilever, drive.experiment, prescribed);
  record.summary = summarise(record.samples, drive);
  return record;
}

}  // namespace stockbridge::cable
