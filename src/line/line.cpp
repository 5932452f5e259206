#include "stockbridge/line/line.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::line {

TypeChoice parse_type_choice(std::string_view name) {
  if (name == "fewest-then-lightest") return TypeChoice::fewest_then_lightest;
  if (name == "fewest-then-cheapest") return TypeChoice::fewest_then_cheapest;
  if (name == "lowest-stress") return TypeChoice::lowest_stress;
  throw InvalidParameter("choose", fmt::format(" = '{}': expected fewest-then-lightest, fewest-then-cheapest or "
                                               "lowest-stress",
                                               printable(name)));
}

std::string_view type_choice_name(TypeChoice choice) {
  switch (choice) {
    case TypeChoice::fewest_then_lightest: return "fewest-then-lightest";
    case TypeChoice::fewest_then_cheapest: return "fewest-then-cheapest";
    case TypeChoice::lowest_stress: return "lowest-stress";
  }
  return "fewest-then-lightest";
}

UndampedRule parse_undamped_rule(std::string_view name) {
  if (name == "balance") return UndampedRule::balance;
  if (name == "tb273") return UndampedRule::tb273;
  throw InvalidParameter("undamped_rule", fmt::format(" = '{}': expected balance or tb273", printable(name)));
}

std::string_view undamped_rule_name(UndampedRule rule) { return rule == UndampedRule::tb273 ? "tb273" : "balance"; }

SphereDampers parse_sphere_dampers(std::string_view name) {
  if (name == "both sides") return SphereDampers::both_sides;
  if (name == "none") return SphereDampers::none;
  throw InvalidParameter("sphere_dampers", fmt::format(" = '{}': expected \"both sides\" (a damper on either side of "
                                                       "each mass along a span) or \"none\"",
                                                       printable(name)));
}

std::string_view sphere_dampers_name(SphereDampers rule) { return rule == SphereDampers::none ? "none" : "both sides"; }

namespace {

/// Every mass position of the span (m from end 1), increasing.
std::vector<double> mass_positions(const span::Span& span) {
  std::vector<double> x;
  for (const span::SpanMass& m : span.masses()) x.insert(x.end(), m.positions.begin(), m.positions.end());
  std::sort(x.begin(), x.end());
  return x;
}

/// The dampers beside span `id`'s masses, sphere_distance_max from them, kept
/// spacing_min apart from each other and from the end dampers' range.
void check_sphere_room(const LineSpan& s, const ScheduleRules& rules) {
  const std::vector<double> x = mass_positions(s.span);
  const double d = rules.sphere_distance_max, gap = rules.positions.spacing_min;
  const double end_zone = rules.positions.position_max + gap + d;
  const auto refuse = [&](const std::string& why) {
    throw InvalidParameter("dampers.sphere_distance_max",
                           fmt::format(" = {}: on span \"{}\", {} (spacing_min = {} m): expected a smaller "
                                       "sphere_distance_max, or sphere_dampers = \"none\"",
                                       format_value(d), printable(s.id), why, format_value(gap)));
  };
  if (x.front() < end_zone || x.back() > s.span.length() - end_zone) {
    const double at = x.front() < end_zone ? x.front() : x.back();
    refuse(fmt::format("the dampers beside the mass at {} m would come within spacing_min of the end dampers' range "
                       "(position_max = {} m)",
                       format_value(at), format_value(rules.positions.position_max)));
  }
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x[i] - x[i - 1] < 2.0 * d + gap) {
      refuse(fmt::format("the dampers beside the masses at {} and {} m would come within spacing_min of each other",
                         format_value(x[i - 1]), format_value(x[i])));
    }
  }
}

}  // namespace

void ScheduleRules::validate() const {
  require_in_range("dampers.min_per_end", min_per_end, 0, 10);
  require_in_range("dampers.max_per_end", max_per_end, 1, 10);
  if (max_per_end < min_per_end) {
    throw InvalidParameter("dampers.max_per_end", fmt::format(" = {}: expected at least min_per_end = {}", max_per_end,
                                                              min_per_end));
  }
  try {
    positions.validate();
  } catch (const InvalidParameter& e) {
    throw InvalidParameter("dampers." + e.field(), e.detail());
  }
  if (life_target) require_positive("dampers.life_target", *life_target, "years");
  if (!(position_step > 0.0 && position_step <= 1.0)) throw_invalid("dampers.position_step", position_step, "a step from 0 to 1 m");
  require_in_range("dampers.points", points, 2, 100000);
  require_in_range("dampers.search_points", search_points, 2, 100000);
  if (!(std::isfinite(sphere_distance_min) && sphere_distance_min > 0.0)) {
    throw_invalid("dampers.sphere_distance_min", sphere_distance_min, "a distance > 0 m from a mass's clamp");
  }
  if (!(std::isfinite(sphere_distance_max) && sphere_distance_max >= sphere_distance_min)) {
    throw_invalid("dampers.sphere_distance_max", sphere_distance_max,
                  fmt::format("a distance >= sphere_distance_min = {} m", format_value(sphere_distance_min)));
  }
  const double room = positions.position_max - positions.position_min;
  if (static_cast<double>(max_per_end - 1) * positions.spacing_min > room) {
    throw InvalidParameter("dampers.spacing_min",
                           fmt::format(" = {}: {} dampers per end that far apart do not fit between position_min = {} "
                                       "and position_max = {} m",
                                       format_value(positions.spacing_min), max_per_end,
                                       format_value(positions.position_min), format_value(positions.position_max)));
  }
}

Line::Line(std::vector<LineSpan> spans, std::vector<DamperType> types, ScheduleRules rules)
    : spans_(std::move(spans)), types_(std::move(types)), rules_(std::move(rules)) {
  rules_.validate();
  if (spans_.empty()) throw InvalidParameter("span", ": the line has no span ([[span]] tables or spans = a CSV file)");
  if (types_.empty()) throw InvalidParameter("dampers.types", ": the line offers no damper type");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < spans_.size(); ++i) {
    const LineSpan& s = spans_[i];
    const std::string field = fmt::format("span[{}].id", i);
    if (s.id.find_first_not_of(" \t") == std::string::npos) throw InvalidParameter(field, ": empty: every span needs an id");
    if (!ids.insert(s.id).second) throw InvalidParameter(field, fmt::format(" = \"{}\": given to an earlier span too", printable(s.id)));
    if (!s.span.dampers().empty()) throw InvalidParameter(field, ": a line's span carries no dampers of its own");
    if (rules_.positions.objective == span::PositionObjective::life && !s.span.fatigue().life) {
      throw InvalidParameter("dampers.objective", " = \"life\": the line gives no climate ([fatigue] wind_weibull and "
                                                  "aeolian_fraction) to compute a life with");
    }
    if (!(rules_.positions.position_max < 0.5 * s.span.length())) {
      throw InvalidParameter("dampers.position_max",
                             fmt::format(" = {}: expected less than half of every span, {} m for span \"{}\"",
                                         format_value(rules_.positions.position_max),
                                         format_value(0.5 * s.span.length()), printable(s.id)));
    }
    if (rules_.life_target && !s.span.fatigue().life) {
      throw InvalidParameter("dampers.life_target", ": the line gives no climate ([fatigue] wind_weibull and "
                                                    "aeolian_fraction) to compute a life with");
    }
    if (gets_sphere_dampers(s.span, rules_)) check_sphere_room(s, rules_);
  }
  std::set<std::string> names;
  for (std::size_t t = 0; t < types_.size(); ++t) {
    if (types_[t].name.find_first_not_of(" \t") == std::string::npos) {
      throw InvalidParameter(fmt::format("dampers.types[{}].name", t), ": empty: every damper type needs a name");
    }
    if (!names.insert(types_[t].name).second) {
      throw InvalidParameter(fmt::format("dampers.types[{}].name", t),
                             fmt::format(" = \"{}\": given to an earlier type too", printable(types_[t].name)));
    }
    if (types_[t].mass) require_positive(fmt::format("dampers.types[{}].mass", t), *types_[t].mass, "kg");
    if (types_[t].price) require_non_negative(fmt::format("dampers.types[{}].price", t), *types_[t].price, "");
    // The choice compares every type by its mass or price: each must have it.
    if (types_.size() > 1 && rules_.choose == TypeChoice::fewest_then_cheapest && !types_[t].price) {
      throw InvalidParameter(fmt::format("dampers.types[{}].price", t),
                             ": missing: choose = \"fewest-then-cheapest\" compares every type's price");
    }
    if (types_.size() > 1 && rules_.choose == TypeChoice::fewest_then_lightest && !types_[t].mass) {
      throw InvalidParameter(fmt::format("dampers.types[{}].mass", t),
                             ": missing: choose = \"fewest-then-lightest\" compares every type's mass (a measured "
                             "sheet's type gives it as mass = kg), or choose = \"lowest-stress\"");
    }
  }
}

bool gets_sphere_dampers(const span::Span& span, const ScheduleRules& rules) {
  return !span.masses().empty() && rules.sphere_dampers == SphereDampers::both_sides;
}

std::vector<double> sphere_damper_positions(const span::Span& span, double distance) {
  std::vector<double> along;
  for (const double x : mass_positions(span)) {
    along.push_back(x - distance);
    along.push_back(x + distance);
  }
  return along;
}

span::Span with_arrangement(const span::Span& span, const DamperType& type, const Arrangement& arrangement) {
  std::vector<span::SpanDamper> dampers;
  span::SpanDamper d = type.damper;
  d.name = type.name;
  d.both_ends = true;
  d.along.clear();
  for (const double x : arrangement.positions) {
    d.position = x;
    dampers.push_back(d);
  }
  if (arrangement.sphere_distance) {
    d.position = 0.0;
    d.along = sphere_damper_positions(span, *arrangement.sphere_distance);
    dampers.push_back(std::move(d));
  }
  return span.with_dampers(std::move(dampers));
}

}  // namespace stockbridge::line
