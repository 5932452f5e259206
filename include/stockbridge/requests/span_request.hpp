#pragma once
// The request layer for the span's energy balance (`stockbridge span`, Python's
// span): what a user asks for (frequencies or a number of points over the wind
// band, dampers or not, the damper model, a position search, threads) turned into
// the balance's inputs and run, and the balance's points as the rows every front
// end shows (CSV columns, Python arrays) with the numbers of a point that did not
// converge masked (NaN), and the summary (the --json keys).

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/profile.hpp"

namespace stockbridge::requests {

struct SpanRequest {
  std::vector<double> frequencies;  ///< Hz, strictly increasing; empty: `points` over the wind band
  int points = 100;                 ///< log-spaced over the wind band (span::band_frequencies), >= 2
  bool no_dampers = false;          ///< balance the span without its dampers
  /// Balance the span without its masses and the dampers along it (the dampers at
  /// its ends kept): the same span "without the warning spheres".
  bool no_attachments = false;
  /// travelling | weak, instead of the span file's [balance] damper_model.
  std::optional<std::string> damper_model;
  /// Search every damper's position in [min, max] (m from the span end's clamp),
  /// dampers at least spacing_min apart, minimising `objective` (max_stress or life),
  /// then balance the span there (span::optimise_positions).
  std::optional<double> position_min, position_max;
  double spacing_min = span::PositionRules{}.spacing_min;
  std::string objective = "max_stress";
  int threads = 1;                  ///< for the dampers' impedance tables
};

/// A span request validated once, its names parsed into the balance's types: what
/// run_span computes from. check_span_request is the only way to one, so a checked
/// request is never checked again.
class CheckedSpanRequest {
 public:
  const SpanRequest& request() const { return request_; }
  /// The damper model asked for instead of the span file's; none: the file's.
  std::optional<span::DamperModel> damper_model() const { return damper_model_; }
  /// The position search asked for; none: the dampers stay where the span has them.
  const std::optional<span::PositionRules>& positions() const { return positions_; }

 private:
  friend CheckedSpanRequest check_span_request(const SpanRequest& request);
  explicit CheckedSpanRequest(SpanRequest request) : request_(std::move(request)) {}
  SpanRequest request_;
  std::optional<span::DamperModel> damper_model_;
  std::optional<span::PositionRules> positions_;
};

/// Checks what can be checked without the span and parses the names (InvalidParameter
/// naming the setting: "frequencies[1]", "points", "damper_model", "optimize_position",
/// "spacing_min", "objective", "threads").
CheckedSpanRequest check_span_request(const SpanRequest& request);

/// Checks the request against the span it is for (the span file's, before
/// no_dampers drops its dampers), before anything is computed: InvalidParameter
/// "optimize_position" (a position search of a span without dampers) or "objective"
/// (the life, of a span without a climate). run_span calls it first; a front end that
/// wants the refusal before anything else of its own may call it before.
void check_against_span(const CheckedSpanRequest& request, const span::Span& span);

/// The analysis's options: the span file's balance options with the request's changes.
span::AnalysisOptions analysis_options(const span::BalanceOptions& file, const CheckedSpanRequest& request);

/// What a span request computed: the analysis (its span as balanced: without
/// dampers, or with them at the position found) and the damper model it used.
struct SpanResult {
  span::SpanAnalysis analysis;
  span::DamperModel damper_model = span::DamperModel::travelling;
};

/// Checks the request against the span (check_against_span) and runs the analysis
/// (span::analyse_span) at the request's frequencies, with the span file's balance
/// options (`file`) and the request's changes; `progress` counts the tables' nodes.
/// Non-convergence is in the points, never an exception. `take_point`: each point
/// handed on as it is final instead of held (span::AnalysisOptions::take_point; the
/// result's points are then none).
SpanResult run_span(const span::Span& span, const span::BalanceOptions& file, const CheckedSpanRequest& request,
                    const damper::SweepProgress& progress = {},
                    std::function<void(const span::Span&, span::BalancePoint&&)> take_point = {});

/// What the summary, the profile and the program's notes need of a span's points
/// beyond the balance's summary, gathered point by point (so that the points need
/// not be held): the largest energy identity error, the points with several steady
/// states and those that did not converge, and the governing point (the first of
/// the largest judged stress).
struct SpanPointTally {
  double max_identity_error = kNoValue;        ///< over the converged points
  std::vector<std::pair<double, std::string>> several_states;  ///< frequency, Hz, and the point's note
  std::vector<std::pair<double, SolverSummary>> failed;        ///< frequency, Hz, and why
  std::optional<span::BalancePoint> governing;

  /// `span`: the span as balanced.
  void add(const span::Span& span, const span::BalancePoint& p);
  /// The tally of a result's points.
  static SpanPointTally of(const SpanResult& result);
};

/// How the per-damper columns name each damper: the span's names (the damper files'
/// stems) where every one is unique and made of letters, digits and '_', else
/// damper1, damper2, ... for all (column_prefixes).
std::vector<std::string> span_damper_prefixes(const span::Span& span);

/// The span CSV's quantities, a row per balance point (`span`: the span as
/// balanced): frequency_hz, wind_speed_m_s, wavelength_m, amplitude_m,
/// amplitude_over_diameter, wind_power_w, self_damping_power_w, damper_power_w,
/// clamp_loop_amplitude_m, damper_clamp_velocity_m_s, stress_fymax_mpa,
/// stress_ps_mpa, damper_clamp_stress_mpa, undamped_amplitude_m,
/// undamped_stress_fymax_mpa, converged, endurance_limit_mpa,
/// energy_identity_error, undamped_stress_ps_mpa, several_states, then for each
/// damper and each end it is at (k = 1, 2) the family <damper>_end<k>_velocity_m_s,
/// _re_z_n_s_m, _im_z_n_s_m, _power_w, _clamp_stress_mpa. NaN for every computed
/// number of a point that did not converge (frequency, wind speed, wavelength and
/// the endurance limit are always given), and for the damper columns of a span
/// without dampers.
Table<span::BalancePoint> span_table(const span::Span& span);
/// What Python's span adds per point beside the CSV's columns: the governing place,
/// termination, messages (why a point did not converge), notes.
Table<span::BalancePoint> span_point_notes_table(const span::Span& span);

/// One sample of the standing wave along the span (span/profile.hpp).
struct SpanProfileRow {
  double x = 0.0;             ///< m from end 1
  double displacement = 0.0;  ///< |Y(x)|, m
  double envelope = 0.0;      ///< the stretch's antinode amplitude, m
  std::string attachment;     ///< at an attachment's position: "sphere (mass)", "sb1 (damper)"; empty elsewhere
};
/// The profile's rows: every sample, an attachment's name at its position.
std::vector<SpanProfileRow> span_profile_rows(const span::SpanProfile& profile);
/// attachment, x_m, displacement_m, envelope_m (`span --profile`'s CSV, Python's arrays).
Table<SpanProfileRow> span_profile_table();
/// The profile at the balance's governing frequency (the largest judged stress);
/// InvalidParameter naming "profile" when no point converged.
span::SpanProfile governing_profile(const SpanResult& result);
/// The same from a tally of its points (`span`: the span as balanced).
span::SpanProfile governing_profile(const span::Span& span, const SpanPointTally& tally);

/// The summary, as `stockbridge span --json` prints it and Python returns it:
/// points, converged, damper_model, dampers, endurance_limit_mpa, verdict (safe,
/// unsafe or unknown), max_stress_fymax_mpa, max_stress_frequency_hz (over the
/// converged points), max_damper_clamp_stress_mpa, undamped_max_stress_fymax_mpa,
/// undamped_max_stress_frequency_hz, undamped_verdict, position_m (the first
/// damper's), positions_m (every damper's, in the file's order), position_optimized, [life_years, damage_per_year, life_missing_points,
/// undamped_life_years, undamped_damage_per_year, undamped_life_missing_points when
/// the span file gives the climate: a life null where a point is missing],
/// impedance_nodes, failed_impedance_nodes, direct_solves, max_energy_identity_error,
/// several_states_hz, failed.
io::JsonObject span_summary(const SpanResult& result);
/// The same where the points were handed on as they came (`tally`: of all of them).
io::JsonObject span_summary(const SpanResult& result, const SpanPointTally& tally);

}  // namespace stockbridge::requests
