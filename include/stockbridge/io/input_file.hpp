#pragma once
// The files an input names, found before they are read: one check and one message
// for the readers (a damper file's cable files; a span file's conductor, damper,
// sheet, wind and S-N curve files; a design's damper and spans; a line's
// conductors), and for the description and CSV files themselves.

#include <filesystem>
#include <string_view>

namespace stockbridge::io {

/// A file that an input names, and where it was looked for.
struct NamedInputFile {
  std::string_view named;           ///< as the input writes it
  std::filesystem::path path;       ///< where it was looked for
  std::string_view what;            ///< what it should be: "cable file", "CSV file"
  std::string_view relative_to;     ///< where relative paths start: "the damper file's folder"
  std::string_view otherwise = {};  ///< what else the input may name there: "a catalogue type"
};

/// `file.path` where a file is there (it exists and is not a folder); else InputError
/// "<where>\"<named>\": expected an existing <what> (looked for <path>; relative paths
/// start at <relative_to>)", followed by " or <otherwise>" where given; `where` is the
/// input's location and key ("span.toml:4: conductor.file: ").
std::filesystem::path existing_input_file(std::string_view where, const NamedInputFile& file);

/// `path` where a file is there; else InputError "<path>: no such file".
std::filesystem::path existing_input_file(const std::filesystem::path& path);

}  // namespace stockbridge::io
