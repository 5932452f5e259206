#pragma once
// The span's energy balance with nonlinear dampers (MODEL.md section 9): at each
// frequency f of the wind band, the antinode amplitude Y at which the power the
// wind feeds in equals what the conductor's self-damping and the dampers of both
// ends dissipate,
//     P_w(Y) = P_s(Y) + sum over ends P_d(Y),
// the smallest Y > 0 where P_w - P_s - P_d changes from positive to negative
// (vibration builds up from rest). Each end's P_d comes from the travelling-wave
// model (travelling_wave.hpp), or from the weak-damper form. The dampers'
// impedances come first from an ImpedanceTable per damper, solved once for the
// band (end_fixed_point.hpp finds each end's clamp velocities on them), then (the
// polish) from harmonic balance solved directly at every damper's clamp velocity:
// all dampers' clamp velocities solved as one system, each frequency continuing
// from the last (docs/span.md, "Several dampers per end"). Then the stresses at
// the span clamp (fymax, Poffenberger-Swart) and at each damper clamp, and the
// summary: the largest stress, the verdict and the life, from converged points only.
//
// Most callers want analysis.hpp (tables, position search, balance and summary in
// one call); this is the balance itself.

#include <complex>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/span/end_fixed_point.hpp"
#include "stockbridge/span/impedance_table.hpp"
#include "stockbridge/span/life.hpp"
#include "stockbridge/span/span.hpp"
#include "stockbridge/span/undamped.hpp"

namespace stockbridge::span {

enum class DamperModel { travelling, weak };
/// Its name in outputs ("travelling", "weak"; a user's name is parsed by io::parse_damper_model).
std::string_view damper_model_name(DamperModel model);

/// How a span is balanced. Each default is here; a span file's [balance] table sets
/// them by the same names (docs/file-formats.md).
struct BalanceOptions {
  DamperModel damper_model = DamperModel::travelling;
  ImpedanceTableOptions table;
  FixedPointOptions fixed_point;
  RootSearchOptions root;
  /// Polish with harmonic balance solved directly at every damper's clamp velocity
  /// (all dampers' velocities as one system, to `polish_tolerance` in log v). Without
  /// it the tables' interpolation error stands (up to tens of percent in Z where a
  /// resonance passes the frequency as v grows: docs/span.md).
  bool polish = true;
  double polish_tolerance = 1e-6;
  /// The polish's evaluations of the system at one frequency at most (each solves
  /// every damper once).
  int max_polish_evaluations = 60;
  /// The amplitudes searched, as fractions of the conductor diameter.
  double amplitude_min_over_diameter = 1e-6;
  double amplitude_max_over_diameter = 10.0;

  /// Throws InvalidParameter naming the field ("table.velocities", "polish_tolerance").
  void validate() const;
};

/// The dampers' impedance tables of a span over its frequencies: one per damper, in
/// the span's order, all made for `frequencies()` (the balance takes them from here,
/// so the two cannot disagree).
class SpanTables {
 public:
  /// The tables of the span's dampers at `frequencies` (Hz, strictly increasing;
  /// none without dampers), one solved per damper of distinct mechanics (dampers
  /// alike share it); `progress` counts their nodes.
  SpanTables(const Span& span, std::vector<double> frequencies, const ImpedanceTableOptions& options,
             const damper::SweepProgress& progress = {});

  /// Tables made elsewhere (a line's, one per damper type, shared by its spans and
  /// threads): one per damper, each at `frequencies`; std::invalid_argument
  /// otherwise. nodes() counts none: nothing is solved here.
  SpanTables(std::vector<double> frequencies, std::vector<ImpedanceTable> tables);
  /// `solved`'s tables with those of `span`'s measured dampers made from its sheets
  /// (the same span but for the sheets: the band of a sheet's interpolation error).
  SpanTables(const SpanTables& solved, const Span& span);

  const std::vector<double>& frequencies() const { return frequencies_; }
  const std::vector<ImpedanceTable>& tables() const { return tables_; }
  /// The (frequency, velocity) nodes solved, a shared table's once; of which did not converge.
  int nodes() const { return nodes_; }
  int failed_nodes() const { return failed_nodes_; }

 private:
  std::vector<double> frequencies_;
  std::vector<ImpedanceTable> tables_;
  int nodes_ = 0;
  int failed_nodes_ = 0;
};

/// One damper at one frequency's balance.
struct DamperAtBalance {
  std::size_t damper = 0;               ///< its index in Span::dampers()
  int end = 1;                          ///< 1 or 2: the end whose chain it is on (the nearer, for one along the span)
  double position = 0.0;                ///< m from end 1
  double clamp_velocity = 0.0;          ///< v_j, m/s
  std::complex<double> impedance;       ///< Z_j(f, v_j), N s/m
  double power = 0.0;                   ///< Re Z_j w^2 |Y_j|^2 / 2, W
  double clamp_stress = 0.0;            ///< conductor stress at its clamp from F = |Z| v, Pa
  /// The largest clamp-section curvature amplitude of the damper's arms (its own
  /// cable's fatigue load, 1/m) from the polish's direct solve at v_j; NaN without the polish.
  double messenger_curvature_max = std::numeric_limits<double>::quiet_NaN();
};

/// A mass (a warning sphere, a marker) at one of its positions at one frequency's balance.
struct MassAtBalance {
  std::size_t mass = 0;        ///< its index in Span::masses()
  double position = 0.0;       ///< m from end 1
  double displacement = 0.0;   ///< |Y| there, m
  /// The conductor's stress at its clamp, Pa: the point force F = w^2 M |Y| on the
  /// tensioned beam (MODEL.md section 9), times the mass's stress_factor.
  double clamp_stress = 0.0;
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
  /// With a measured damper (a sheet): the band of the fymax stress its sheet's
  /// interpolation leaves, the stress times (1 -+ the sheets' error estimate:
  /// analysis.hpp), Pa; NaN without one, or unknown.
  double stress_fymax_low = std::numeric_limits<double>::quiet_NaN();
  double stress_fymax_high = std::numeric_limits<double>::quiet_NaN();
  double stress_poffenberger_swart = 0.0;  ///< Pa
  /// Yb, the peak-to-peak displacement relative to the span clamp at x_b
  /// (FatigueSpec::yb_distance): what a vibration recorder measures, m
  double bending_amplitude = 0.0;
  double damper_clamp_stress = 0.0;     ///< largest over the dampers, Pa
  /// The other span clamp's (end 2) loop, stresses and Yb, as end 1's above.
  double clamp_loop_amplitude_end2 = 0.0;
  double stress_fymax_end2 = 0.0;
  double stress_poffenberger_swart_end2 = 0.0;
  double bending_amplitude_end2 = 0.0;
  /// The largest antinode amplitude of the stretches between the span's attachments
  /// (Y itself without masses or dampers along the span), m, and where that stretch
  /// lies, m from end 1.
  double max_subspan_amplitude = 0.0;
  double max_subspan_from = 0.0;
  double max_subspan_to = 0.0;
  std::vector<MassAtBalance> masses;    ///< every mass at every position, by position from end 1
  /// |P_d - sum Re Z w^2 |Y_j|^2 / 2| relative to the power the incoming waves bring
  /// to the ends, sum Z0 w^2 |B|^2 / 2 (the scale of P_d's round-off: P_d is the
  /// difference of the incoming and outgoing waves' powers)
  double identity_error = 0.0;
  std::vector<DamperAtBalance> dampers; ///< end 1's by position from the end, then end 2's
  double undamped_amplitude = 0.0;      ///< m (NaN: no undamped balance)
  double undamped_stress_fymax = 0.0;   ///< Pa
  double undamped_stress_poffenberger_swart = 0.0;  ///< Pa
  double undamped_bending_amplitude = 0.0;  ///< Yb without dampers, m
  /// Without dampers (the masses kept): the largest stress the criterion judges over
  /// the span's clamps and the masses' clamps, and the largest stress of the life
  /// (Poffenberger-Swart at the span clamps, the point force's at a mass), Pa.
  double undamped_judged_stress = 0.0;
  double undamped_life_stress = 0.0;
  /// How the balance ended: converged; no_root (the wind's power exceeds the
  /// dissipation up to the amplitude limit: no stable balance); inner_failure (a
  /// damper's impedance not known or not solved: `where`); max_iterations or
  /// no_progress (the dampers' clamp velocities with directly solved impedances:
  /// evaluations, residual = max |log G - log v|); energy_mismatch (the ends'
  /// identity: residual = identity_error). brief_report(summary) is the message.
  SolverSummary summary;
  /// Several self-consistent states near this frequency: the continuation passed a
  /// fold of the clamp velocities (the sign of det(dh/du) changed since the last
  /// frequency), or the tables' start reached another state; `note` says which.
  bool several_states = false;
  /// A damper from a measured sheet moved below its sheet's lowest curve here (its Z
  /// held at that curve's: ImpedanceSheet); `note` says which.
  bool below_sheet = false;
  std::string note;

  bool converged() const { return summary.converged(); }
};

/// Pass or fail against the endurance limit, from converged points only: the stress
/// the span's criterion judges (Span::judges_poffenberger_swart: fymax, or the
/// Poffenberger-Swart stress of the microstrain criterion).
enum class Verdict {
  safe,       ///< every point converged, and every judged stress (and its band's top) within the limit
  unsafe,     ///< a converged point's judged stress exceeds the limit
  unknown,    ///< some points did not converge and none of the others exceeds the limit
  uncertain,  ///< every point converged within the limit, but a measured sheet's band reaches above it
};
std::string_view verdict_name(Verdict verdict);

/// Where a point's judged stress is largest, and that stress (Pa): a span clamp
/// ("span clamp 1", "span clamp 2": the criterion's stress there) or a mass's clamp
/// ("sphere at 150 m": the point-force stress). Span clamp 1 where they tie.
struct GoverningPlace {
  double stress = 0.0;
  std::string place;
};
GoverningPlace governing_place(const Span& span, const BalancePoint& point);
/// The stress the lives count at a point, Pa: the largest of the Poffenberger-Swart
/// stresses at the span clamps (the S-N curves are stated for it) and the masses' clamp stresses.
double life_stress(const BalancePoint& point);

/// The stress the span's criterion judges at a converged point, at its governing
/// place, Pa; and the top of its measured sheets' band (the same, times
/// stress_fymax_high / stress_fymax; NaN without a band).
double judged_stress(const Span& span, const BalancePoint& point);
double judged_stress_high(const Span& span, const BalancePoint& point);

/// The span's figures over the band; nothing here rests on a point that did not converge.
struct BalanceSummary {
  int points = 0;
  int converged = 0;
  double endurance_limit = 0.0;          ///< Pa
  /// Over the converged points (a lower bound where converged < points), Pa.
  double max_stress_fymax = 0.0;
  double max_stress_frequency_hz = 0.0;
  double max_damper_clamp_stress = 0.0;  ///< Pa
  /// Over the converged points too: the Poffenberger-Swart stress (Pa) and Yb (m) at the span clamp.
  double max_stress_poffenberger_swart = 0.0;
  double max_bending_amplitude = 0.0;
  /// The largest stress the criterion judges over the converged points (fymax, or
  /// Poffenberger-Swart under the microstrain criterion), Pa, its frequency, and the
  /// largest top of its measured sheets' band (NaN without one).
  double max_judged_stress = 0.0;
  double max_judged_stress_frequency_hz = 0.0;
  double max_judged_stress_high = std::numeric_limits<double>::quiet_NaN();
  /// Where that largest judged stress is (governing_place: "span clamp 1", a mass's clamp).
  std::string max_judged_stress_place;
  Verdict verdict = Verdict::unknown;
  int undamped_points = 0;               ///< with an undamped balance (the rest: none up to 10 D)
  double undamped_max_stress_fymax = 0.0;
  double undamped_max_stress_frequency_hz = 0.0;
  Verdict undamped_verdict = Verdict::unknown;
  double undamped_max_judged_stress = 0.0;               ///< Pa, as max_judged_stress
  double undamped_max_stress_poffenberger_swart = 0.0;  ///< Pa
  double undamped_max_bending_amplitude = 0.0;          ///< m
  /// Miner's life from the Poffenberger-Swart stresses (the Safe Border Line is stated
  /// for them), when the span gives the climate and every point converged; none
  /// otherwise (`life_missing_points` then says how many are missing).
  std::optional<LifeEstimate> life;
  std::optional<LifeEstimate> undamped_life;
  int life_missing_points = 0;
  int undamped_life_missing_points = 0;
  int several_states = 0;                ///< points with several self-consistent states
  int impedance_nodes = 0;               ///< the tables' (frequency, velocity) nodes
  int failed_impedance_nodes = 0;
  int direct_solves = 0;                 ///< the polish's harmonic-balance solves of a damper

  bool all_converged() const { return converged == points; }
};

/// What a balance run returns.
struct SpanBalance {
  std::vector<BalancePoint> points;
  BalanceSummary summary;
};

/// The frequencies of the wind band f = St U / D, U from speed_min to speed_max, log-spaced.
std::vector<double> band_frequencies(const Span& span, int points);

/// The span's figures without its dampers (its masses kept) at each of the tables'
/// frequencies, the undamped_* fields of a BalancePoint: the same for every
/// arrangement of the dampers, so a position search works them out once.
class UndampedFigures {
 public:
  UndampedFigures(const Span& span, const SpanTables& tables, const BalanceOptions& options);
  /// Point i's undamped_* fields.
  void fill(std::size_t i, BalancePoint& p) const;

 private:
  /// A BalancePoint's undamped_* fields: what is kept per frequency (not a whole
  /// point, ten times its size, held for every frequency of the band).
  struct Figures {
    double amplitude, stress_fymax, bending_amplitude, stress_poffenberger_swart, judged_stress, life_stress;
  };
  std::vector<Figures> figures_;
};

/// Point i of run_balance on the tables alone (options.polish is not used): each
/// frequency then stands on its own, so a caller may take them in any order (the
/// position search stops an arrangement as soon as a point shows it cannot win).
/// run_balance's preconditions: options valid, the tables one per damper;
/// `undamped` the span's.
BalancePoint balance_on_tables(const Span& span, const SpanTables& tables, std::size_t i, const BalanceOptions& options,
                               const UndampedFigures& undamped);

/// The balance at every frequency of the tables (made for this span's dampers, or
/// for dampers alike: only the dampers' positions may differ; none without dampers).
/// `undamped`: the span's, made with the same tables and options (none: worked out
/// here). std::invalid_argument when the tables are not one per damper.
SpanBalance run_balance(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                        const UndampedFigures* undamped = nullptr);

}  // namespace stockbridge::span
