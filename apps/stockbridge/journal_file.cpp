#include "journal_file.hpp"

#include <unistd.h>

#include <fstream>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cli {

JournalFile::JournalFile(const std::filesystem::path& path, const std::string& head, bool append) : path_(path) {
  file_ = std::fopen(path.string().c_str(), append ? "ab" : "wb");
  if (!file_) throw OutputError(fmt::format("{}: cannot write the journal", path.string()));
  if (!append || std::ftell(file_) == 0) write(head);
}

JournalFile::~JournalFile() {
  if (file_) std::fclose(file_);
}

void JournalFile::write(const std::string& record) {
  const std::string line = record + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0) {
    throw OutputError(fmt::format("{}: cannot write the journal", path_.string()));
  }
  ::fsync(fileno(file_));
}

JournalRecords read_journal(const std::filesystem::path& path, const std::string& head) {
  JournalRecords out;
  std::ifstream in(path, std::ios::binary);
  if (!in) return out;
  std::string first;
  std::getline(in, first);
  if (first != head) {
    throw InvalidParameter(fmt::format("--resume: {} was written for other inputs (its first line is '{}', these "
                                       "inputs give '{}': the description or a file it reads changed): run without "
                                       "--resume to start again",
                                       path.string(), printable(first), head));
  }
  for (std::string record; std::getline(in, record);) {
    if (in.eof()) {  // no line break after it: cut short
      ++out.cut_short;
      break;
    }
    out.records.push_back(std::move(record));
  }
  return out;
}

namespace {

std::atomic<bool> interrupt_requested{false};

extern "C" void on_interrupt_request(int) { interrupt_requested.store(true); }

}  // namespace

InterruptRequest::InterruptRequest() {
  interrupt_requested.store(false);
  previous_ = std::signal(SIGINT, on_interrupt_request);
}

InterruptRequest::~InterruptRequest() { std::signal(SIGINT, previous_); }

const std::atomic<bool>& InterruptRequest::flag() { return interrupt_requested; }

}  // namespace stockbridge::cli
