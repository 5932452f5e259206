#include "option_parsing.hpp"

#include <charconv>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cli {

double parse_number(std::string_view text, std::string_view what) {
  std::string trimmed(text);
  double value = 0.0;
  const char* first = trimmed.data();
  const char* last = first + trimmed.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  if (trimmed.empty() || ec != std::errc() || end != last) {
    throw InvalidParameter(fmt::format("{} = '{}': expected a number", what, text));
  }
  return value;
}

section::Jenkin parse_jenkin_pair(std::string_view text, std::string_view what) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos || text.find(':', colon + 1) != std::string_view::npos) {
    throw InvalidParameter(fmt::format("{} = '{}': expected c:h, two numbers such as 20:0.7", what, text));
  }
  section::Jenkin element;
  element.c = parse_number(text.substr(0, colon), fmt::format("{} c", what));
  element.h = parse_number(text.substr(colon + 1), fmt::format("{} h", what));
  return element;
}

std::vector<double> parse_number_list(std::string_view text, std::string_view what) {
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    values.push_back(parse_number(text.substr(start, comma - start), what));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return values;
}

}  // namespace stockbridge::cli
