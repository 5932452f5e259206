#pragma once
// Conductor files (TOML, SI units): a conductor by its data sheet and its
// stranding (span::StrandedConductor), and the catalogue of them the library
// ships (data/conductors/*.toml, compiled in). A span file selects one with
// [conductor] type = "ACSR Drake" (the catalogue) or file = "my.toml" (a file).
//
//     [conductor]
//     type = "ACSR Drake"              # the name the catalogue knows it by
//     source = "ASTM B232 ..."         # optional: where the values come from
//     mass_per_length = 1.628          # kg/m
//     diameter = 0.02814               # m (within 2 % of the stranding's)
//     rated_tensile_strength = 138800  # N
//
//     [conductor.core]                 # the core wire
//     material = "steel"               # steel | aluminium | aluminium-alloy
//     youngs_modulus = 207e9           # Pa
//     wire_diameter = 0.00345          # m
//
//     [[conductor.layer]]              # one per layer, from the inside out, touching
//     material = "steel"
//     youngs_modulus = 207e9           # Pa
//     count = 6                        # wires, integer 1..1000
//     wire_diameter = 0.00345          # m
//     lay_ratio = 21                   # lay length / the layer's outer diameter; or lay_length = m
//
// The format is described in docs/file-formats.md (Conductor file).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/span/stranded_conductor.hpp"

namespace stockbridge::io {

/// Reads and validates a conductor file. Throws InputError "<file>:<line>: <key> ...:
/// expected ..." on a missing file, a syntax error, a missing, unknown or mistyped
/// key, or a value the model refuses (keys named as in the file, e.g.
/// "conductor.layer[1].lay_ratio").
span::StrandedConductor read_conductor_file(const std::filesystem::path& path);

/// The shipped catalogue (data/conductors/*.toml, read once), in the order of its files.
const std::vector<span::StrandedConductor>& conductor_catalogue();

/// Whether `query` names the conductor of `type`: equal once case, spaces, hyphens and
/// underscores are ignored, with or without the type's first word ("acsr-drake",
/// "ACSR_DRAKE" and "Drake" name "ACSR Drake").
bool conductor_type_matches(std::string_view query, std::string_view type);

/// The catalogue's conductor that `query` names (conductor_type_matches); throws
/// InvalidParameter naming "type", with the catalogue's types, when none does.
const span::StrandedConductor& catalogue_conductor(std::string_view query);

}  // namespace stockbridge::io
