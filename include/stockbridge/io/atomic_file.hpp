#pragma once
// Output files appear whole or not at all: the text goes to a temporary file in
// the target's directory, which is then renamed over the target.

#include <filesystem>
#include <string_view>

namespace stockbridge::io {

/// Writes `contents` to `path` atomically. Throws OutputError naming the path.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace stockbridge::io
