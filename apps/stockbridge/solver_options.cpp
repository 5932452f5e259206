#include "solver_options.hpp"

namespace stockbridge::cli {

void SolverFlags::add_to(CLI::App& command) {
  command.add_option("--method", method, "Periodic solver: hb (harmonic balance), collocation, time, shooting")
      ->check(CLI::IsMember({"hb", "collocation", "time", "shooting"}))
      ->capture_default_str();
  command.add_option("--harmonics", harmonics, "Harmonics H (hb, collocation)")->capture_default_str();
  command.add_option("--samples", samples, "Time samples per period for hb (0: automatic, 8 H rounded up to a power of 2, at least 64)")
      ->capture_default_str();
  command.add_option("--steps", steps, "Time steps per period (time, shooting)")->capture_default_str();
  command.add_option("--max-iterations", max_iterations, "Newton iterations per point (hb, collocation)")->capture_default_str();
  command.add_option("--energy-tolerance", energy_tolerance,
                     "Largest energy-balance error (relative to the apparent power) of a trusted point")
      ->capture_default_str();
}

damper::SolverOptions SolverFlags::options() const {
  damper::SolverOptions options;
  options.method = damper::parse_method(method);
  options.harmonic_balance.harmonics = harmonics;
  options.harmonic_balance.samples = samples;
  options.harmonic_balance.max_iterations = max_iterations;
  options.steps_per_period = steps;
  options.energy_tolerance = energy_tolerance;
  options.validate();
  return options;
}

}  // namespace stockbridge::cli
