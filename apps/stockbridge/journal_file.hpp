#pragma once
// Journals of long runs (`line`, `design`): every finished result appended as one
// line and flushed to the disk before the next, so that --resume can go on after an
// interruption; and Ctrl-C turned into a request to stop.

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace stockbridge::cli {

/// A journal opened for appending: its first line `head` (a new journal, or an
/// empty one), then records, each written whole and flushed to the disk.
class JournalFile {
 public:
  JournalFile(const std::filesystem::path& path, const std::string& head, bool append);
  ~JournalFile();
  JournalFile(const JournalFile&) = delete;
  JournalFile& operator=(const JournalFile&) = delete;

  /// Appends `record` and a line break. Throws OutputError naming the file.
  void write(const std::string& record);

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
};

/// A journal's complete records: those ending in a line break (a last one cut short
/// by the interruption is counted in `cut_short`, not returned); none where there is
/// no file. InvalidParameter naming --resume where its first line is not `head`
/// (a journal of other inputs).
struct JournalRecords {
  std::vector<std::string> records;
  int cut_short = 0;
};
JournalRecords read_journal(const std::filesystem::path& path, const std::string& head);

/// While it lives, Ctrl-C (SIGINT) sets `requested()` instead of ending the program.
class InterruptRequest {
 public:
  InterruptRequest();
  ~InterruptRequest();
  InterruptRequest(const InterruptRequest&) = delete;
  InterruptRequest& operator=(const InterruptRequest&) = delete;

  static const std::atomic<bool>& flag();
  static bool requested() { return flag().load(); }

 private:
  void (*previous_)(int) = nullptr;
};

/// The exit status after Ctrl-C (128 + SIGINT).
inline constexpr int kInterrupted = 130;

}  // namespace stockbridge::cli
