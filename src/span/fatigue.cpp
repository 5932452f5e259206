#include "stockbridge/span/fatigue.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {
constexpr double fatigue_pa_per_mpa = 1e6;
}  // namespace

double fymax_stress(const Conductor& c, double frequency, double loop_amplitude) {
  return std::numbers::pi * c.outer_wire_diameter * c.outer_wire_modulus * std::sqrt(c.mass_per_length / c.ei_min) *
         frequency * loop_amplitude;
}

double poffenberger_swart_factor(const Conductor& c, double tension, double x_b) {
  const double p = bending_decay(c, tension);
  const double px = p * x_b;
  const double shape = std::expm1(-px) + px;  // exp(-px) - 1 + px, accurate for a small px too
  return c.outer_wire_modulus * c.outer_wire_diameter * p * p / (4.0 * shape);
}

double bending_amplitude(const Conductor& c, double tension, double frequency, double loop_amplitude, double x_b) {
  const BeamWavenumbers w = beam_wavenumbers(c, tension, frequency);
  const double k = w.travelling;
  const double r = k / w.decaying;
  const double y = loop_amplitude * (std::sin(k * x_b) - r * std::cos(k * x_b) + r * std::exp(-w.decaying * x_b)) /
                   std::sqrt(1.0 + r * r);
  return 2.0 * y;
}

double poffenberger_swart_stress(const Conductor& c, double tension, double bending_amplitude, double x_b) {
  return poffenberger_swart_factor(c, tension, x_b) * bending_amplitude;
}

double point_force_stress(const Conductor& c, double tension, double force_amplitude) {
  return c.outer_wire_modulus * c.outer_wire_diameter * std::abs(force_amplitude) /
         (4.0 * bending_decay(c, tension) * c.ei_min);
}

double bending_strain_pp_microstrain(const Conductor& c, double stress) {
  return 2.0 * stress / c.outer_wire_modulus * 1e6;
}

double SafeBorderLine::endurance_limit(double cycles) const {
  const double mpa = cycles <= knee ? a_low * std::pow(cycles, b_low) : a_high * std::pow(cycles, b_high);
  return fatigue_pa_per_mpa * mpa;
}

double SafeBorderLine::cycles_to_failure(double stress) const {
  if (!(stress > 0.0)) return std::numeric_limits<double>::infinity();
  const double mpa = stress / fatigue_pa_per_mpa;
  if (mpa > a_low * std::pow(knee, b_low)) return std::pow(mpa / a_low, 1.0 / b_low);
  if (mpa < a_high * std::pow(knee, b_high)) return std::pow(mpa / a_high, 1.0 / b_high);
  return knee;  // inside the step at the knee
}

SafeBorderLine safe_border_line(int aluminium_layers) {
  require_in_range("aluminium_layers", aluminium_layers, 1, 1000);
  if (aluminium_layers == 1) return {730.0, -0.2, 2e7, 430.0, -0.17};
  return {450.0, -0.2, 1.56e7, 263.0, -0.17};
}

}  // namespace stockbridge::span
