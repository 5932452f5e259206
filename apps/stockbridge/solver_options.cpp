#include "solver_options.hpp"

#include <fmt/format.h>

namespace stockbridge::cli {

void SolverFlags::add_to(CLI::App& command) {
  const damper::SolverOptions defaults;
  command.add_option("--method", method_, "Periodic solver: hb (harmonic balance), collocation, time, shooting")
      ->check(CLI::IsMember({"hb", "collocation", "time", "shooting"}))
      ->capture_default_str();
  harmonics_flag_ = command.add_option(
      "--harmonics", harmonics_,
      fmt::format("Harmonics H (hb: default {}, collocation: default {})", defaults.harmonic_balance.harmonics,
                  defaults.collocation.harmonics));
  samples_flag_ = command.add_option(
      "--samples", samples_, "Time samples per period for hb (default: 8 H rounded up to a multiple of 16, at least 64)");
  command.add_flag(
      "--full-period", full_period_, "hb: every harmonic and the mean over whole periods (default: odd harmonics over half "
                       "periods, as the symmetric law and drive allow)");
  steps_flag_ = command.add_option(
      "--steps", steps_, fmt::format("Time steps per period (time, shooting; default {})", defaults.time_integration.steps_per_period));
  max_iterations_flag_ = command.add_option(
      "--max-iterations", max_iterations_,
      fmt::format("Newton iterations per point (hb, collocation: default {}; shooting: default {})",
                  defaults.harmonic_balance.max_iterations, defaults.shooting.max_iterations));
  max_periods_flag_ = command.add_option(
      "--max-periods", max_periods_,
      fmt::format("Periods integrated at most (time; default {})", defaults.time_integration.max_periods));
  energy_tolerance_flag_ = command.add_option(
      "--energy-tolerance", energy_tolerance_,
      fmt::format("Largest energy-balance error (relative to the apparent power) of a trusted point (default {})",
                  defaults.energy_tolerance));
}

requests::SolverSettings SolverFlags::settings() const {
  requests::SolverSettings s;
  s.method = method_;
  if (harmonics_flag_->count() > 0) s.harmonics = harmonics_;
  if (samples_flag_->count() > 0) s.samples = samples_;
  if (full_period_) s.half_wave = false;
  if (steps_flag_->count() > 0) s.steps = steps_;
  if (max_iterations_flag_->count() > 0) s.max_iterations = max_iterations_;
  if (max_periods_flag_->count() > 0) s.max_periods = max_periods_;
  if (energy_tolerance_flag_->count() > 0) s.energy_tolerance = energy_tolerance_;
  return s;
}

}  // namespace stockbridge::cli
