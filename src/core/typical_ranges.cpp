#include "stockbridge/core/typical_ranges.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge {

const std::vector<TypicalRange>& typical::all() {
  static const std::vector<TypicalRange> ranges{cable_length, ei,       jenkin_c,     jenkin_h,  clamp_mass,
                                                arm_mass,     arm_inertia, arm_offset, frequency, velocity,
                                                displacement, impedance, tip_deflection_ratio, tip_rotation,
                                                conductor_diameter, conductor_mass_per_length, span_length};
  return ranges;
}

std::string UnusualValue::message() const {
  const std::string unit = range.unit.empty() ? "" : fmt::format(" {}", range.unit);
  return fmt::format("{} = {}: outside the typical {} to {}{} of the {} ({})", field, format_value(value),
                     format_value(range.min), format_value(range.max), unit, range.quantity,
                     hint.empty() ? "a unit mistake?" : hint);
}

std::optional<UnusualValue> unusual(std::string field, double value, const TypicalRange& range) {
  if (range.contains(value)) return std::nullopt;
  return UnusualValue{std::move(field), value, range, {}};
}

void check_typical(std::vector<UnusualValue>& out, std::string field, double value, const TypicalRange& range) {
  if (auto u = unusual(std::move(field), value, range)) out.push_back(std::move(*u));
}

}  // namespace stockbridge
