#pragma once
// Unknown words on the command line named, with the closest valid one: a misspelt
// subcommand ("impedence") or flag ("--frequncy") would otherwise surface as CLI11's
// "A subcommand is required" or "--frequency is required".

#include <CLI/CLI.hpp>

namespace stockbridge::cli {

/// Throws InvalidParameter naming the first unknown subcommand or long flag in
/// argv (for the subcommand it belongs to) and the closest valid word.
void reject_misspellings(const CLI::App& app, int argc, const char* const* argv);

}  // namespace stockbridge::cli
