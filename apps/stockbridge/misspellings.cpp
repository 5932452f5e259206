#include "misspellings.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cli {

namespace {

/// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best_distance <= std::max<std::size_t>(2, word.size() / 3) ? best : std::string();
}

std::string suggestion(std::string_view word, const std::vector<std::string>& candidates, std::string_view kind) {
  const std::string best = closest(word, candidates);
  std::string list;
  for (const std::string& c : candidates) list += (list.empty() ? "" : ", ") + c;
  return best.empty() ? fmt::format("expected one of the {}: {}", kind, list) : fmt::format("did you mean '{}'?", best);
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> long_flags(const CLI::App& app) {
  std::vector<std::string> flags;
  for (const CLI::Option* option : app.get_options({})) {
    for (const std::string& name : option->get_lnames()) {
      if (std::find(flags.begin(), flags.end(), "--" + name) == flags.end()) flags.push_back("--" + name);
    }
  }
  return flags;
}

/// The subcommand a word selects, descending (identify -> local); checks the words.
const CLI::App* selected(const CLI::App& app, std::string_view word, std::string_view path) {
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == word) return sub;
  }
  throw InvalidParameter(fmt::format("unknown command '{}' for '{}': {}", printable(word), path,
                                     suggestion(word, subcommand_names(app), "commands")));
}

}  // namespace

void reject_misspellings(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* command = &app;
  std::string path = "stockbridge";
  int k = 1;
  // The subcommand words: as long as the current command has subcommands.
  while (k < argc && !command->get_subcommands({}).empty() && argv[k][0] != '-') {
    command = selected(*command, argv[k], path);
    path += " " + command->get_name();
    ++k;
  }
  const std::vector<std::string> flags = long_flags(*command);
  for (; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (!arg.starts_with("--") || arg == "--") continue;
    const std::string_view flag = arg.substr(0, arg.find('='));
    if (std::find(flags.begin(), flags.end(), flag) != flags.end()) continue;
    throw InvalidParameter(fmt::format("unknown option '{}' for '{}': {}", printable(flag), path,
                                       suggestion(flag, flags, "options")));
  }
}

}  // namespace stockbridge::cli
