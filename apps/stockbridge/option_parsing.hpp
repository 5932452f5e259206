#pragma once
// Parsing of compound option values shared by the commands.

#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/section/jenkin.hpp"

namespace stockbridge::cli {

/// Parses a number; throws InvalidParameter "<what> = '<text>': expected a number".
double parse_number(std::string_view text, std::string_view what);
/// Parses "c:h" into a Jenkin element (values validated by the library later).
section::Jenkin parse_jenkin_pair(std::string_view text, std::string_view what);
/// Parses a comma-separated list of numbers ("0.2,0.05", "0.2, 0.05"); an empty or
/// malformed list is an error naming `what`.
std::vector<double> parse_number_list(std::string_view text, std::string_view what);
/// Splits a comma-separated list into its items, each without the spaces and tabs
/// around it ("a, b" -> {"a", "b"}; "" -> {""}).
std::vector<std::string> split_list(std::string_view text);

/// A file a command reads or writes, with how the user named it (flag or argument).
struct CommandFile {
  std::string role;  ///< "-o", "--fitted", "the damper file", ...
  std::string path;  ///< empty: not given
};

/// Throws InvalidParameter if an output resolves to an input (the same file, also
/// through links) or two outputs to one file: checked before anything is read or
/// written, so the input stays untouched.
void require_outputs_apart(const std::vector<CommandFile>& outputs, const std::vector<CommandFile>& inputs);

}  // namespace stockbridge::cli
