#pragma once
// Reading damper description files (TOML, format in docs/file-formats.md):
//
//   [clamp]
//   mass = 0.7            # kg
//   [[arm]]
//   name = "long"
//   mass = 0.856          # kg
//   inertia = 0.001814    # kg m^2 about the centre of gravity
//   offset = 0.0325       # m, cable tip to centre of gravity, toward the clamp
//   [arm.cable]           # the keys of a cable file's [cable] table
//   length = 0.1875
//   ...
//
// or, for a cable identified once and cut to each arm's length, a reference to a
// cable file (relative to the damper file) with optional overrides:
//
//   [arm.cable]
//   file = "cable.toml"
//   length = 0.15         # also: sections, mirror_length, lever_arm_cap

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/damper/damper.hpp"

namespace stockbridge::io {

/// A damper file as read: the damper, the cable files its arms reference (inputs a
/// command must not overwrite), and a warning line for each value outside the
/// typical ranges, located in the file that holds it (but for one a unit slip
/// explains, which `policy` refuses: UnusualValueError, typical_ranges.hpp).
struct DamperFile {
  damper::Damper damper;
  std::vector<std::filesystem::path> cable_files;
  std::vector<std::string> warnings;
};

/// Reads a damper file and builds the (validated) damper; InputError with file,
/// line, key, value and expectation.
DamperFile load_damper_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);
/// load_damper_file's damper alone.
damper::Damper read_damper_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);
/// The same from TOML text a front end built from its own values (Python's
/// make_damper): the same keys, checks and messages, naming `source`, no lines;
/// referenced cable files are relative to the working directory.
DamperFile load_damper_text(std::string_view text, std::string_view source, SlipPolicy policy = SlipPolicy::refuse);
damper::Damper read_damper_text(std::string_view text, std::string_view source, SlipPolicy policy = SlipPolicy::refuse);

/// A whole damper file for `description`, every arm's cable written out in full (no
/// references): `comment` first (each line as a TOML comment). Numbers are written
/// so that they read back exactly.
std::string damper_file_toml(const damper::DamperDescription& description, std::string_view comment);

}  // namespace stockbridge::io
