#include "stockbridge/span/span.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/tension_figures.hpp"

namespace stockbridge::span {

namespace {

void require_one_of(const std::optional<double>& a, std::string_view a_name, const std::optional<double>& b,
                    std::string_view b_name) {
  if (a.has_value() == b.has_value()) {
    throw InvalidParameter(std::string(a.has_value() ? a_name : b_name),
                           fmt::format(": give exactly one of {} and {}", a_name, b_name));
  }
}

}  // namespace

void FatigueSpec::validate() const {
  require_one_of(cycles, "cycles", endurance_limit, "endurance_limit");
  if (cycles) require_plausible("cycles", *cycles, "");
  if (endurance_limit) require_plausible("endurance_limit", *endurance_limit, "Pa");
  if (life) life->validate();
  require_plausible("yb_distance", yb_distance, "m");
}

Span::Span(Conductor conductor, double length, double tension, WindModel wind, SelfDampingModel self_damping,
           std::vector<SpanDamper> dampers, FatigueSpec fatigue, std::optional<int> terrain)
    : conductor_(std::move(conductor)),
      length_(length),
      tension_(tension),
      wind_(std::move(wind)),
      self_damping_(std::move(self_damping)),
      dampers_(std::move(dampers)),
      fatigue_(std::move(fatigue)),
      terrain_(terrain) {
  within_field("conductor", [&] { conductor_.validate(); });
  require_plausible("span.length", length_, "m");
  check_tension(conductor_, tension_, "span.tension");
  within_field("wind", [&] { wind_.validate(); });
  within_field("self_damping", [&] { self_damping_.validate(); });
  self_damping_.validate_with(conductor_);  // names conductor.ei_max itself
  for (std::size_t j = 0; j < dampers_.size(); ++j) {
    if (dampers_[j].damper.has_value() == dampers_[j].measured()) {
      throw InvalidParameter(fmt::format("damper[{}]", j), ": expected a damper model or a measured sheet, one of the two");
    }
    const double a = dampers_[j].position;
    if (a > 0.0 && !(a < 0.5 * length_) && typical::damper_position.contains(a)) {
      throw_invalid("span.length", length_,
                    fmt::format("more than twice damper[{}].position = {} m: the span is too short for its dampers{}",
                                j, format_value(a),
                                typical::span_length.slipped(length_) ? " (a length in km?)" : ""));
    }
    if (!(a > 0.0 && a < 0.5 * length_)) {
      throw_invalid(fmt::format("damper[{}].position", j), a,
                    fmt::format("a distance from the span end > 0 and < half the span, {} m", 0.5 * length_));
    }
  }
  within_field("fatigue", [&] { fatigue_.validate(); });
  if (terrain_) terrain_category(*terrain_, "span.terrain");
}

double Span::endurance_limit() const {
  if (fatigue_.endurance_limit) return *fatigue_.endurance_limit;
  return safe_border_line(conductor_.aluminium_layers).endurance_limit(*fatigue_.cycles);
}

Span Span::with_dampers_at(double position) const {
  std::vector<SpanDamper> moved = dampers_;
  const double shift = dampers_.empty() ? 0.0 : position - dampers_.front().position;
  for (SpanDamper& d : moved) d.position += shift;
  return Span(conductor_, length_, tension_, wind_, self_damping_, std::move(moved), fatigue_, terrain_);
}

Span Span::with_dampers(std::vector<SpanDamper> dampers) const {
  return Span(conductor_, length_, tension_, wind_, self_damping_, std::move(dampers), fatigue_, terrain_);
}

Span Span::without_dampers() const {
  return Span(conductor_, length_, tension_, wind_, self_damping_, {}, fatigue_, terrain_);
}

}  // namespace stockbridge::span
