#include "stockbridge/io/atomic_file.hpp"

#include <system_error>
#include <utility>

#include <fmt/format.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

namespace fs = std::filesystem;

AtomicFileWriter::AtomicFileWriter(fs::path path) : path_(std::move(path)) {
  std::error_code ec;
  if (fs::is_directory(path_, ec)) {
    throw OutputError(fmt::format("{}: is a directory, expected a file name to write", path_.string()));
  }
  const fs::path directory = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
  temporary_ = directory / fmt::format(".{}.tmp-{}", path_.filename().string(), static_cast<long>(::getpid()));
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    throw OutputError(
        fmt::format("{}: cannot write (directory {} missing or not writable)", path_.string(), directory.string()));
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  fs::remove(temporary_, ec);
}

void AtomicFileWriter::write(std::string_view text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) throw OutputError(fmt::format("{}: writing failed (disk full?)", path_.string()));
}

void AtomicFileWriter::commit() {
  out_.close();
  if (!out_) throw OutputError(fmt::format("{}: writing failed (disk full?)", path_.string()));
  std::error_code ec;
  fs::rename(temporary_, path_, ec);
  if (ec) throw OutputError(fmt::format("{}: cannot replace the file ({})", path_.string(), ec.message()));
  committed_ = true;
}

void write_file_atomically(const fs::path& path, std::string_view contents) {
  AtomicFileWriter file(path);
  file.write(contents);
  file.commit();
}

}  // namespace stockbridge::io
