#include "stockbridge/io/input_file.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

namespace {

/// A file there: it exists and is not a folder (a pipe or a device reads too).
bool input_file_there(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec);
}

}  // namespace

std::filesystem::path existing_input_file(std::string_view where, const NamedInputFile& file) {
  if (input_file_there(file.path)) return file.path;
  throw InputError(fmt::format("{}\"{}\": expected an existing {} (looked for {}; relative paths start at {}){}", where,
                               printable(file.named), file.what, printable(file.path.string(), 300), file.relative_to,
                               file.otherwise.empty() ? std::string() : fmt::format(" or {}", file.otherwise)));
}

std::filesystem::path existing_input_file(const std::filesystem::path& path) {
  if (input_file_there(path)) return path;
  throw InputError(fmt::format("{}: no such file", path.string()));
}

}  // namespace stockbridge::io
