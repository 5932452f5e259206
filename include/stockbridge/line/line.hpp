#pragma once
// A line: spans of different lengths, tensions, terrains and conductors sharing a
// climate and a choice of damper types (MODEL.md section 12; docs/line.md), and its
// damper schedule: for every span the fewest dampers per end, and where, that make
// it safe. A constant description, valid by construction; schedule.hpp computes.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/position_search.hpp"
#include "stockbridge/span/span.hpp"

namespace stockbridge::line {

/// A damper on offer: a model or a measured sheet (span::SpanDamper, its position
/// and ends set by the schedule), and its mass for the bill of materials.
struct DamperType {
  std::string name;
  span::SpanDamper damper;
  std::optional<double> mass;  ///< kg per damper: the model's own, or the line file's for a sheet
  std::optional<double> price;  ///< per damper, in the line file's currency (for choose = fewest-then-cheapest)
  std::string file;            ///< the damper file or sheet it was read from (absolute); empty if made in code
  std::string fit_from;        ///< a model fitted to the sheet `file`: the drawing it was fitted from (absolute)
};

/// How one span was given, beside the span itself: what a schedule row restates.
struct LineSpan {
  std::string id;
  span::Span span;               ///< without dampers
  span::BalanceOptions balance;  ///< the line's [balance]
  std::string tension_form;      ///< "tension", "tension_fraction" or "catenary_parameter"
  double tension_given = 0.0;    ///< in that form (N, a fraction, m)
  std::string conductor;         ///< the span's own conductor (a catalogue type or a file); empty: the line's
  std::string source;            ///< where it was given ("line.toml:34" or "spans.csv:12"), for messages
};

/// The position search's defaults for a line's spans (ScheduleRules::positions).
inline span::PositionRules line_position_rules() {
  span::PositionRules rules;
  rules.scan_points = 21;
  rules.max_evaluations = 40;
  rules.local_searches = 2;
  return rules;
}

/// Which damper type a span gets among those that make it safe with the fewest
/// dampers per end: the lightest, the cheapest, or the one of the lowest stress (the
/// objective); ties go to the objective, then to the type listed first.
enum class TypeChoice { fewest_then_lightest, fewest_then_cheapest, lowest_stress };
/// "fewest-then-lightest", "fewest-then-cheapest" or "lowest-stress"; InvalidParameter naming "choose" otherwise.
TypeChoice parse_type_choice(std::string_view name);
std::string_view type_choice_name(TypeChoice choice);

/// What decides that a span needs no damper: its own energy balance without
/// dampers (safe), or CIGRE TB 273's rule for its terrain (H/w within the limit of
/// its terrain category; a span without a terrain is judged by its balance).
enum class UndampedRule { balance, tb273 };
/// "balance" or "tb273"; InvalidParameter naming "undamped_rule" otherwise.
UndampedRule parse_undamped_rule(std::string_view name);
std::string_view undamped_rule_name(UndampedRule rule);

/// Whether a span's masses (warning spheres, markers) get dampers of their own: one on
/// either side of each mass, of the type at the span's ends (both_sides), or none.
enum class SphereDampers { both_sides, none };
/// "both sides" or "none"; InvalidParameter naming "sphere_dampers" otherwise.
SphereDampers parse_sphere_dampers(std::string_view name);
std::string_view sphere_dampers_name(SphereDampers rule);

/// The schedule's rules (the line file's [dampers] table, docs/line.md).
struct ScheduleRules {
  int min_per_end = 0;  ///< 0: a span safe without dampers gets none
  int max_per_end = 3;
  /// position_min, position_max, spacing_min, objective; a lighter search than one
  /// span's (a line has many): a scan of 21 positions for one damper, one local
  /// search of at most 40 balances for several.
  span::PositionRules positions = line_position_rules();
  /// Years: a span is safe when its life reaches this (and every point converged);
  /// none: when its largest fymax stress is within the endurance limit.
  std::optional<double> life_target;
  double position_step = 0.01;  ///< m: positions are rounded to this (what is installed)
  TypeChoice choose = TypeChoice::fewest_then_lightest;
  /// An arrangement whose verdict is uncertain (a measured sheet's band reaches above
  /// the limit) counts as safe; by default it does not.
  bool accept_uncertain = false;
  UndampedRule undamped_rule = UndampedRule::balance;
  int points = 100;             ///< frequencies of each arrangement's polished balance over the band
  int search_points = 40;       ///< frequencies of the position search's balances (tables alone)
  /// A span with masses: every arrangement also gets a damper on either side of each
  /// mass (both_sides), at one distance from it for the whole span, chosen within
  /// [sphere_distance_min, sphere_distance_max] (m from the mass's clamp). By default
  /// from 1 m (clear of a 600-800 mm sphere and the armour rods under its clamp) to 3 m.
  SphereDampers sphere_dampers = SphereDampers::both_sides;
  double sphere_distance_min = 1.0;
  double sphere_distance_max = 3.0;

  /// Throws InvalidParameter naming the field as the line file spells it
  /// ("dampers.max_per_end", "dampers.life_target", "dampers.position_step",
  /// "dampers.sphere_distance_max").
  void validate() const;
};

/// Where a span's dampers of one type go: `positions` (m from the clamp, increasing)
/// at both ends, and, with `sphere_distance`, one on either side of every mass at that
/// distance from it.
struct Arrangement {
  std::vector<double> positions;
  std::optional<double> sphere_distance;
};

class Line {
 public:
  /// Throws InvalidParameter naming the field: "span" (none), "span[3].id" (empty or
  /// repeated), "dampers.types" (none), a rule; "dampers.objective" for the life
  /// without a climate on some span; "dampers.sphere_distance_max" where the dampers
  /// beside a span's masses would come within spacing_min of each other or of the end
  /// dampers' range.
  Line(std::vector<LineSpan> spans, std::vector<DamperType> types, ScheduleRules rules);

  const std::vector<LineSpan>& spans() const { return spans_; }
  const std::vector<DamperType>& types() const { return types_; }
  const ScheduleRules& rules() const { return rules_; }

 private:
  std::vector<LineSpan> spans_;
  std::vector<DamperType> types_;
  ScheduleRules rules_;
};

/// Whether a span's arrangements get dampers beside its masses under `rules`: it has
/// masses and the rule is both_sides.
bool gets_sphere_dampers(const span::Span& span, const ScheduleRules& rules);

/// The positions (m from end 1, increasing) of the dampers `distance` m on either
/// side of each of the span's masses.
std::vector<double> sphere_damper_positions(const span::Span& span, double distance);

/// `span` with dampers of `type` as `arrangement` places them: one at each of its
/// positions at both ends (in that order), then, with a sphere distance, one damper
/// along the span at sphere_damper_positions (span::SpanDamper::along).
span::Span with_arrangement(const span::Span& span, const DamperType& type, const Arrangement& arrangement);

}  // namespace stockbridge::line
