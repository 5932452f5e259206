#pragma once
// The commands' --report FILE.html: the option checked before anything is computed
// (an .html name in a folder that exists, apart from the inputs); what the report
// states of the run (when, the exact command, every warning printed) is the
// Invocation's (invocation.hpp).

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace stockbridge::cli {

/// Adds `--report FILE.html` to a command.
CLI::Option* add_report_option(CLI::App& command, std::optional<std::string>& path, const std::string& what);

/// Throws InvalidParameter naming `option` (--report, -o) where the path is not an
/// .html file in an existing folder (checked before anything is computed or written).
void check_report_path(const std::optional<std::string>& path, const std::string& option = "--report");

}  // namespace stockbridge::cli
