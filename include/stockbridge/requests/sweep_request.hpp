#pragma once
// The request layer for impedance sweeps: what a user asks for (amplitudes as
// velocities or displacements, a frequency grid or list, solver settings, threads)
// turned into the library's SweepSpec, and the sweep's points as the rows every
// front end shows, with non-converged points masked (NaN).

#include <optional>
#include <string>
#include <vector>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/requests/output_table.hpp"
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

/// The impedance CSV's quantities for `damper` (one row per point; Python's
/// impedance arrays): frequency, amplitudes, Z, powers and the solver's figures,
/// then the design figures (design_figures). Every computed number of a point that
/// did not converge is NaN (the frequency, amplitudes, iterations, periods and
/// flags are always given); Re Z, the power and an arm's power that are round-off
/// of zero (nothing slips) are 0.
Table<damper::ImpedancePoint> impedance_table(const damper::Damper& damper);

/// One point as `response --json` prints it and Python's response gives it:
/// frequency_hz, velocity_m_s, displacement_m, converged, termination, re_z_n_s_m,
/// im_z_n_s_m, power_w, dissipated_power_w, energy_error, then the design figures
/// by the impedance CSV's names; the computed ones NaN unless it converged.
Table<damper::ImpedancePoint> point_summary_table(const damper::Damper& damper);

/// The design figures of a point: messenger_curvature_max_per_m, then per arm
/// <arm>_power_w and <arm>_mass_amplitude_m (NaN unless it converged; an arm's
/// power that is round-off of zero, an arm that does not slip, as 0). The last
/// quantities of both tables above.
std::vector<Quantity<damper::ImpedancePoint>> design_figures();

/// How tables name each arm's columns (`<prefix>_x_m`): its name from the damper
/// file where every arm has one that is unique, made of letters, digits and '_',
/// and makes no column the table has already (not `dissipated` or `shaker`), else
/// arm1, arm2, ... for all (column_prefixes).
std::vector<std::string> arm_column_prefixes(const damper::Damper& damper);

/// Summary figures of a sweep.
struct SweepTally {
  int points = 0;
  int converged = 0;
  int non_unique = 0;
  std::optional<double> max_energy_error;  ///< over the converged points; none if none converged
};
SweepTally tally(const std::vector<damper::SweepRun>& runs);

/// A sweep's summary built as its points arrive (stream_sweep's order): the tally
/// and the points that did not converge, nothing kept of a converged point.
class SweepSummary {
 public:
  /// A point that did not converge.
  struct Failure {
    double frequency_hz = 0.0;
    double amplitude = 0.0;  ///< as given (V or X)
    Termination termination = Termination::not_run;
    std::string reason;
  };

  void add(double amplitude, const damper::ImpedancePoint& point);
  const SweepTally& tally() const { return tally_; }
  const std::vector<Failure>& failures() const { return failures_; }
  /// What `impedance --json` prints (sweep_summary).
  io::JsonObject json(std::string_view method, std::optional<double> seconds = std::nullopt) const;

 private:
  SweepTally tally_;
  std::vector<Failure> failures_;
};

/// The sweep's points in the CSV's order: each amplitude's frequencies in turn.
std::vector<const damper::ImpedancePoint*> sweep_points(const std::vector<damper::SweepRun>& runs);

/// What Python's impedance adds per point beside the CSV's columns: termination,
/// messages (why a point did not converge; a converged point's note).
Table<damper::ImpedancePoint> impedance_point_notes_table();

/// The summary `impedance --json` prints: method, points, converged, non_unique,
/// max_energy_error (null when no point converged), seconds (the wall time the
/// front end measured, when given), failed [{frequency_hz, amplitude, termination,
/// reason}].
io::JsonObject sweep_summary(const std::vector<damper::SweepRun>& runs, std::string_view method,
                             std::optional<double> seconds = std::nullopt);

}  // namespace stockbridge::requests
