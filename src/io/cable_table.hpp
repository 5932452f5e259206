#pragma once
// The [cable] table, shared by cable files and the [arm.cable] tables of damper files.

#include "stockbridge/cable/cable_description.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

/// Reads every key of a cable table, rejecting unknown ones; the values are the
/// model's to validate (cable::Cable, inside build_from_file).
cable::CableDescription read_cable_table(const TomlTable& table);

}  // namespace stockbridge::io
