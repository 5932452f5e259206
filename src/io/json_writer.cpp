#include "stockbridge/io/json_writer.hpp"

#include <cmath>

#include <fmt/format.h>

namespace stockbridge::io {

std::string json_quote(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<int>(ch));
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

namespace {
std::string number(double value) { return std::isfinite(value) ? fmt::format("{}", value) : "null"; }
}  // namespace

JsonObject& JsonObject::add_raw(std::string_view key, std::string raw) {
  members_.emplace_back(std::string(key), std::move(raw));
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, double value) { return add_raw(key, number(value)); }
JsonObject& JsonObject::add(std::string_view key, int value) { return add_raw(key, std::to_string(value)); }
JsonObject& JsonObject::add(std::string_view key, long long value) { return add_raw(key, std::to_string(value)); }
JsonObject& JsonObject::add(std::string_view key, bool value) { return add_raw(key, value ? "true" : "false"); }
JsonObject& JsonObject::add(std::string_view key, std::string_view value) { return add_raw(key, json_quote(value)); }
JsonObject& JsonObject::add(std::string_view key, const JsonObject& value) { return add_raw(key, value.str()); }

JsonObject& JsonObject::add(std::string_view key, const std::vector<JsonObject>& values) {
  std::string raw = "[";
  for (std::size_t i = 0; i < values.size(); ++i) raw += (i ? ", " : "") + values[i].str();
  return add_raw(key, raw + "]");
}

JsonObject& JsonObject::add(std::string_view key, const std::vector<double>& values) {
  std::string raw = "[";
  for (std::size_t i = 0; i < values.size(); ++i) raw += (i ? ", " : "") + number(values[i]);
  return add_raw(key, raw + "]");
}

JsonObject& JsonObject::add(std::string_view key, const std::vector<std::vector<double>>& rows) {
  std::string raw = "[";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    raw += i ? ", [" : "[";
    for (std::size_t j = 0; j < rows[i].size(); ++j) raw += (j ? ", " : "") + number(rows[i][j]);
    raw += "]";
  }
  return add_raw(key, raw + "]");
}

JsonObject& JsonObject::add(std::string_view key, const std::vector<std::string>& values) {
  std::string raw = "[";
  for (std::size_t i = 0; i < values.size(); ++i) raw += (i ? ", " : "") + json_quote(values[i]);
  return add_raw(key, raw + "]");
}

JsonObject& JsonObject::add_null(std::string_view key) { return add_raw(key, "null"); }

std::string JsonObject::str() const {
  std::string out = "{";
  for (std::size_t i = 0; i < members_.size(); ++i) {
    out += fmt::format("{}{}: {}", i ? ", " : "", json_quote(members_[i].first), members_[i].second);
  }
  return out + "}";
}

}  // namespace stockbridge::io
