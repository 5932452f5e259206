#pragma once
// The request layer for the conductor catalogue (`stockbridge conductors`, Python's
// conductor() and conductors()): what both front ends show of a conductor.

#include <string>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/span/stranded_conductor.hpp"

namespace stockbridge::requests {

/// One conductor: {"type", "stranding", "source", then the [conductor] table's values
/// with units: "mass_per_length_kg_m", "diameter_m", "rated_tensile_strength_n",
/// "ei_min_n_m2", "ei_max_n_m2", "outer_wire_diameter_m", "outer_wire_modulus_pa",
/// "aluminium_layers", "outer_wire_material"} (ei_min and the rest derived from the
/// stranding).
io::JsonObject conductor_summary(const span::StrandedConductor& conductor);
/// The [conductor] table's values with units, as conductor_summary names them (the
/// span JSON's inputs restate the conductor as used with them).
void add_conductor_figures(io::JsonObject& json, const span::Conductor& conductor);

/// {"conductors": [conductor_summary of each]}.
io::JsonObject conductors_summary(const std::vector<span::StrandedConductor>& conductors);

/// The text table of the catalogue: one row per conductor (type, stranding, D in mm,
/// m in kg/m, RTS in kN, EI_min and EI_max in N m^2, the outer wires' material) under
/// a header row.
std::string conductor_list_text(const std::vector<span::StrandedConductor>& conductors);

/// The span file's [conductor] table of this conductor, every key written out (the
/// derived ones to full precision, so that pasting it gives the numbers of
/// `type = "<type>"`), with comments naming units and sources; TOML text.
std::string conductor_table_toml(const span::StrandedConductor& conductor);

}  // namespace stockbridge::requests
