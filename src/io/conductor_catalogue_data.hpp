#pragma once
// The conductor catalogue's files as compiled into the library (private): CMake
// writes their text into a generated source (src/CMakeLists.txt, from
// data/conductors/*.toml and conductor_catalogue_data.cpp.in).

#include <span>
#include <string_view>

namespace stockbridge::io {

struct EmbeddedConductorFile {
  std::string_view name;  ///< the file's name, e.g. "acsr_drake.toml"
  std::string_view text;  ///< its contents
};

/// Every catalogue file, in the order of their names.
std::span<const EmbeddedConductorFile> embedded_conductor_files();

}  // namespace stockbridge::io
