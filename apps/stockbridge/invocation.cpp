#include "invocation.hpp"

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "stockbridge/report/html_page.hpp"

namespace stockbridge::cli {

namespace {

std::string shell_quoted(const std::string& word) {
  if (!word.empty() && word.find_first_of(" \t\n'\"\\$`*?;&|<>()[]{}#~!") == std::string::npos) return word;
  std::string out = "'";
  for (const char c : word) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  out += '\'';
  return out;
}

std::string typed_command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    std::string word = argv[i];
    if (i == 0) word = std::filesystem::path(word).filename().string();
    if (i > 0) line += ' ';
    line += shell_quoted(word);
  }
  return line;
}

}  // namespace

Invocation::Invocation(int argc, const char* const* argv) : command_line_(typed_command_line(argc, argv)) {}

void Invocation::warn(const std::string& line) {
  const std::lock_guard lock(mutex_);
  warnings_.push_back(line);
  if (started_) print_held();
}

void Invocation::flush_warnings() {
  const std::lock_guard lock(mutex_);
  started_ = true;
  print_held();
}

void Invocation::print_held() {
  for (; printed_ < warnings_.size(); ++printed_) fmt::print(stderr, "warning: {}\n", warnings_[printed_]);
}

report::ReportContext Invocation::report_context() const {
  const std::lock_guard lock(mutex_);
  return {report::utc_now(), command_line_, warnings_};
}

}  // namespace stockbridge::cli
