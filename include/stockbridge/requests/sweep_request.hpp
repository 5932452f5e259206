#pragma once
// The request layer for impedance sweeps: what a user asks for (amplitudes as
// velocities or displacements, a frequency grid or list, solver settings, threads)
// turned into the library's SweepSpec, and the sweep's points as the rows every
// front end shows, with non-converged points masked (NaN).

#include <optional>
#include <string>
#include <vector>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/requests/solver_settings.hpp"

namespace stockbridge::requests {

/// Log-spaced frequencies from fmin to fmax (Hz); its ends are exactly fmin and fmax.
struct FrequencyGrid {
  double fmin = 1.0;
  double fmax = 100.0;
  int points = 200;
};

struct SweepRequest {
  std::vector<double> velocities;     ///< V, m/s (constant over the sweep) ...
  std::vector<double> displacements;  ///< ... or X, m: exactly one of the two is given
  std::vector<double> frequencies;    ///< explicit frequencies, Hz; empty: the grid
  FrequencyGrid grid;
  SolverSettings solver;
  int threads = 1;
};

/// The validated sweep (InvalidParameter naming the setting otherwise).
damper::SweepSpec sweep_spec(const SweepRequest& request);

/// One excitation from a frequency and exactly one of a velocity amplitude (m/s)
/// and a displacement amplitude (m), validated.
damper::Excitation excitation(double frequency_hz, std::optional<double> velocity, std::optional<double> displacement);

/// The columns of a point of `damper` as the impedance CSV and Python's arrays name
/// them: frequency, amplitudes, Z, powers and the solver's figures, then the design
/// figures (figure_columns).
std::vector<std::string> impedance_columns(const damper::Damper& damper);
/// A point's values in impedance_columns() order: NaN for every computed number of
/// a point that did not converge (the amplitude and frequency are always given).
/// `point.arms` has one entry per arm (as combine makes it).
std::vector<double> impedance_row(const damper::ImpedancePoint& point);

/// The design figures' names, the last columns of impedance_columns() and the keys
/// `response` reports them by: messenger_curvature_max_per_m, then per arm
/// <prefix>_power_w and <prefix>_mass_amplitude_m (prefixes: arm_column_prefixes).
std::vector<std::string> figure_columns(const damper::Damper& damper);
/// Their values for a point in that order: NaN unless it converged; an arm's power
/// that is round-off of zero (an arm that does not slip) as 0.
std::vector<double> figure_values(const damper::ImpedancePoint& point);

/// How tables name each arm's columns (`<prefix>_x_m`): its name from the damper
/// file where every arm has one that is unique, made of letters, digits and '_',
/// and makes no column the table has already (not `dissipated` or `shaker`), else
/// arm1, arm2, ... for all.
std::vector<std::string> arm_column_prefixes(const damper::Damper& damper);

/// Summary figures of a sweep.
struct SweepTally {
  int points = 0;
  int converged = 0;
  int non_unique = 0;
  std::optional<double> max_energy_error;  ///< over the converged points; none if none converged
};
SweepTally tally(const std::vector<damper::SweepRun>& runs);

}  // namespace stockbridge::requests
