#include "stockbridge/span/conductor.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

void Conductor::validate() const {
  require_plausible("mass_per_length", mass_per_length, "kg/m");
  require_plausible("diameter", diameter, "m");
  require_plausible("rated_tensile_strength", rated_tensile_strength, "N");
  require_plausible("ei_min", ei_min, "N m^2");
  require_plausible_or_zero("ei_max", ei_max, "N m^2");
  if (ei_max != 0.0 && ei_max < ei_min) {
    throw_invalid("ei_max", ei_max, fmt::format("0 (not given) or at least ei_min = {} N m^2", format_value(ei_min)));
  }
  require_plausible("outer_wire_diameter", outer_wire_diameter, "m");
  if (!(outer_wire_diameter < diameter)) {
    throw_invalid("outer_wire_diameter", outer_wire_diameter,
                  fmt::format("less than the conductor's diameter = {} m", format_value(diameter)));
  }
  require_plausible("outer_wire_modulus", outer_wire_modulus, "Pa");
  require_in_range("aluminium_layers", aluminium_layers, 1, 10);
}

void check_tension(const Conductor& conductor, double tension, const std::string& field) {
  require_positive(field, tension, "N");
  if (!(tension < conductor.rated_tensile_strength)) {
    throw_invalid(field, tension,
                  fmt::format("less than the rated tensile strength = {} N", format_value(conductor.rated_tensile_strength)));
  }
}

double tension_from_fraction(const Conductor& conductor, double fraction, const std::string& field) {
  if (!(fraction > 0.0 && fraction < 1.0)) throw_invalid(field, fraction, "a fraction of the rated tensile strength > 0 and < 1");
  return fraction * conductor.rated_tensile_strength;
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
