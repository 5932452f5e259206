#pragma once
// A damper design study (MODEL.md section 10): a base damper, the spans it serves,
// the numbers varied (by their damper-file paths, or the dampers' position on the
// spans), numbers tied to them, constraints and an objective. A candidate is one
// value per variable; its evaluation is the span balance of every span over its
// band, exactly as `stockbridge span` computes it, with the candidate replacing the
// spans' dampers.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <functional>
#include <vector>

#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/span/analysis.hpp"
#include "stockbridge/span/table_cache.hpp"

namespace stockbridge::design {

/// What a study minimises: the largest fymax stress over the spans and their bands
/// relative to each span's endurance limit, or (maximises) the shortest life.
enum class Objective { max_stress, life };
Objective parse_objective(std::string_view name);
std::string_view objective_name(Objective objective);

/// The name of the variable that moves the spans' dampers (m from the span clamp).
inline constexpr std::string_view kPosition = "position";
/// The variable that moves them by a rule that scales with each span's conductor
/// and tension: the first damper at this fraction of the span's shortest loop
/// c / (2 f_max) (MODEL.md section 12; c = sqrt(T / m), f_max the band's top).
inline constexpr std::string_view kPositionLoopFraction = "position_loop_fraction";

struct DesignVariable {
  std::string name;  ///< a damper number's path (damper_numbers.hpp) or "position"
  double min = 0.0;
  double max = 0.0;
};

/// A damper number that follows a variable (symmetric designs).
struct DesignTie {
  std::string name;    ///< a damper number's path
  std::string equals;  ///< a variable's name
};

struct DesignConstraints {
  std::optional<double> total_mass_max;           ///< kg, the clamp and the arms' masses
  std::optional<double> messenger_curvature_max;  ///< 1/m, every arm, span and frequency
};

/// A span the candidates serve, the name the results give it, and how it is
/// balanced (its span file's [balance] table).
struct DesignSpan {
  span::Span span;
  std::string name;
  span::BalanceOptions balance;
};

class DesignStudy {
 public:
  /// Throws InvalidParameter naming the field: a variable or tie that names no
  /// number of the base damper, min >= max, a tie to something that is not a
  /// variable, a position variable for spans without dampers at the ends, a
  /// non-positive budget.
  DesignStudy(damper::DamperDescription base, std::vector<DesignSpan> spans, Objective objective,
              std::vector<DesignVariable> variables, std::vector<DesignTie> ties, DesignConstraints constraints,
              int points = 100);

  const damper::DamperDescription& base() const { return base_; }
  const std::vector<DesignSpan>& spans() const { return spans_; }
  Objective objective() const { return objective_; }
  const std::vector<DesignVariable>& variables() const { return variables_; }
  const std::vector<DesignTie>& ties() const { return ties_; }
  const DesignConstraints& constraints() const { return constraints_; }
  /// Frequencies of each span's band (as `stockbridge span --points`).
  int points() const { return points_; }

  /// The base design's values of the variables (the position: the first span's first
  /// damper at the ends).
  std::vector<double> base_values() const;
  /// The damper of a candidate: the variables and ties set; an arm whose mass
  /// changes while its inertia is neither a variable nor tied keeps its radius of
  /// gyration (the inertia scales with the mass). Validated (InvalidParameter).
  damper::DamperDescription damper_of(const std::vector<double>& x) const;
  /// The dampers' position of a candidate: the position variable, none if not varied
  /// (or varied as a fraction of the loop: position_on).
  std::optional<double> position_of(const std::vector<double>& x) const;
  /// The first damper's position on span k (m): the position variable, or the loop
  /// fraction times span k's shortest loop; none where neither is varied.
  std::optional<double> position_on(std::size_t k, const std::vector<double>& x) const;
  /// Span k's shortest loop c / (2 f_max), m.
  double shortest_loop(std::size_t k) const;
  /// Span k with the candidate's damper in place of every damper of its file (those
  /// along the span too, where the file has them: beside its masses), at the
  /// candidate's position (every damper at the ends moved together; those along the
  /// span stay at the file's positions) or the file's. Its masses kept.
  span::Span span_with(std::size_t k, const damper::Damper& damper, std::optional<double> position) const;

 private:
  damper::DamperDescription base_;
  std::vector<DesignSpan> spans_;
  Objective objective_;
  std::vector<DesignVariable> variables_;
  std::vector<DesignTie> ties_;
  DesignConstraints constraints_;
  int points_;
};

/// A candidate's figures on one span (NaN where the candidate was not balanced there).
struct SpanFigures {
  double max_stress_ratio = std::numeric_limits<double>::quiet_NaN();     ///< its largest fymax stress / endurance limit
  double max_stress = std::numeric_limits<double>::quiet_NaN();           ///< Pa
  double undamped_max_stress = std::numeric_limits<double>::quiet_NaN();  ///< Pa, the same span without dampers
  double life_years = std::numeric_limits<double>::quiet_NaN();           ///< with the span's climate
  /// Where its largest stress lies: "span clamp 1", "span clamp 2" or a mass's clamp
  /// ("sphere at 120 m"): BalanceSummary::max_judged_stress_place.
  std::string governing_place;
  /// The candidate's dampers raise the span's largest stress above its undamped one.
  bool worse_than_undamped() const { return max_stress > undamped_max_stress; }
};

/// A candidate's figures. `objective` is what the study compares (smaller is better
/// for both objectives: the stress ratio, or minus the shortest life in years).
struct Evaluation {
  std::vector<double> x;
  /// How the candidate's balances ended: converged (every span's every point
  /// balanced), else the termination of the first point that did not (`failure`
  /// names the span, the frequency and the solver's report); not_run where the
  /// candidate could not be built (`infeasibility` says why).
  Termination termination = Termination::not_run;
  std::string failure;
  /// Why the candidate lies outside the design space: a broken constraint, or a
  /// damper or span that is not valid. Empty: within it.
  std::string infeasibility;
  double objective = std::numeric_limits<double>::infinity();
  double max_stress_ratio = std::numeric_limits<double>::quiet_NaN();  ///< largest fymax stress / endurance limit
  double max_stress = std::numeric_limits<double>::quiet_NaN();        ///< Pa, where the ratio is largest
  double frequency_at_max_hz = std::numeric_limits<double>::quiet_NaN();
  std::size_t span_at_max = 0;
  std::string place_at_max;  ///< on that span: its governing_place
  double total_mass = std::numeric_limits<double>::quiet_NaN();        ///< kg
  double messenger_curvature_max = std::numeric_limits<double>::quiet_NaN();  ///< 1/m
  double shortest_life_years = std::numeric_limits<double>::quiet_NaN();     ///< with objective life
  std::vector<SpanFigures> spans;  ///< one per span of the study, in its order (converged candidates)

  bool converged() const { return termination == Termination::converged; }
  /// Converged and within the design space: the only candidates a study ranks as answers.
  bool feasible() const { return converged() && infeasibility.empty(); }
};

/// The dampers' impedance tables of the candidates evaluated so far, by the span and
/// the values of their damper variables: candidates that differ only in the
/// position share them (a table depends on the damper and the span's band alone, so
/// sharing changes no result). Safe to use from several threads.
using TableCache = span::TableCache<span::SpanTables>;

/// A candidate as it can be built: each value rounded to `digits` significant digits
/// (masses, lengths and the rest alike), rounded toward the inside of its variable's
/// range where the nearest value lies outside it. InvalidParameter naming
/// "round_digits" unless 1 <= digits <= 15.
std::vector<double> rounded_candidate(const DesignStudy& study, const std::vector<double>& x, int digits);

/// Evaluates a candidate (one thread): the span analysis (span::analyse_span) of
/// every span with its own balance options, tables from `cache` where given. A
/// candidate whose damper is invalid (an arm mass below zero, a cable too short)
/// is infeasible, with the reason, and not run.
Evaluation evaluate(const DesignStudy& study, const std::vector<double>& x, TableCache* cache = nullptr);

}  // namespace stockbridge::design
