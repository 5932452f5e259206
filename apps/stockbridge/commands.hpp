#pragma once
// The subcommands of the `stockbridge` program. Each `add_*_command` registers its
// options on `app` and arranges for the invocation's exit code to be set when it
// runs (the invocation, main's, also takes the command's warnings). Commands parse
// arguments, call the library, and write files; nothing else.

#include <CLI/CLI.hpp>

#include "invocation.hpp"

namespace stockbridge::cli {

/// Exit statuses shared by every command.
enum ExitStatus : int { kSuccess = 0, kBadInput = 2, kNotConverged = 3 };

void add_loop_command(CLI::App& app, Invocation& invocation);
void add_cycle_command(CLI::App& app, Invocation& invocation);
void add_identify_command(CLI::App& app, Invocation& invocation);
/// `identify impedance`, registered on the identify command.
void add_identify_impedance_command(CLI::App& identify, Invocation& invocation);
/// `identify self-damping`, registered on the identify command.
void add_identify_self_damping_command(CLI::App& identify, Invocation& invocation);
void add_impedance_command(CLI::App& app, Invocation& invocation);
void add_response_command(CLI::App& app, Invocation& invocation);
void add_strand_command(CLI::App& app, Invocation& invocation);
void add_conductors_command(CLI::App& app, Invocation& invocation);
void add_modes_command(CLI::App& app, Invocation& invocation);
void add_span_command(CLI::App& app, Invocation& invocation);
void add_recorder_command(CLI::App& app, Invocation& invocation);
void add_design_command(CLI::App& app, Invocation& invocation);
void add_line_command(CLI::App& app, Invocation& invocation);
void add_datasheet_command(CLI::App& app, Invocation& invocation);
void add_fatigue_tests_command(CLI::App& app, Invocation& invocation);
void add_simulate_command(CLI::App& app, Invocation& invocation);

}  // namespace stockbridge::cli
