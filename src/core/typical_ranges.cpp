#include "stockbridge/core/typical_ranges.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge {

const std::vector<TypicalRange>& typical::all() {
  static const std::vector<TypicalRange> ranges{cable_length, ei,       jenkin_c,     jenkin_h,  clamp_mass,
                                                arm_mass,     arm_inertia, arm_offset, frequency, velocity,
                                                displacement, impedance, tip_deflection_ratio, tip_rotation,
                                                conductor_diameter, conductor_mass_per_length, span_length,
                                                rated_tensile_strength, conductor_ei_min, conductor_ei_max,
                                                outer_wire_diameter, outer_wire_modulus, span_tension,
                                                tension_fraction, catenary_parameter, damper_position, attachment_mass, strouhal,
                                                wind_speed, turbulence_intensity, self_damping_l, self_damping_m,
                                                self_damping_n, fatigue_cycles, endurance_limit, endurance_limit_mpa,
                                                limit_pp_microstrain, weibull_shape,
                                                weibull_scale, aeolian_fraction, yb_distance, recorder_yb,
                                                self_damping_amplitude, self_damping_power, yb_pp_mm};
  return ranges;
}

std::optional<double> TypicalRange::slipped(double value) const {
  if (slip.factor == 0.0 || contains(value)) return std::nullopt;
  const double si = value * slip.factor;
  if (!contains(si)) return std::nullopt;
  return si;
}

std::string UnusualValue::message() const {
  const std::string unit = range.unit.empty() ? "" : fmt::format(" {}", range.unit);
  std::string slip_hint = hint;
  if (const std::optional<double> si = range.slipped(value); slip_hint.empty() && si) {
    const std::string si_text = range.unit.empty() ? fmt::format("{:.6g}", *si) : fmt::format("{:.6g} {}", *si, range.unit);
    slip_hint = range.slip.unit == "%" ? fmt::format("a percentage? {} % = {}", format_value(value), si_text)
                                       : fmt::format("in {}? {} {} = {}", range.slip.unit, format_value(value),
                                                     range.slip.unit, si_text);
  }
  return fmt::format("{} = {}: outside the typical {:.6g} to {:.6g}{} of the {} ({})", field, format_value(value),
                     range.min, range.max, unit, range.quantity, slip_hint.empty() ? "a unit mistake?" : slip_hint);
}

std::optional<UnusualValue> unusual(std::string field, double value, const TypicalRange& range) {
  if (range.contains(value)) return std::nullopt;
  return UnusualValue{std::move(field), value, range, {}};
}

void check_typical(std::vector<UnusualValue>& out, std::string field, double value, const TypicalRange& range) {
  if (auto u = unusual(std::move(field), value, range)) out.push_back(std::move(*u));
}

void judge_unusual(const UnusualValue& value, const std::string& location, SlipPolicy policy,
                   std::vector<std::string>& warnings) {
  if (policy == SlipPolicy::refuse && value.slip_explained()) throw UnusualValueError(location + value.message());
  warnings.push_back(location + value.message());
}

void judge_implausible(std::string line, SlipPolicy policy, std::vector<std::string>& warnings) {
  if (policy == SlipPolicy::refuse) throw UnusualValueError(line);
  warnings.push_back(std::move(line));
}

}  // namespace stockbridge
