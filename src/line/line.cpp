#include "stockbridge/line/line.hpp"

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::line {

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
    if (s.id.empty()) throw InvalidParameter(field, ": empty: every span needs an id");
    if (!ids.insert(s.id).second) throw InvalidParameter(field, fmt::format(" = \"{}\": given to an earlier span too", printable(s.id)));
    if (!s.span.dampers().empty()) throw InvalidParameter(field, ": a line's span carries no dampers of its own");
    if (rules_.positions.objective == span::PositionObjective::life && !s.span.fatigue().life) {
      throw InvalidParameter("dampers.objective", " = \"life\": the line gives no climate ([fatigue] wind_weibull and "
                                                  "aeolian_fraction) to compute a life with");
    }
    if (rules_.life_target && !s.span.fatigue().life) {
      throw InvalidParameter("dampers.life_target", ": the line gives no climate ([fatigue] wind_weibull and "
                                                    "aeolian_fraction) to compute a life with");
    }
  }
  std::set<std::string> names;
  for (std::size_t t = 0; t < types_.size(); ++t) {
    if (!names.insert(types_[t].name).second) {
      throw InvalidParameter(fmt::format("dampers.types[{}].name", t),
                             fmt::format(" = \"{}\": given to an earlier type too", printable(types_[t].name)));
    }
    if (types_[t].mass) require_positive(fmt::format("dampers.types[{}].mass", t), *types_[t].mass, "kg");
  }
}

span::Span with_arrangement(const span::Span& span, const DamperType& type, const std::vector<double>& positions) {
  std::vector<span::SpanDamper> dampers;
  for (const double x : positions) {
    span::SpanDamper d = type.damper;
    d.position = x;
    d.both_ends = true;
    d.name = type.name;
    dampers.push_back(std::move(d));
  }
  return span.with_dampers(std::move(dampers));
}

}  // namespace stockbridge::line
