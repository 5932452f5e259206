#pragma once
// The solver flags shared by the damper commands (impedance, response): the
// request layer's SolverSettings, by the same names. Defaults are the library's,
// per method (shown in --help from there, not repeated here).

#include <CLI/CLI.hpp>

#include "stockbridge/requests/solver_settings.hpp"

namespace stockbridge::cli {

class SolverFlags {
 public:
  void add_to(CLI::App& command);
  /// The settings given on the command line (unset flags stay unset).
  requests::SolverSettings settings() const;
  const std::string& method() const { return method_; }

 private:
  std::string method_ = "hb";
  int harmonics_ = 0, samples_ = 0, steps_ = 0, max_iterations_ = 0, max_periods_ = 0;
  double energy_tolerance_ = 0.0;
  CLI::Option *harmonics_flag_ = nullptr, *samples_flag_ = nullptr, *steps_flag_ = nullptr;
  bool full_period_ = false;
  CLI::Option *max_iterations_flag_ = nullptr, *max_periods_flag_ = nullptr, *energy_tolerance_flag_ = nullptr;
};

}  // namespace stockbridge::cli
