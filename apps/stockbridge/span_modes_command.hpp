#pragma once
// `stockbridge span SPAN.toml --modes`: the span's natural frequencies with its
// attachments (requests/span_modes_request.hpp), a mode of the span command. Its
// options are registered on the span command, which calls run_span_modes_command
// when --modes is given.

#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "invocation.hpp"

namespace stockbridge::cli {

struct SpanModesFlags {
  bool modes = false;
  std::optional<double> fmax;
  std::string dampers = "linear";
  std::optional<std::string> shapes;
};

/// What --modes shares with the span command's own options.
struct SpanModesCommon {
  std::string span_file;
  std::string output;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
};

/// Adds --modes, --fmax, --dampers and --shapes to the span command: --modes excludes
/// the balance's own options, the others need --modes (CLI11's one-line errors, exit 2).
void add_span_modes_options(CLI::App& span, SpanModesFlags& flags);

/// Runs --modes: exit status kSuccess (a bad option or file throws, exit 2).
int run_span_modes_command(const SpanModesFlags& flags, const SpanModesCommon& common, Invocation& invocation);

}  // namespace stockbridge::cli
