#include "record_text.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

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

namespace {

/// FNV-1a, 64 bits: enough to tell inputs apart (not a defence against forgery).
struct InputDigest {
  std::uint64_t h = 1469598103934665603ULL;
  void add(std::string_view bytes) {
    for (const unsigned char c : bytes) h = (h ^ c) * 1099511628211ULL;
    for (const unsigned char c : fmt::format("|{}|", bytes.size())) h = (h ^ c) * 1099511628211ULL;
  }
};

}  // namespace

std::string input_fingerprint(std::string_view text, const std::vector<std::filesystem::path>& inputs) {
  InputDigest d;
  d.add(version_string);
  d.add(text);
  for (const std::filesystem::path& input : inputs) {
    std::ifstream in(input, std::ios::binary);
    d.add(input.string());
    d.add(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
  }
  return fmt::format("{:016x}", d.h);
}

}  // namespace stockbridge::requests::record_text
