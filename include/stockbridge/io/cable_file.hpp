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
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/cable/cable.hpp"
#include "stockbridge/core/typical_ranges.hpp"

namespace stockbridge::io {

/// A cable file as read: the cable, and a warning line for each value outside the
/// typical ranges ("<file>:<line>: cable.ei = 4.9e+06: outside the typical ..."),
/// but for one a unit slip explains, which `policy` refuses (UnusualValueError) or warns
/// of (typical_ranges.hpp).
struct CableFile {
  cable::Cable cable;
  std::vector<std::string> warnings;
};

/// Reads a cable file and builds the (validated, discretised) cable. Throws
/// InputError with one line naming the file, line, key, value and what was expected.
CableFile load_cable_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);
/// load_cable_file's cable alone.
cable::Cable read_cable_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);
/// The same from TOML text a front end built from its own values (Python's
/// make_cable): the same keys, checks and messages, naming `source`, no lines.
CableFile load_cable_text(std::string_view text, std::string_view source, SlipPolicy policy = SlipPolicy::refuse);
cable::Cable read_cable_text(std::string_view text, std::string_view source, SlipPolicy policy = SlipPolicy::refuse);

/// The keys of a [cable] table for `description` (what cable and damper files accept).
std::string cable_table_toml(const cable::CableDescription& description);
/// A whole cable file: `comment` (each line as a TOML comment), then [cable].
std::string cable_file_toml(const cable::CableDescription& description, std::string_view comment);

}  // namespace stockbridge::io
