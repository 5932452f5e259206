#include "stockbridge/span/conductor.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::span {

std::string_view wire_material_name(WireMaterial material) {
  switch (material) {
    case WireMaterial::steel: return "steel";
    case WireMaterial::aluminium: return "aluminium";
    case WireMaterial::aluminium_alloy: return "aluminium-alloy";
    case WireMaterial::aluminium_clad_steel: return "aluminium-clad-steel";
  }
  return "steel";
}

WireMaterial parse_wire_material(std::string_view name, std::string_view field) {
  if (name == "steel") return WireMaterial::steel;
  if (name == "aluminium" || name == "aluminum") return WireMaterial::aluminium;
  if (name == "aluminium-alloy" || name == "aluminum-alloy") return WireMaterial::aluminium_alloy;
  if (name == "aluminium-clad-steel" || name == "aluminum-clad-steel") return WireMaterial::aluminium_clad_steel;
  throw InvalidParameter(std::string(field),
                         fmt::format(" = \"{}\": expected steel, aluminium, aluminium-alloy or aluminium-clad-steel",
                                     printable(name)));
}

bool is_aluminium(WireMaterial material) {
  return material == WireMaterial::aluminium || material == WireMaterial::aluminium_alloy;
}

void Conductor::validate() const {
  require_plausible("mass_per_length", mass_per_length, "kg/m");
  require_plausible("diameter", diameter, "m");
  require_plausible("rated_tensile_strength", rated_tensile_strength, "N");
  require_plausible("ei_min", ei_min, "N m^2");
  require_plausible_or_zero("ei_max", ei_max, "N m^2");
  if (ei_max != 0.0 && ei_max < ei_min) {
    // The one outside its typical range is the one at fault (an ei_min in N mm^2 or
    // copied from ei_max), else the no-slip bound, which must be the larger.
    if (!typical::conductor_ei_min.contains(ei_min) && typical::conductor_ei_max.contains(ei_max)) {
      throw_invalid("ei_min", ei_min,
                    fmt::format("at most ei_max = {} N m^2 (the free wires' stiffness, typically {} to {} N m^2)",
                                format_value(ei_max), format_value(typical::conductor_ei_min.min),
                                format_value(typical::conductor_ei_min.max)));
    }
    throw_invalid("ei_max", ei_max, fmt::format("0 (not given) or at least ei_min = {} N m^2", format_value(ei_min)));
  }
  require_plausible("outer_wire_diameter", outer_wire_diameter, "m");
  if (!(outer_wire_diameter < diameter)) {
    throw_invalid("outer_wire_diameter", outer_wire_diameter,
                  fmt::format("less than the conductor's diameter = {} m", format_value(diameter)));
  }
  require_plausible("outer_wire_modulus", outer_wire_modulus, "Pa");
  // The Safe Border Line is picked by the aluminium layers of a conductor with aluminium
  // outer wires; an earth wire of steel or aluminium-clad steel may have none.
  require_in_range("aluminium_layers", aluminium_layers, safe_border_line_applies() ? 1 : 0, 10);
}

void check_tension(const Conductor& conductor, double tension, const std::string& field) {
  require_positive(field, tension, "N");
  if (!(tension < conductor.rated_tensile_strength)) {
    throw_invalid(field, tension,
                  fmt::format("less than the rated tensile strength = {} N", format_value(conductor.rated_tensile_strength)));
  }
}

double tension_from_fraction(const Conductor& conductor, double fraction, const std::string& field) {
  if (!(fraction > 0.0 && fraction < 1.0)) {
    const std::string percent = fraction >= 2.0 && fraction < 100.0
                                    ? fmt::format(" (a percentage? {} % is {:.6g})", format_value(fraction),
                                                  fraction / 100.0)
                                    : "";
    throw_invalid(field, fraction, "a fraction of the rated tensile strength > 0 and < 1" + percent);
  }
  return fraction * conductor.rated_tensile_strength;
}

double tension_from_catenary_parameter(const Conductor& conductor, double catenary_parameter,
                                       const std::string& field) {
  require_plausible(field, catenary_parameter, "m");
  const double weight = conductor.mass_per_length * standard_gravity;  // N/m
  const double tension = catenary_parameter * weight;
  // (A conductor not valid yet is Conductor::validate's to report.)
  if (weight > 0.0 && conductor.rated_tensile_strength > 0.0 && !(tension < conductor.rated_tensile_strength)) {
    throw_invalid(field, catenary_parameter,
                  fmt::format("less than the rated tensile strength per weight, {:.6g} m (T = (H/w) m g = {:.6g} N)",
                              conductor.rated_tensile_strength / weight, tension));
  }
  return tension;
}

double catenary_parameter(const Conductor& conductor, double tension) {
  return tension / (conductor.mass_per_length * standard_gravity);
}

double wave_speed(const Conductor& conductor, double tension) {
  return std::sqrt(tension / conductor.mass_per_length);
}

double wavenumber(const Conductor& conductor, double tension, double frequency) {
  return 2.0 * std::numbers::pi * frequency / wave_speed(conductor, tension);
}

double wavelength(const Conductor& conductor, double tension, double frequency) {
  return wave_speed(conductor, tension) / frequency;
}

double wave_impedance(const Conductor& conductor, double tension) {
  return std::sqrt(tension * conductor.mass_per_length);
}

double bending_decay(const Conductor& conductor, double tension) { return std::sqrt(tension / conductor.ei_min); }

double lilien_k(const Conductor& conductor) {
  const double diameter_mm = 1e3 * conductor.diameter;
  const double rts_kn = 1e-3 * conductor.rated_tensile_strength;
  return diameter_mm / std::sqrt(conductor.mass_per_length * rts_kn);
}

BeamWavenumbers beam_wavenumbers(const Conductor& conductor, double tension, double frequency) {
  const double w = 2.0 * std::numbers::pi * frequency;
  const double ei = conductor.ei_min;
  const double mw2 = conductor.mass_per_length * w * w;
  const double root = std::sqrt(tension * tension + 4.0 * ei * mw2);
  // k1^2 = (root - T) / (2 EI) written without the cancellation of a small EI.
  return {std::sqrt(2.0 * mw2 / (root + tension)), std::sqrt((root + tension) / (2.0 * ei))};
}

}  // namespace stockbridge::span
