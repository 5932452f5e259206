#pragma once
// Strand description files (TOML, SI units), read into a strand::Strand.
//
//     [strand]
//     youngs_modulus = 210e9   # Pa, optional (default 210e9, steel)
//     core_radius = 0.001      # m
//     core_youngs_modulus = 207e9  # Pa, optional (default: youngs_modulus)
//
//     [[strand.layer]]         # one per layer, from the inside out; none for a single wire
//     count = 6                # wires in the layer, integer 1..1000
//     wire_radius = 0.001      # m
//     pitch_radius = 0.002     # m, strand axis to wire axis
//     lay_length = 0.06        # m, axial length of one turn
//     youngs_modulus = 68.9e9  # Pa, optional (default: the strand's youngs_modulus)
//
// The format is described in docs/strand.md.

#include <filesystem>

#include "stockbridge/strand/strand_bounds.hpp"

namespace stockbridge::io {

/// Reads and validates a strand file. Throws InputError "<file>:<line>: <key> ...:
/// expected ..." on a missing file, a syntax error, a missing, unknown or mistyped
/// key, or a value out of range (keys are named as in the file, e.g.
/// "strand.layer[1].lay_length").
strand::Strand read_strand_file(const std::filesystem::path& path);

}  // namespace stockbridge::io
