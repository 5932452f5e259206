#include "option_parsing.hpp"

#include <charconv>
#include <filesystem>

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

namespace {
std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}
}  // namespace

std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    items.emplace_back(trimmed(text.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return items;
}

std::vector<double> parse_number_list(std::string_view text, std::string_view what) {
  if (trimmed(text).empty()) {
    throw InvalidParameter(fmt::format("{} = '{}': expected a comma-separated list of numbers, such as 0.2,0.05", what, text));
  }
  std::vector<double> values;
  for (const std::string& item : split_list(text)) {
    try {
      values.push_back(parse_number(item, what));
    } catch (const InvalidParameter&) {
      throw InvalidParameter(fmt::format("{} = '{}': item {} ('{}') is not a number; expected a comma-separated list "
                                         "of numbers, such as 0.2,0.05",
                                         what, text, values.size() + 1, item));
    }
  }
  return values;
}

namespace {
/// Whether two paths name one file: the same inode where both exist (links
/// included), else the same normalised absolute path.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec)) {
    const bool same = std::filesystem::equivalent(a, b, ec);
    if (!ec) return same;
  }
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}
}  // namespace

void require_outputs_apart(const std::vector<CommandFile>& outputs, const std::vector<CommandFile>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const CommandFile& out = outputs[i];
    if (out.path.empty()) continue;
    const std::filesystem::path folder = std::filesystem::path(out.path).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) {
      throw InvalidParameter(fmt::format("{} {}: the folder {} does not exist: expected an output file in an existing "
                                         "folder",
                                         out.role, printable(out.path, 300), printable(folder.string(), 300)));
    }
    for (const CommandFile& in : inputs) {
      if (!in.path.empty() && same_file(out.path, in.path)) {
        throw InvalidParameter(fmt::format("{} {}: is {} ({}); writing it would destroy that input, choose another "
                                           "output name",
                                           out.role, out.path, in.role, in.path));
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].path.empty() && same_file(out.path, outputs[j].path)) {
        throw InvalidParameter(fmt::format("{} {}: the same file as {} {}; expected two different output files", out.role,
                                           out.path, outputs[j].role, outputs[j].path));
      }
    }
  }
}

}  // namespace stockbridge::cli
