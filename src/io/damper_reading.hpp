#pragma once
// A damper file's document built into its damper, for readers that hold a damper
// inside a file of their own (the fits' cache). Library-internal.

#include <filesystem>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

/// The damper a damper file's tables (`document`) describe, as load_damper_file
/// builds it: messages located in `source`, cable files relative to `base_directory`.
DamperFile build_damper(const toml::table& document, const TomlSource& source, const std::filesystem::path& base_directory,
                        SlipPolicy policy);

}  // namespace stockbridge::io
