#pragma once
// Numbers out of a command's --json summary, for the command-line tests.

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

namespace stockbridge::testing {

/// The number after "key": in a JSON text, the first at or after `from`: NaN where
/// the value is null; NaN and a test failure where the key is not there.
inline double json_number(const std::string& json, const std::string& key, std::size_t from = 0) {
  const std::size_t at = from > json.size() ? std::string::npos : json.find("\"" + key + "\": ", from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no key " << key << " in " << json;
    return std::nan("");
  }
  const char* value = json.c_str() + at + key.size() + 4;
  return std::string_view(value).starts_with("null") ? std::nan("") : std::strtod(value, nullptr);
}

/// The same after the first key "anchor" ("": in the whole text).
inline double json_number_after(const std::string& json, const std::string& anchor, const std::string& key) {
  const std::size_t from = anchor.empty() ? 0 : json.find("\"" + anchor + "\": ");
  if (from == std::string::npos) {
    ADD_FAILURE() << "no key " << anchor << " in " << json;
    return std::nan("");
  }
  return json_number(json, key, from);
}

}  // namespace stockbridge::testing
