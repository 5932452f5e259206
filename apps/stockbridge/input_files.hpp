#pragma once
// Description files as the commands read them: the library's reader, its warnings
// (values outside the typical ranges) printed on stderr one line each, and the
// command's outputs checked apart from every file read, referenced ones included.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "invocation.hpp"
#include "option_parsing.hpp"
#include "stockbridge/cable/cable.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/core/warning.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/io/design_file.hpp"
#include "stockbridge/io/span_file.hpp"

namespace stockbridge::cli {

/// `--allow-unusual` on a command that reads description files or takes amounts:
/// a value a unit slip explains (typical_ranges.hpp) is then a warning, not an error.
void add_allow_unusual_flag(CLI::App& command, bool& allow_unusual);
inline SlipPolicy slip_policy(bool allow_unusual) { return allow_unusual ? SlipPolicy::warn : SlipPolicy::refuse; }

/// The damper file at `path`, its warnings the invocation's; throws InvalidParameter
/// if an output would overwrite it or a cable file it references. Under `policy` a
/// value a unit slip explains is refused (UnusualValueError) or a warning; the same
/// below.
damper::Damper read_damper_input(Invocation& invocation, const std::string& path,
                                 const std::vector<CommandFile>& outputs, SlipPolicy policy);
/// The span file at `path` (the span and its balance options); throws
/// InvalidParameter if an output would overwrite it or a file it references (damper
/// files, their cable files, a wind table).
io::SpanFile read_span_input(Invocation& invocation, const std::string& path,
                             const std::vector<CommandFile>& outputs, SlipPolicy policy);
/// The design file at `path`; throws InvalidParameter if an output would overwrite
/// it or a file it reads (the damper, its cable files, the span files and theirs).
io::DesignFile read_design_input(Invocation& invocation, const std::string& path,
                                 const std::vector<CommandFile>& outputs, SlipPolicy policy);
/// The cable file at `path`; throws InvalidParameter if an output would overwrite it.
cable::Cable read_cable_input(Invocation& invocation, const std::string& path,
                              const std::vector<CommandFile>& outputs, SlipPolicy policy);

/// "warning: <line>" on stderr for each line (Invocation::warn: held until the
/// computation starts).
void print_warnings(Invocation& invocation, const std::vector<std::string>& lines);
/// The same for the library's warnings, a setting's name shown as its flag
/// ("--velocity = 100: ...").
void print_warnings(Invocation& invocation, const std::vector<Warning>& warnings);
/// A warning for each option value outside its typical range, the field named as
/// the option ("--velocity = 100: outside the typical ..."); one a unit slip
/// explains refused (UnusualValueError) under `policy`.
void warn_unusual_options(Invocation& invocation, const std::vector<UnusualValue>& values, SlipPolicy policy);
/// The refusal alone, where the request warns of the values itself (Python too).
void refuse_slipped_options(const std::vector<UnusualValue>& values, SlipPolicy policy);

}  // namespace stockbridge::cli
