#include "stockbridge/io/atomic_file.hpp"

#include <cstdio>
#include <fstream>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    throw OutputError(fmt::format("{}: is a directory, expected a file name to write", path.string()));
  }
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const fs::path temporary =
      directory / fmt::format(".{}.tmp-{}", path.filename().string(), static_cast<long>(::getpid()));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw OutputError(fmt::format("{}: cannot write (directory {} missing or not writable)",
                                    path.string(), directory.string()));
    }
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.close();
    if (!out) {
      fs::remove(temporary, ec);
      throw OutputError(fmt::format("{}: writing failed (disk full?)", path.string()));
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw OutputError(fmt::format("{}: cannot replace the file ({})", path.string(), ec.message()));
  }
}

}  // namespace stockbridge::io
