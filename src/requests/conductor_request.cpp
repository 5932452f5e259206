#include "stockbridge/requests/conductor_request.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/toml_text.hpp"

namespace stockbridge::requests {

namespace {

/// `key = value` padded so that the comments line up.
std::string toml_line(const std::string& assignment, const std::string& comment) {
  return fmt::format("{:<40} # {}\n", assignment, comment);
}

}  // namespace

void add_conductor_figures(io::JsonObject& json, const span::Conductor& c) {
  json.add("mass_per_length_kg_m", c.mass_per_length)
      .add("diameter_m", c.diameter)
      .add("rated_tensile_strength_n", c.rated_tensile_strength)
      .add("ei_min_n_m2", c.ei_min)
      .add("ei_max_n_m2", c.ei_max)
      .add("outer_wire_diameter_m", c.outer_wire_diameter)
      .add("outer_wire_modulus_pa", c.outer_wire_modulus)
      .add("aluminium_layers", c.aluminium_layers);
}

io::JsonObject conductor_summary(const span::StrandedConductor& conductor) {
  io::JsonObject json;
  json.add("type", conductor.type).add("stranding", span::stranding_label(conductor)).add("source", conductor.source);
  const span::Conductor c = span::conductor_of(conductor);
  add_conductor_figures(json, c);
  json.add("outer_wire_material", std::string(span::wire_material_name(c.outer_wire_material)));
  return json;
}

io::JsonObject conductors_summary(const std::vector<span::StrandedConductor>& conductors) {
  std::vector<io::JsonObject> entries;
  for (const span::StrandedConductor& conductor : conductors) entries.push_back(conductor_summary(conductor));
  return io::JsonObject().add("conductors", entries);
}

std::string conductor_list_text(const std::vector<span::StrandedConductor>& conductors) {
  std::size_t type_width = 4;
  std::size_t stranding_width = 9;
  for (const span::StrandedConductor& conductor : conductors) {
    type_width = std::max(type_width, conductor.type.size());
    stranding_width = std::max(stranding_width, span::stranding_label(conductor).size());
  }
  std::string text = fmt::format("{:<{}}  {:<{}}  {:>6}  {:>6}  {:>6}  {:>8}  {:>8}  {}\n", "type", type_width, "stranding",
                                 stranding_width, "D mm", "m kg/m", "RTS kN", "EI_min", "EI_max", "outer wires");
  for (const span::StrandedConductor& conductor : conductors) {
    const span::Conductor c = span::conductor_of(conductor);
    text += fmt::format("{:<{}}  {:<{}}  {:>6.2f}  {:>6.3f}  {:>6.1f}  {:>8.2f}  {:>8.0f}  {}\n", conductor.type, type_width,
                        span::stranding_label(conductor), stranding_width, c.diameter * 1e3, c.mass_per_length,
                        c.rated_tensile_strength * 1e-3, c.ei_min, c.ei_max, span::wire_material_name(c.outer_wire_material));
  }
  return text + "(EI_min, EI_max in N m^2, derived from the stranding; the Safe Border Line judges only outer wires of "
                "aluminium or aluminium-alloy, the others need [fatigue] endurance_limit_mpa; stockbridge conductors "
                "TYPE prints one as a span file's [conductor] table)\n";
}

std::string conductor_table_toml(const span::StrandedConductor& conductor) {
  const span::Conductor c = span::conductor_of(conductor);
  std::string text = fmt::format("# {}, {}\n", conductor.type, span::stranding_label(conductor));
  if (!conductor.source.empty()) text += fmt::format("# Source: {}\n", conductor.source);
  text += "# ei_min, ei_max, outer_wire_diameter, outer_wire_modulus, outer_wire_material and aluminium_layers\n"
          "# are derived from the stranding (docs/strand.md); the same as [conductor] type = " +
          io::toml_basic_string(conductor.type) + ".\n";
  text += "[conductor]\n";
  text += fmt::format("name = {}\n", io::toml_basic_string(c.name));
  text += toml_line(fmt::format("mass_per_length = {}", format_value(c.mass_per_length)), "kg/m");
  text += toml_line(fmt::format("diameter = {}", format_value(c.diameter)), "m");
  text += toml_line(fmt::format("rated_tensile_strength = {}", format_value(c.rated_tensile_strength)), "N");
  text += toml_line(fmt::format("ei_min = {}", format_value(c.ei_min)), "N m^2, the free wires");
  text += toml_line(fmt::format("ei_max = {}", format_value(c.ei_max)), "N m^2, no slip");
  text += toml_line(fmt::format("outer_wire_diameter = {}", format_value(c.outer_wire_diameter)), "m");
  text += toml_line(fmt::format("outer_wire_modulus = {}", format_value(c.outer_wire_modulus)), "Pa");
  text += toml_line(fmt::format("outer_wire_material = \"{}\"", span::wire_material_name(c.outer_wire_material)),
                    c.safe_border_line_applies() ? "the Safe Border Line judges these"
                                                 : "no Safe Border Line: give [fatigue] endurance_limit_mpa");
  text += toml_line(fmt::format("aluminium_layers = {}", c.aluminium_layers),
                    c.safe_border_line_applies() ? "picks the Safe Border Line" : "none needed");
  return text;
}

}  // namespace stockbridge::requests
