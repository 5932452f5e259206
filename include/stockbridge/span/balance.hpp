#pragma once
// The span's energy balance with nonlinear dampers (MODEL.md section 9): at each
// frequency f of the wind band, the antinode amplitude Y at which the power the
// wind feeds in equals what the conductor's self-damping and the dampers of both
// ends dissipate,
//     P_w(Y) = P_s(Y) + sum over ends P_d(Y),
// the smallest Y > 0 where P_w - P_s - P_d changes from positive to negative
// (vibration builds up from rest). Each end's P_d comes from the travelling-wave
// model with every damper's impedance at its own clamp velocity (a fixed point,
// end_fixed_point.hpp), or from the weak-damper form. The dampers' impedances come
// from an ImpedanceTable per damper, solved once for the band, then (the polish)
// from harmonic balance solved directly at each damper's clamp velocity, followed
// along the band (damper::DamperTracker). Then the stresses at
// the span clamp (fymax, Poffenberger-Swart) and at each damper clamp, and the
// endurance limit of the Safe Border Line.

#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/span/conductor.hpp"
#include "stockbridge/span/end_fixed_point.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/impedance_table.hpp"
#include "stockbridge/span/life.hpp"
#include "stockbridge/span/self_damping.hpp"
#include "stockbridge/span/undamped.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

/// A damper on the span: at `position` (m from the span end's clamp) at one end, or
/// at both ends (mirrored).
struct SpanDamper {
  damper::Damper damper;
  double position = 0.0;
  bool both_ends = true;
  std::string name;  ///< how tables and messages call it ("damper 1" or the file's stem)
};

/// Where the fatigue verdict's endurance limit comes from: the Safe Border Line at
/// `cycles`, or a given limit (Pa).
struct FatigueSpec {
  std::optional<double> cycles;
  std::optional<double> endurance_limit;
  std::optional<LifeModel> life;

  void validate() const;
};

/// A span as a span file describes it, valid by construction.
class Span {
 public:
  Span(Conductor conductor, double length, double tension, WindModel wind, SelfDampingModel self_damping,
       std::vector<SpanDamper> dampers, FatigueSpec fatigue);

  const Conductor& conductor() const { return conductor_; }
  double length() const { return length_; }
  double tension() const { return tension_; }
  const WindModel& wind() const { return wind_; }
  const SelfDampingModel& self_damping() const { return self_damping_; }
  const std::vector<SpanDamper>& dampers() const { return dampers_; }
  const FatigueSpec& fatigue() const { return fatigue_; }
  /// The endurance limit the verdict uses, Pa.
  double endurance_limit() const;
  /// The same span with every damper moved to `position` + (its position - the first's).
  Span with_dampers_at(double position) const;
  /// The same span without dampers.
  Span without_dampers() const;

 private:
  Conductor conductor_;
  double length_;
  double tension_;
  WindModel wind_;
  SelfDampingModel self_damping_;
  std::vector<SpanDamper> dampers_;
  FatigueSpec fatigue_;
};

enum class DamperModel { travelling, weak };
DamperModel parse_damper_model(std::string_view name);
std::string_view damper_model_name(DamperModel model);

struct BalanceOptions {
  DamperModel damper_model = DamperModel::travelling;
  ImpedanceTableOptions table;
  FixedPointOptions fixed_point;
  RootSearchOptions root;
  /// Polish with harmonic balance solved directly: at trial clamp velocities v each
  /// damper is solved directly and the span balanced with those impedances held
  /// fixed; the velocities that reproduce themselves are found by the secant method
  /// in log v, to `polish_tolerance`; then every damper's Z is the directly solved
  /// one at its v*. Without it the table's interpolation error stands (up to tens of
  /// percent in Z where a resonance passes the frequency as v grows: docs/span.md).
  bool polish = true;
  double polish_tolerance = 1e-6;
  int max_polish_iterations = 60;
  /// The amplitudes searched, as fractions of the conductor diameter.
  double amplitude_min_over_diameter = 1e-6;
  double amplitude_max_over_diameter = 10.0;

  void validate() const;
};

/// One damper at one frequency's balance.
struct DamperAtBalance {
  std::size_t damper = 0;               ///< its index in Span::dampers()
  int end = 1;                          ///< 1 or 2
  double clamp_velocity = 0.0;          ///< v_j, m/s
  std::complex<double> impedance;       ///< Z_j(f, v_j), N s/m
  double power = 0.0;                   ///< Re Z_j w^2 |Y_j|^2 / 2, W
  double clamp_stress = 0.0;            ///< conductor stress at its clamp from F = |Z| v, Pa
  /// The largest clamp-section curvature amplitude of the damper's arms (its own
  /// cable's fatigue load, 1/m) from the polish's direct solve at v_j; NaN without the polish.
  double messenger_curvature_max = std::numeric_limits<double>::quiet_NaN();
};

/// The balance at one frequency; numbers NaN unless converged.
struct BalancePoint {
  double frequency_hz = 0.0;
  double wind_speed = 0.0;              ///< U = f D / St, m/s
  double wavelength = 0.0;              ///< m
  double amplitude = 0.0;               ///< Y, antinode, zero-to-peak, m
  double wind_power = 0.0;              ///< P_w(Y), W
  double self_damping_power = 0.0;      ///< P_s(Y), W
  double damper_power = 0.0;            ///< both ends, W
  double clamp_loop_amplitude = 0.0;    ///< S at end 1, m
  double stress_fymax = 0.0;            ///< at the span clamp, Pa
  double stress_poffenberger_swart = 0.0;  ///< Pa
  double damper_clamp_stress = 0.0;     ///< largest over the dampers, Pa
  /// |P_d - sum Re Z w^2 |Y_j|^2 / 2| relative to the power the incoming waves bring
  /// to the ends, sum Z0 w^2 |B|^2 / 2 (the scale of P_d's round-off: P_d is the
  /// difference of the incoming and outgoing waves' powers)
  double identity_error = 0.0;
  std::vector<DamperAtBalance> dampers; ///< end 1's by position from the end, then end 2's
  double undamped_amplitude = 0.0;      ///< m
  double undamped_stress_fymax = 0.0;   ///< Pa
  Termination termination = Termination::not_run;
  std::string failure;

  bool converged() const { return termination == Termination::converged; }
};

/// The span's figures over the band.
struct BalanceSummary {
  int points = 0;
  int converged = 0;
  double endurance_limit = 0.0;          ///< Pa
  double max_stress_fymax = 0.0;         ///< Pa, over the converged points
  double max_stress_frequency_hz = 0.0;
  double max_damper_clamp_stress = 0.0;  ///< Pa
  double undamped_max_stress_fymax = 0.0;
  double undamped_max_stress_frequency_hz = 0.0;
  bool safe = false;                     ///< every converged point's fymax stress within the endurance limit
  std::optional<LifeEstimate> life;      ///< with dampers (when the span file gives the wind climate)
  std::optional<LifeEstimate> undamped_life;
  int impedance_nodes = 0;               ///< the tables' (frequency, velocity) nodes
  int failed_impedance_nodes = 0;
  int direct_solves = 0;                 ///< the polish's harmonic-balance solves of a damper
};

/// What a balance run returns.
struct SpanBalance {
  std::vector<BalancePoint> points;
  BalanceSummary summary;
};

/// The frequencies of the wind band f = St U / D, U from speed_min to speed_max, log-spaced.
std::vector<double> band_frequencies(const Span& span, int points);

/// The dampers' impedance tables for `frequencies` (one per damper of the span).
std::vector<ImpedanceTable> impedance_tables(const Span& span, const std::vector<double>& frequencies,
                                             const BalanceOptions& options, const damper::SweepProgress& progress = {});

/// The balance at every frequency (strictly increasing), with the dampers' tables
/// (impedance_tables for the same frequencies; none needed without dampers).
SpanBalance run_balance(const Span& span, const std::vector<double>& frequencies, const std::vector<ImpedanceTable>& tables,
                        const BalanceOptions& options);

/// The position (m from the span end) in [position_min, position_max] minimising the
/// largest fymax stress over the band, every damper moved together: a scan of
/// `scan_points` positions, then a golden-section refinement around the best; the
/// balances of the search use the tables without the polish (max_stress_fymax is
/// theirs), so balance the position found with the caller's options.
struct PositionSearch {
  double position = 0.0;
  double max_stress_fymax = 0.0;  ///< Pa, at the position found
  int balances = 0;               ///< balance runs made
};
PositionSearch optimise_position(const Span& span, const std::vector<double>& frequencies,
                                 const std::vector<ImpedanceTable>& tables, const BalanceOptions& options,
                                 double position_min, double position_max, int scan_points = 41);

}  // namespace stockbridge::span
