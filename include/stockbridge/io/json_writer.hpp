#pragma once
// A small JSON builder for the commands' --json summaries: keys keep their
// insertion order; numbers in shortest round-trip form; a non-finite number is
// written as null (the program never passes off an untrusted value as a number).

#include <string>
#include <string_view>
#include <vector>

namespace stockbridge::io {

class JsonObject {
 public:
  JsonObject& add(std::string_view key, double value);
  JsonObject& add(std::string_view key, int value);
  JsonObject& add(std::string_view key, long long value);
  JsonObject& add(std::string_view key, bool value);
  JsonObject& add(std::string_view key, std::string_view value);
  JsonObject& add(std::string_view key, const char* value) { return add(key, std::string_view(value)); }
  JsonObject& add(std::string_view key, const JsonObject& value);
  JsonObject& add(std::string_view key, const std::vector<JsonObject>& values);
  JsonObject& add(std::string_view key, const std::vector<double>& values);
  JsonObject& add(std::string_view key, const std::vector<std::vector<double>>& rows);
  JsonObject& add(std::string_view key, const std::vector<std::string>& values);
  JsonObject& add_null(std::string_view key);

  /// The object as one line of JSON.
  std::string str() const;

 private:
  JsonObject& add_raw(std::string_view key, std::string raw);
  std::vector<std::pair<std::string, std::string>> members_;
};

/// A JSON string literal with escapes.
std::string json_quote(std::string_view text);

}  // namespace stockbridge::io
