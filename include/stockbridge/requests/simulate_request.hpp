#pragma once
// The request layer for the span in time (`stockbridge simulate`;
// span/conductor_in_time.hpp, docs/time-domain.md): what a user asks for by the
// names they type (frequency, duration, ends, probes), validated once; the run, with
// the energy balance at the same frequency beside it; the history's rows as they
// come, and the JSON summary.

#include <atomic>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/conductor_in_time.hpp"

namespace stockbridge::requests {

struct SimulateRequest {
  double frequency_hz = 0.0;          ///< the drive (the span's natural mode nearest it is taken)
  /// Each given one replaces the span file's (span::TimeSettings: [span] ends, [time]).
  std::optional<double> duration_s;   ///< simulated at most
  std::optional<std::string> ends;    ///< clamped | pinned
  std::optional<int> elements_per_wavelength;
  std::optional<int> steps_per_period;
  /// "ebm" (the energy balance's own wind, the default) or "wake" (the wake
  /// oscillator with the span file's [wake] parameters).
  std::string wind = "ebm";
  /// Where the history gives the displacement, m from end 1. Empty: the span clamp's
  /// Y_b point (yb_distance from end 1), each damper, mid-span.
  std::vector<double> probes;
  /// The drive mode's antinode amplitude at t = 0, m; none: the balance's at the
  /// asked frequency (the simulation then shows whether it stays there).
  std::optional<double> start_amplitude_m;
  int every = 1;                      ///< a history row every this many steps
};

/// Checks what can be checked without the span: InvalidParameter naming the setting
/// ("frequency", "duration", "ends", "elements_per_wavelength", "steps_per_period",
/// "wind", "probes[i]", "start_amplitude", "every").
void validate(const SimulateRequest& request);

/// The settings the run uses: the request's where it gives them, else the span
/// file's (`file`: its [span] ends and [time] table).
span::TimeSettings time_settings(const SimulateRequest& request, const span::TimeSettings& file);

/// The probes the history gives: the request's, or the defaults. InvalidParameter
/// naming "probes[i]" where one is past the span's length or within 0.5 mm of another.
std::vector<double> simulation_probes(const span::Span& span, const SimulateRequest& request);
/// Each probe's member of the history's <probe> columns: "y_at_89mm" (whole millimetres from end 1).
std::vector<std::string> probe_columns(const std::vector<double>& probes);

/// The dampers' count in the history (each position of each damper of the span).
std::size_t simulation_dampers(const span::Span& span);

/// A row of the history: the time and, at that time, the displacement at each
/// probe, each damper's clamp force and velocity.
struct SimulationRow {
  double time_s = 0.0;
  std::vector<double> y_m, force_n, velocity_m_s;
};

struct SimulateResult {
  span::EbmWindHistory history;
  std::vector<double> probes;              ///< m from end 1, as used
  std::vector<std::string> probe_columns;  ///< "y_at_89mm": the history's column per probe
  double asked_frequency_hz = 0.0;
  span::TimeSettings settings;             ///< as used
  span::WindInTime wind = span::WindInTime::ebm;
  double start_amplitude_m = 0.0;
  /// The energy balance's point (the span command's balance) at the simulation's frequency.
  span::BalancePoint balance;
  double seconds = 0.0;

  /// Whether the balance's point converged (its figures are usable).
  bool balance_converged() const;
  /// The balance's damper at `position_m` from end 1; none unless the balance converged.
  const span::DamperAtBalance* balance_damper(double position_m) const;
};

/// Runs the span file's span in time under the EBM's wind (a) with its dampers, with
/// the file's time settings but where the request gives its own, each history row to
/// `row` as it comes (every `request.every` steps), `progress` (simulated s, s
/// asked) once a second simulated; `stop` ends it early (`history.interrupted`),
/// with the periods done. The balance, with the file's balance options, at the asked
/// frequency gives the default start, and at the simulated frequency the comparison.
/// InvalidParameter as validate() and settle_on_ebm_wind.
SimulateResult run_simulate(const io::SpanFile& file, const SimulateRequest& request,
                            const std::function<void(const SimulationRow&)>& row,
                            const std::function<void(double, double)>& progress = {},
                            const std::atomic<bool>* stop = nullptr);

/// A steady figure of a run beside the balance's: the simulation's (NaN unless the
/// run settled), the balance's (NaN unless it converged), and their ratio.
struct ComparedFigure {
  double simulated = std::numeric_limits<double>::quiet_NaN();
  double balanced = std::numeric_limits<double>::quiet_NaN();
  double ratio = std::numeric_limits<double>::quiet_NaN();
};

/// The figures the span command judges, in time and by the balance: the antinode
/// amplitude (mid-span), the loop amplitude S next to clamp 1, Y_b there, and the
/// stresses from them (fatigue.hpp).
struct SteadyComparison {
  ComparedFigure antinode_amplitude_m, clamp_loop_amplitude_m, bending_amplitude_m, stress_poffenberger_swart_pa,
      stress_fymax_pa;
};
SteadyComparison steady_comparison(const span::Span& span, const SimulateResult& result);

/// The history CSV's quantities: time_s, <probe>_m (y at each probe), and per damper
/// (damper_1, damper_2, ... in the summary's order) <damper>_force_n (on the
/// conductor, upward) and <damper>_velocity_m_s (its clamp's).
Table<SimulationRow> simulation_table(const std::vector<std::string>& probe_columns, std::size_t dampers);

/// The --json summary: the run (frequency_hz, asked_frequency_hz, ends, elements,
/// dt_s, simulated_s, periods, settled, interrupted, start_amplitude_m), the steady
/// figures beside the balance's and their ratio (antinode amplitude, the clamp's
/// loop amplitude S, Y_b and the stresses; null unless settled, the balance's null
/// unless it converged), each damper's power, dissipation, velocity and force
/// harmonics, the envelope per period and the amplitude along the span.
io::JsonObject simulate_summary(const span::Span& span, const SimulateResult& result);

}  // namespace stockbridge::requests
