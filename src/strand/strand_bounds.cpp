#include "stockbridge/strand/strand_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::strand {

namespace {

/// Second moment of area of a circular wire about its own axis, pi r^4 / 4, m^4.
double wire_inertia(double radius) { return std::numbers::pi * std::pow(radius, 4) / 4.0; }

/// cos alpha = 1 / sqrt(1 + tan^2 alpha), tan alpha = 2 pi R / lambda.
double cos_lay_angle(const StrandLayer& layer) {
  return 1.0 / std::hypot(1.0, 2.0 * std::numbers::pi * layer.pitch_radius / layer.lay_length);
}

}  // namespace

double core_modulus(const Strand& strand) { return strand.core_youngs_modulus.value_or(strand.youngs_modulus); }

double layer_modulus(const Strand& strand, const StrandLayer& layer) {
  return layer.youngs_modulus.value_or(strand.youngs_modulus);
}

bool single_modulus(const Strand& strand) {
  const double e = core_modulus(strand);
  return std::all_of(strand.layers.begin(), strand.layers.end(),
                     [&](const StrandLayer& layer) { return layer_modulus(strand, layer) == e; });
}

double lay_angle(const StrandLayer& layer) {
  return std::atan(2.0 * std::numbers::pi * layer.pitch_radius / layer.lay_length);
}

void check_layer_position(const StrandLayer& layer, double inner_radius, std::string_view name) {
  constexpr double slack = 1.02;  // hand-rounded data: 2 %
  const double r = layer.wire_radius, R = layer.pitch_radius;
  const std::string field = fmt::format("{}.pitch_radius", name);
  if (R * slack < inner_radius + r) {
    throw_invalid(field, R,
                  fmt::format("at least {} m, the radius the wires rest on ({} m) plus their radius ({} m)",
                              format_value(inner_radius + r), format_value(inner_radius), format_value(r)));
  }
  if (layer.count * std::asin(std::min(1.0, r / R)) > std::numbers::pi * slack) {
    throw_invalid(field, R,
                  fmt::format("room for {} wires of radius {} m side by side around the strand (at least {} m)",
                              layer.count, format_value(r), format_value(r / std::sin(std::numbers::pi / std::max(layer.count, 2)))));
  }
}

void check_lay_angle(const StrandLayer& layer, std::string_view name) {
  const double shortest = 2.0 * std::numbers::pi * layer.pitch_radius;
  if (!(layer.lay_length > shortest)) {
    throw_invalid(fmt::format("{}.lay_length", name), layer.lay_length,
                  fmt::format("more than 2 pi pitch_radius = {} m (a lay angle below 45 degrees)", format_value(shortest)));
  }
}

void validate(const Strand& strand) {
  require_positive("youngs_modulus", strand.youngs_modulus, "Pa");
  require_positive("core_radius", strand.core_radius, "m");
  if (strand.core_youngs_modulus) require_positive("core_youngs_modulus", *strand.core_youngs_modulus, "Pa");
  for (std::size_t j = 0; j < strand.layers.size(); ++j) {
    const StrandLayer& layer = strand.layers[j];
    require_in_range(fmt::format("layer[{}].count", j), layer.count, 1, 1000);
    if (layer.youngs_modulus) require_positive(fmt::format("layer[{}].youngs_modulus", j), *layer.youngs_modulus, "Pa");
    require_positive(fmt::format("layer[{}].wire_radius", j), layer.wire_radius, "m");
    require_positive(fmt::format("layer[{}].pitch_radius", j), layer.pitch_radius, "m");
    require_positive(fmt::format("layer[{}].lay_length", j), layer.lay_length, "m");
  }
  double inner_radius = strand.core_radius;
  for (std::size_t j = 0; j < strand.layers.size(); ++j) {
    const StrandLayer& layer = strand.layers[j];
    check_layer_position(layer, inner_radius, fmt::format("layer[{}]", j));
    check_lay_angle(layer, fmt::format("layer[{}]", j));
    inner_radius = layer.pitch_radius + layer.wire_radius;
  }
}

StrandBounds strand_bounds(const Strand& strand) {
  validate(strand);
  // Sums of second moments of area, m^4, each weighted by its wires' modulus relative
  // to the strand's (exactly 1 for a wire without a modulus of its own, so that a strand
  // of one material gives the same numbers, to the last bit, as before moduli per
  // layer); the strand's E multiplies once at the end.
  const double e = strand.youngs_modulus;
  const double core = core_modulus(strand) / e * wire_inertia(strand.core_radius);
  double free_wires = core;   // (A.4), (A.5)
  double no_slip = core;      // (A.1) without B_ij
  for (const StrandLayer& layer : strand.layers) {
    const double n = layer_modulus(strand, layer) / e * layer.count;
    const double r = layer.wire_radius;
    const double R = layer.pitch_radius;
    free_wires += n * wire_inertia(r);
    // N/2 pi r^2 (r^2/2 + R^2) = N (pi r^4/4 + pi r^2 R^2 / 2): each wire about its own
    // axis plus Steiner's term averaged over the wire's turn around the strand axis.
    no_slip += n / 2.0 * std::numbers::pi * r * r * (r * r / 2.0 + R * R) * std::pow(cos_lay_angle(layer), 3);
  }
  const StrandBounds bounds{e * free_wires, e * no_slip};
  // Absurd sizes leave a double's range: r^4 overflows, or underflows to zero or to
  // subnormals whose few digits no longer keep ei_min <= ei_max.
  if (!std::isnormal(bounds.ei_min) || !std::isnormal(bounds.ei_max)) {
    throw NumericalError(fmt::format("strand bending stiffness outside a double's range (ei_min = {}, ei_max = {} N m^2)",
                                     format_value(bounds.ei_min), format_value(bounds.ei_max)));
  }
  return bounds;
}

}  // namespace stockbridge::strand
