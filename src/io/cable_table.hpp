#pragma once
// The [cable] table, shared by cable files and the [arm.cable] tables of damper files.

#include <string>
#include <string_view>

#include "stockbridge/cable/cable_description.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

/// Reads every key of a cable table, rejecting unknown ones; the values are the
/// model's to validate (cable::Cable, inside build_from_file).
cable::CableDescription read_cable_table(const TomlTable& table);

/// Every line of `comment` as a TOML comment line ("# ...\n"), for the files the
/// program writes (cable and damper files).
std::string toml_comment_lines(std::string_view comment);

}  // namespace stockbridge::io
