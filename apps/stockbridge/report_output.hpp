#pragma once
// The commands' --report FILE.html: the option checked before anything is computed
// (an .html name in a folder that exists, apart from the inputs), what the report
// states of the run (when, the exact command, every warning printed), and the page
// written atomically beside the command's other outputs.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "stockbridge/report/reports.hpp"

namespace stockbridge::cli {

/// Kept from main() for the reports' header: the command line as typed (arguments
/// with spaces or quotes quoted for a POSIX shell).
void remember_command_line(int argc, const char* const* argv);

/// A warning line for stderr ("warning: <line>"), kept for the report. Held until
/// flush_warnings: a run refused for bad input then prints its one error line alone.
void remember_warning(const std::string& line);
/// Prints the warnings held, and every later one at once: when the computation
/// starts (a progress report begins), or the command ended without an error.
void flush_warnings();

/// The run as the report states it: now (UTC), the command line, the warnings so far.
report::ReportContext report_context();

/// Adds `--report FILE.html` to a command.
CLI::Option* add_report_option(CLI::App& command, std::optional<std::string>& path, const std::string& what);

/// Throws InvalidParameter naming `option` (--report, -o) where the path is not an
/// .html file in an existing folder (checked before anything is computed or written).
void check_report_path(const std::optional<std::string>& path, const std::string& option = "--report");

}  // namespace stockbridge::cli
