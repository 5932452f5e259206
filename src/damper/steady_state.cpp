#include "stockbridge/damper/steady_state.hpp"

#include <cmath>

#include "stockbridge/damper/sweep.hpp"

namespace stockbridge::damper {

namespace {

ArmSolution solve_arm(const Arm& arm, const Excitation& excitation, const SolverOptions& options) {
  const std::unique_ptr<ArmSolver> solver = make_arm_solver(arm, options);
  ArmSolution direct = solver->solve(excitation, Eigen::VectorXd());
  if (direct.summary.converged) return direct;
  // Continuation at constant velocity amplitude from f/4 up to f.
  const double v = excitation.velocity_amplitude();
  const std::vector<double> path = log_spaced(excitation.frequency_hz / 4.0, excitation.frequency_hz, 25);
  Eigen::VectorXd predictor;
  double predictor_amplitude = 0.0;
  ArmSolution last;
  for (const double f : path) {
    const Excitation step = Excitation::from_velocity(f, v);
    if (predictor.size() > 0) predictor *= step.displacement_amplitude / predictor_amplitude;
    last = solver->solve(step, predictor);
    if (!last.summary.converged) break;
    predictor = last.unknowns;
    predictor_amplitude = step.displacement_amplitude;
  }
  if (last.summary.converged) {
    last.summary.message = "reached by continuation from " + std::to_string(path.front()) + " Hz";
    return last;
  }
  return direct;
}

}  // namespace

DamperSteadyState solve_steady_state(const DamperDescription& damper, const Excitation& excitation,
                                     const SolverOptions& options) {
  damper.validate();
  excitation.validate();
  options.validate();
  const std::vector<std::size_t> representative = distinct_arms(damper);
  DamperSteadyState state;
  state.arms.resize(damper.arms.size());
  for (std::size_t k = 0; k < damper.arms.size(); ++k) {
    if (representative[k] == k) {
      state.arms[k] = solve_arm(Arm(damper.arms[k]), excitation, options);
    } else {
      state.arms[k] = state.arms[representative[k]];
    }
  }
  std::vector<const ArmSolution*> pointers;
  for (const ArmSolution& s : state.arms) pointers.push_back(&s);
  state.point = combine(damper, excitation, pointers, options.energy_tolerance);
  return state;
}

}  // namespace stockbridge::damper
