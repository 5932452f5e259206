#pragma once
// Text the program writes into TOML files it generates (a fitted damper file, a
// conductor's [conductor] table): strings made safe to read back.

#include <string>
#include <string_view>

namespace stockbridge::io {

/// `text` as a quoted TOML basic string: quotes and backslashes escaped, control
/// characters as \uXXXX ("ACSR Drake" -> "\"ACSR Drake\"").
std::string toml_basic_string(std::string_view text);

}  // namespace stockbridge::io
