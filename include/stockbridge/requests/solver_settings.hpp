#pragma once
// The request layer (what the CLI and the Python module both call): a user's
// solver settings, by the names both front ends use, turned into the library's
// full per-method options. A setting left unset takes the chosen method's own
// default (SolverOptions holds each method's defaults, in one place); a setting
// the chosen method does not use is an error rather than silently ignored.

#include <optional>
#include <string>

#include "stockbridge/damper/impedance.hpp"

namespace stockbridge::requests {

struct SolverSettings {
  std::string method = "hb";              ///< hb | collocation | time | shooting
  std::optional<int> harmonics;           ///< H (hb, collocation)
  std::optional<int> samples;             ///< AFT samples per period (hb; 0: automatic)
  std::optional<int> steps;               ///< time steps per period (time, shooting)
  std::optional<int> max_iterations;      ///< Newton iterations per point (hb, collocation, shooting)
  std::optional<int> max_periods;         ///< periods integrated at most (time)
  std::optional<double> energy_tolerance; ///< largest energy-balance error of a trusted point (every method)
  std::optional<bool> half_wave;          ///< odd harmonics over half periods (hb; default true)
};

/// The options for `settings` (InvalidParameter naming the setting otherwise).
damper::SolverOptions solver_options(const SolverSettings& settings);

}  // namespace stockbridge::requests
