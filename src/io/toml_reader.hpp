#pragma once
// Reading TOML description files with precise errors (private to the library).
//
// A TomlTable wraps one table of a parsed file together with the file name and
// the table's key path. Every read names the file, the line (where toml++ knows
// it), the full key, the value and what was expected; keys that were never read
// are rejected by reject_unknown_keys(), so a misspelt key is an error, not a
// silently ignored line.

#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace stockbridge::io {

/// Parses a whole TOML file; throws InputError "<file>:<line>:<col>: <what>" on syntax errors.
toml::table parse_toml_file(const std::filesystem::path& path);

class TomlTable {
 public:
  TomlTable(const toml::table& table, std::string file, std::string key_path);

  bool contains(std::string_view key) const;

  /// A required number (integers are accepted); `check` validates it with the
  /// library's require_* functions, whose InvalidParameter becomes an InputError
  /// with the file, line and full key.
  double number(std::string_view key, const std::function<void(std::string_view, double)>& check) const;
  std::optional<double> optional_number(std::string_view key,
                                        const std::function<void(std::string_view, double)>& check) const;
  long long integer(std::string_view key, long long lo, long long hi) const;
  std::optional<long long> optional_integer(std::string_view key, long long lo, long long hi) const;
  std::optional<bool> optional_boolean(std::string_view key) const;
  std::optional<std::string> optional_string(std::string_view key) const;

  /// A required sub-table.
  TomlTable table(std::string_view key) const;
  std::optional<TomlTable> optional_table(std::string_view key) const;
  /// An array of tables ([[arm]] or [ {..}, {..} ]); empty if absent and not required.
  std::vector<TomlTable> table_array(std::string_view key, bool required) const;
  /// The raw node of a key (marks it as read), nullptr if absent.
  const toml::node* node(std::string_view key) const;

  /// Throws InputError naming the first key that no reader asked for (listing those it did).
  void reject_unknown_keys() const;

  /// "<file>:<line>: " for the key's node (or for the table when the key is absent).
  std::string location(std::string_view key) const;
  std::string location_of(const toml::node& node) const;
  /// The key's full dotted path, e.g. "cable.jenkin[0].h".
  std::string qualified(std::string_view key) const;
  const std::string& file() const { return file_; }
  const std::string& key_path() const { return key_path_; }

  /// Throws InputError "<location><qualified key>: <message>".
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;

 private:
  const toml::node& required(std::string_view key, std::string_view expected) const;

  const toml::table* table_;
  std::string file_;
  std::string key_path_;
  mutable std::set<std::string, std::less<>> asked_;  // every key a reader asked for: the known keys
};

/// Describes a node's TOML type for messages ("a string", "an array", ...).
std::string describe_type(const toml::node& node);

}  // namespace stockbridge::io
