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
/// Parses a comma-separated list of numbers ("0.2,0.05").
std::vector<double> parse_number_list(std::string_view text, std::string_view what);

}  // namespace stockbridge::cli
