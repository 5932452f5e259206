#pragma once
// One run of the program, made by main() and handed to the command it runs: the
// command line as typed, the warnings (printed on stderr, stated by the reports) and
// the exit status. The program keeps no other state of a run.

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include "stockbridge/report/reports.hpp"

namespace stockbridge::cli {

class Invocation {
 public:
  /// The run of main's arguments: the program's name without its folder, arguments
  /// with spaces or quotes quoted for a POSIX shell.
  Invocation(int argc, const char* const* argv);
  Invocation(const Invocation&) = delete;
  Invocation& operator=(const Invocation&) = delete;

  /// The command line as typed (quoted as above).
  const std::string& command_line() const { return command_line_; }

  /// A warning line for stderr ("warning: <line>"), kept for the report. Held until
  /// flush_warnings: a run refused for bad input then prints its one error line alone.
  /// Any thread may warn.
  void warn(const std::string& line);
  /// Prints the warnings held, and every later one at once: when the computation
  /// starts (a progress report begins), or the command ended without an error.
  void flush_warnings();

  /// The run as the report states it: now (UTC), the command line, the warnings so far.
  report::ReportContext report_context() const;

  /// The command's exit status (commands.hpp's ExitStatus; 0 until a command sets it).
  int exit_code() const { return exit_code_; }
  void set_exit_code(int code) { exit_code_ = code; }

 private:
  /// Prints the warnings held (the lock taken).
  void print_held();

  std::string command_line_;
  mutable std::mutex mutex_;
  std::vector<std::string> warnings_;  ///< every warning so far, printed or held
  std::size_t printed_ = 0;            ///< of which printed on stderr
  bool started_ = false;               ///< the computation started: a warning is printed at once
  int exit_code_ = 0;
};

}  // namespace stockbridge::cli
