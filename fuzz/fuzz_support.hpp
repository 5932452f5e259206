#pragma once
// Shared by the libFuzzer targets: the input handed to a file reader as a real
// file, and invariants that abort (so that libFuzzer keeps the input) when broken.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace stockbridge::fuzz {

/// This process's folder for the files it hands the readers.
inline const std::filesystem::path& folder() {
  static const std::filesystem::path directory = [] {
    auto d = std::filesystem::temp_directory_path() / ("stockbridge-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return directory;
}

/// Writes the fuzzer's bytes to a file of this process (the readers take paths, as
/// the program does) and returns its path.
inline std::filesystem::path as_file(const std::uint8_t* data, std::size_t size, std::string_view name) {
  const std::filesystem::path path = folder() / std::string(name);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  return path;
}

/// The same for a fixed text: a file the fuzzed input may name (a damper file, a
/// sheet, a spans CSV beside a line file).
inline std::filesystem::path as_file(std::string_view text, std::string_view name) {
  return as_file(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), name);
}

/// A broken invariant: say which and abort, so that libFuzzer saves the input.
[[noreturn]] inline void broken(std::string_view what) {
  std::fprintf(stderr, "invariant broken: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

inline void require(bool holds, std::string_view what) {
  if (!holds) broken(what);
}

/// Any error's message: one line, not empty.
inline void require_one_line(const std::string& message) {
  require(!message.empty() && message.find('\n') == std::string::npos && message.find('\r') == std::string::npos,
          "an error is one line");
}

/// The program's contract for a rejected file: one line that begins with the file's path.
inline void require_one_line_naming(const std::string& message, const std::filesystem::path& path) {
  require_one_line(message);
  require(message.rfind(path.string(), 0) == 0, "an input error begins with the file's path");
}

}  // namespace stockbridge::fuzz
