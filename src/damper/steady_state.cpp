#include "stockbridge/damper/steady_state.hpp"

#include <cmath>

#include <fmt/format.h>

#include "stockbridge/damper/sweep.hpp"

namespace stockbridge::damper {

namespace {

ArmSolution solve_arm(const Arm& arm, const Excitation& excitation, const SolverOptions& options) {
  const std::unique_ptr<ArmSolver> solver = make_arm_solver(arm, options);
  Continuation cold;
  ArmSolution direct = solver->solve(excitation, cold);
  if (direct.summary.converged()) return direct;
  // Continuation at constant velocity amplitude from f/4 up to f.
  const double v = excitation.velocity_amplitude();
  const std::vector<double> path_frequencies = log_spaced(excitation.frequency_hz / 4.0, excitation.frequency_hz, 25);
  Continuation path;
  ArmSolution last;
  for (const double f : path_frequencies) {
    last = solver->solve(Excitation::from_velocity(f, v), path);
    if (!last.summary.converged()) break;
  }
  if (!last.summary.converged()) return direct;
  last.note = fmt::format("reached by continuation from {:.4g} Hz", path_frequencies.front());
  return last;
}

}  // namespace

DamperSteadyState solve_steady_state(const Damper& damper, const Excitation& excitation, const SolverOptions& options) {
  excitation.validate();
  options.validate();
  DamperSteadyState state;
  state.arms.resize(damper.arms().size());
  for (std::size_t k = 0; k < damper.arms().size(); ++k) {
    const std::size_t r = damper.representative()[k];
    state.arms[k] = r == k ? solve_arm(damper.arms()[k], excitation, options) : state.arms[r];
  }
  std::vector<const ArmSolution*> pointers;
  for (const ArmSolution& s : state.arms) pointers.push_back(&s);
  state.point = combine(damper, excitation, pointers, options.energy_tolerance);
  return state;
}

}  // namespace stockbridge::damper
