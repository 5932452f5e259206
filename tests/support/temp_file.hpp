#pragma once
// Writes a small text file for a test and returns its path.

#include <filesystem>
#include <fstream>
#include <string>

namespace stockbridge::testing {

inline std::filesystem::path write_temp_file(const std::filesystem::path& directory, const std::string& name,
                                             const std::string& contents) {
  std::filesystem::create_directories(directory);
  const auto path = directory / name;
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

}  // namespace stockbridge::testing
