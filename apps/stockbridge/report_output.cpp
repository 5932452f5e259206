#include "report_output.hpp"

#include <filesystem>
#include <mutex>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cli {

namespace {

struct RunRecord {
  std::mutex mutex;
  std::string command;
  std::vector<std::string> warnings;  ///< every warning so far, printed or held
  std::size_t printed = 0;            ///< of which printed on stderr
  bool started = false;               ///< the computation started: a warning is printed at once
};

/// Prints the warnings held (the lock taken).
void print_held(RunRecord& record) {
  for (; record.printed < record.warnings.size(); ++record.printed) {
    fmt::print(stderr, "warning: {}\n", record.warnings[record.printed]);
  }
}

RunRecord& run_record() {
  static RunRecord record;
  return record;
}

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

}  // namespace

void remember_command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    std::string word = argv[i];
    if (i == 0) word = std::filesystem::path(word).filename().string();
    if (i > 0) line += ' ';
    line += shell_quoted(word);
  }
  const std::lock_guard lock(run_record().mutex);
  run_record().command = line;
}

void remember_warning(const std::string& line) {
  const std::lock_guard lock(run_record().mutex);
  run_record().warnings.push_back(line);
  if (run_record().started) print_held(run_record());
}

void flush_warnings() {
  const std::lock_guard lock(run_record().mutex);
  run_record().started = true;
  print_held(run_record());
}

report::ReportContext report_context() {
  const std::lock_guard lock(run_record().mutex);
  return {report::utc_now(), run_record().command, run_record().warnings};
}

CLI::Option* add_report_option(CLI::App& command, std::optional<std::string>& path, const std::string& what) {
  return command.add_option("--report", path,
                            "Also write a self-contained HTML report (" + what + "; printable on A4), e.g. report.html");
}

void check_report_path(const std::optional<std::string>& path, const std::string& option) {
  if (!path) return;
  const std::filesystem::path p(*path);
  const std::string extension = p.extension().string();
  if (extension != ".html" && extension != ".htm") {
    throw InvalidParameter(
        fmt::format("{} = '{}': expected an HTML file name ending in .html", option, printable(*path)));
  }
  const std::filesystem::path folder = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    throw InvalidParameter(fmt::format("{} = '{}': the folder '{}' does not exist", option, printable(*path),
                                       printable(folder.string())));
  }
}

}  // namespace stockbridge::cli
