#pragma once
// Reading cable description files (TOML, format in docs/file-formats.md):
//
//   [cable]
//   length = 0.3        # m
//   sections = 40       # integration points along the cable
//   ei = 2.8            # N m^2, or a profile { s = [...], value = [...] }
//   jenkin = [ { c = 20.0, h = 0.7 } ]   # N m^2 and N m; each may be a profile; k0 optional
//   mirror_length = 0.3 # optional: mirror method from a cable of this length
//   lever_arm_cap = 0.3 # optional: modified Masing model's cap of |M|/|F|, m

#include <filesystem>

#include "stockbridge/cable/cable_description.hpp"

namespace stockbridge::io {

/// Reads and validates a cable file. Throws InputError with one line naming the
/// file, line, key, value and what was expected.
cable::CableDescription read_cable_file(const std::filesystem::path& path);

}  // namespace stockbridge::io
