#pragma once
// The damper's periodic steady state at one excitation, for the `response`
// command and the Python module: every distinct arm is solved directly and, if
// that fails (near a resonance the linear start can be far off), by continuation
// in frequency at constant velocity amplitude from a quarter of the frequency.

#include <vector>

#include "stockbridge/damper/impedance.hpp"

namespace stockbridge::damper {

struct DamperSteadyState {
  ImpedancePoint point;
  std::vector<ArmSolution> arms;  ///< one per arm of the damper (identical arms share a solution)
};

DamperSteadyState solve_steady_state(const Damper& damper, const Excitation& excitation,
                                     const SolverOptions& options);

}  // namespace stockbridge::damper
