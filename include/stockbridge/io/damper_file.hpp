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

#include <filesystem>
#include <string_view>

#include "stockbridge/damper/damper.hpp"

namespace stockbridge::io {

/// Reads a damper file and builds the (validated) damper; InputError with file,
/// line, key, value and expectation.
damper::Damper read_damper_file(const std::filesystem::path& path);
/// The same from TOML text a front end built from its own values (Python's
/// make_damper): the same keys, checks and messages, naming `source`, no lines.
damper::Damper read_damper_text(std::string_view text, std::string_view source);

}  // namespace stockbridge::io
