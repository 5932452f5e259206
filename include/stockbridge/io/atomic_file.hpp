#pragma once
// Output files appear whole or not at all: the text goes to a temporary file in
// the target's directory, which is then renamed over the target.

#include <filesystem>
#include <fstream>
#include <string_view>

namespace stockbridge::io {

/// A file written piece by piece that appears whole or not at all: the pieces go
/// to a temporary file beside `path`, renamed over it by `commit`. Destroyed
/// without a commit (an error, an interruption), the temporary file is removed and
/// `path` is as it was. Throws OutputError naming the path.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::filesystem::path path);
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;
  ~AtomicFileWriter();

  void write(std::string_view text);
  /// Closes the temporary file and renames it over the target.
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes `contents` to `path` atomically. Throws OutputError naming the path.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace stockbridge::io
