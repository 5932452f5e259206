#include "stockbridge/span/stranded_conductor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

// Names in this unnamed namespace are unique across the library (the sanitizer
// presets compile it in unity batches).

constexpr double kStrandingSlack = 1.02;  // hand-rounded data: 2 %, as strand::check_layer_position

std::string layer_field(std::size_t j, std::string_view key) { return fmt::format("layer[{}].{}", j, key); }

int count_aluminium_layers(const StrandedConductor& conductor) {
  return static_cast<int>(std::count_if(conductor.layers.begin(), conductor.layers.end(),
                                         [](const ConductorLayer& layer) { return is_aluminium(layer.material); }));
}

/// A length the stranding's geometry gives, for messages: 6 digits, without the
/// round-off of the sums (0.0045, not 0.0045000000000000005).
std::string stranding_length(double metres) { return fmt::format("{:.6g}", metres); }

/// A number in mm for labels: "3.45", "4.442" (no trailing zeros).
std::string stranding_mm(double metres) { return fmt::format("{:.4g}", metres * 1e3); }

}  // namespace

std::vector<double> pitch_radii(const StrandedConductor& conductor) {
  std::vector<double> radii;
  double below = conductor.core.wire_diameter / 2.0;  // the outer radius of what the layer rests on
  for (const ConductorLayer& layer : conductor.layers) {
    radii.push_back(below + layer.wire_diameter / 2.0);
    below = radii.back() + layer.wire_diameter / 2.0;
  }
  return radii;
}

double stranding_diameter(const StrandedConductor& conductor) {
  if (conductor.layers.empty()) return conductor.core.wire_diameter;
  return 2.0 * pitch_radii(conductor).back() + conductor.layers.back().wire_diameter;
}

double lay_length(const StrandedConductor& conductor, std::size_t layer) {
  const ConductorLayer& l = conductor.layers.at(layer);
  if (l.lay_length > 0.0) return l.lay_length;
  return l.lay_ratio * (2.0 * pitch_radii(conductor)[layer] + l.wire_diameter);
}

void StrandedConductor::validate() const {
  if (type.empty()) throw InvalidParameter("type", " = \"\": expected a name (e.g. \"ACSR Drake\")");
  require_plausible("mass_per_length", mass_per_length, "kg/m");
  require_plausible("diameter", diameter, "m");
  require_plausible("rated_tensile_strength", rated_tensile_strength, "N");
  require_plausible("core.youngs_modulus", core.youngs_modulus, "Pa");
  require_plausible("core.wire_diameter", core.wire_diameter, "m");
  if (layers.empty()) throw InvalidParameter("layer", ": none: expected the layers of wires around the core, from the inside out");
  for (std::size_t j = 0; j < layers.size(); ++j) {
    const ConductorLayer& layer = layers[j];
    require_in_range(layer_field(j, "count"), layer.count, 1, 1000);
    require_plausible(layer_field(j, "youngs_modulus"), layer.youngs_modulus, "Pa");
    require_plausible(layer_field(j, "wire_diameter"), layer.wire_diameter, "m");
    require_plausible_or_zero(layer_field(j, "lay_length"), layer.lay_length, "m");
    require_plausible_or_zero(layer_field(j, "lay_ratio"), layer.lay_ratio, "");
    if ((layer.lay_length > 0.0) == (layer.lay_ratio > 0.0)) {
      throw InvalidParameter(layer_field(j, "lay_length"),
                             fmt::format(" = {} with lay_ratio = {}: expected one of the two (the other 0)",
                                         format_value(layer.lay_length), format_value(layer.lay_ratio)));
    }
  }
  const std::vector<double> radii = pitch_radii(*this);
  for (std::size_t j = 0; j < layers.size(); ++j) {
    const ConductorLayer& layer = layers[j];
    const double r = layer.wire_diameter / 2.0;
    const double R = radii[j];
    const double per_wire = std::asin(std::min(1.0, r / R));  // half the angle a wire takes around the axis
    if (layer.count * per_wire > std::numbers::pi * kStrandingSlack) {
      throw InvalidParameter(
          layer_field(j, "count"),
          fmt::format(" = {}: expected at most {} wires of {} m side by side around the layer beneath (pitch radius {} m)",
                      layer.count, static_cast<int>(std::floor(std::numbers::pi * kStrandingSlack / per_wire)),
                      format_value(layer.wire_diameter), stranding_length(R)));
    }
    const double outer = 2.0 * R + layer.wire_diameter;
    const double shortest = 2.0 * std::numbers::pi * R;  // lay angle 45 degrees
    if (layer.lay_length > 0.0 && !(layer.lay_length > shortest)) {
      throw_invalid(layer_field(j, "lay_length"), layer.lay_length,
                    fmt::format("more than 2 pi R = {} m, R = {} m the layer's pitch radius (a lay angle below 45 degrees)",
                                stranding_length(shortest), stranding_length(R)));
    }
    if (layer.lay_ratio > 0.0 && !(layer.lay_ratio * outer > shortest)) {
      throw_invalid(layer_field(j, "lay_ratio"), layer.lay_ratio,
                    fmt::format("more than 2 pi R / D = {}, R = {} m the layer's pitch radius and D = {} m its outer "
                                "diameter (a lay angle below 45 degrees)",
                                stranding_length(shortest / outer), stranding_length(R), stranding_length(outer)));
    }
  }
  const double stranded = stranding_diameter(*this);
  if (std::abs(diameter - stranded) > (kStrandingSlack - 1.0) * stranded) {
    throw_invalid("diameter", diameter,
                  fmt::format("the stranding's outer diameter, {} m, within 2 % (the wires' count or diameter wrong?)",
                              stranding_length(stranded)));
  }
  const int aluminium = count_aluminium_layers(*this);
  if (aluminium > 10) {
    throw InvalidParameter("layer", fmt::format(": {} layers of aluminium or aluminium-alloy wires: expected at most 10 "
                                                "(the Safe Border Line is chosen by their number)",
                                                aluminium));
  }
}

strand::Strand strand_of(const StrandedConductor& conductor) {
  conductor.validate();
  strand::Strand strand;
  strand.core_radius = conductor.core.wire_diameter / 2.0;
  strand.youngs_modulus = conductor.core.youngs_modulus;
  const std::vector<double> radii = pitch_radii(conductor);
  for (std::size_t j = 0; j < conductor.layers.size(); ++j) {
    const ConductorLayer& layer = conductor.layers[j];
    strand.layers.push_back(strand::StrandLayer{layer.count, layer.wire_diameter / 2.0, radii[j],
                                                lay_length(conductor, j), layer.youngs_modulus});
  }
  return strand;
}

Conductor conductor_of(const StrandedConductor& conductor) {
  const strand::StrandBounds bounds = strand::strand_bounds(strand_of(conductor));
  Conductor c;
  c.name = conductor.type;
  c.mass_per_length = conductor.mass_per_length;
  c.diameter = conductor.diameter;
  c.rated_tensile_strength = conductor.rated_tensile_strength;
  c.ei_min = bounds.ei_min;
  c.ei_max = bounds.ei_max;
  c.outer_wire_diameter = conductor.layers.back().wire_diameter;
  c.outer_wire_modulus = conductor.layers.back().youngs_modulus;
  c.outer_wire_material = conductor.layers.back().material;
  c.aluminium_layers = count_aluminium_layers(conductor);
  c.stranding = stranding_label(conductor);
  return c;
}

std::string stranding_label(const StrandedConductor& conductor) {
  int aluminium_wires = 0;
  int steel_wires = 0;
  std::vector<const ConductorLayer*> wires{&conductor.core};
  for (const ConductorLayer& layer : conductor.layers) wires.push_back(&layer);
  for (const ConductorLayer* layer : wires) (is_aluminium(layer->material) ? aluminium_wires : steel_wires) += layer->count;
  std::string label = steel_wires == 0 || aluminium_wires == 0 ? fmt::format("{}", aluminium_wires + steel_wires)
                                                               : fmt::format("{}/{}", aluminium_wires, steel_wires);
  // Runs of layers of one material and wire diameter: "steel 1+6 x 3.45 mm".
  std::string runs;
  for (std::size_t i = 0; i < wires.size(); ++i) {
    const bool continues = i > 0 && wires[i]->material == wires[i - 1]->material &&
                           wires[i]->wire_diameter == wires[i - 1]->wire_diameter;
    if (continues) {
      runs += fmt::format("+{}", wires[i]->count);
      continue;
    }
    if (i > 0) runs += fmt::format(" x {} mm, ", stranding_mm(wires[i - 1]->wire_diameter));
    runs += fmt::format("{} {}", wire_material_name(wires[i]->material), wires[i]->count);
  }
  runs += fmt::format(" x {} mm", stranding_mm(wires.back()->wire_diameter));
  return label + ": " + runs;
}

}  // namespace stockbridge::span
