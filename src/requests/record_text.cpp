#include "record_text.hpp"

#include <charconv>

#include <fmt/format.h>

#include "stockbridge/core/digest.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/version.hpp"

namespace stockbridge::requests::record_text {

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      out += c;
    }
  }
  return out;
}

std::string unescaped(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\' || i + 1 == text.size()) {
      out += text[i];
      continue;
    }
    const char c = text[++i];
    out += c == 't' ? '\t' : c == 'n' ? '\n' : c == 'r' ? '\r' : c;
  }
  return out;
}

void bad_record(std::string_view why) { throw InvalidParameter("record", fmt::format(": {}", why)); }

RecordFields::RecordFields(std::string_view record) {
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = record.find('\t', start);
    fields_.push_back(record.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
    if (tab == std::string_view::npos) break;
    start = tab + 1;
  }
}

std::string_view RecordFields::next() {
  if (next_ >= fields_.size()) bad_record("cut short");
  return fields_[next_++];
}

std::string RecordFields::text() { return unescaped(next()); }

double RecordFields::number() {
  const std::string_view f = next();
  double value = 0.0;
  const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
  if (error != std::errc() || end != f.data() + f.size()) bad_record(fmt::format("'{}' is not a number", printable(f)));
  return value;
}

long long RecordFields::integer() {
  const std::string_view f = next();
  long long value = 0;
  const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
  if (error != std::errc() || end != f.data() + f.size()) bad_record(fmt::format("'{}' is not an integer", printable(f)));
  return value;
}

std::string input_fingerprint(std::string_view text, const std::vector<std::filesystem::path>& inputs) {
  ContentDigest d;
  d.add(version_string).add(text);
  for (const std::filesystem::path& input : inputs) d.add_file(input);
  return d.hex();
}

}  // namespace stockbridge::requests::record_text
