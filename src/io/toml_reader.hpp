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
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

/// Parses a whole TOML file; throws InputError "<file>:<line>:<col>: <what>" on syntax errors.
toml::table parse_toml_file(const std::filesystem::path& path);
/// Parses TOML text that is not a user's file (built by a front end from its own
/// values); messages name `source` and no line.
toml::table parse_toml_text(std::string_view text, std::string_view source);

/// Where messages point: a file (with lines) or a front end's values (without).
struct TomlSource {
  std::string name;
  bool lines = true;
};

class TomlTable {
 public:
  TomlTable(const toml::table& table, TomlSource source, std::string key_path);

  bool contains(std::string_view key) const;
  /// Whether the key is present, without making it a known key (for a key that
  /// belongs to another kind of table, to be refused by name).
  bool present(std::string_view key) const;

  /// A required number (integers are accepted). Ranges are the model's to check
  /// (build_from_file), except where `check` is given (values the model does not
  /// own, such as a file's own settings); its InvalidParameter becomes an InputError
  /// with the file, line and full key.
  double number(std::string_view key, const std::function<void(std::string_view, double)>& check = {}) const;
  std::optional<double> optional_number(std::string_view key,
                                        const std::function<void(std::string_view, double)>& check = {}) const;
  long long integer(std::string_view key, long long lo, long long hi) const;
  std::optional<long long> optional_integer(std::string_view key, long long lo, long long hi) const;
  std::optional<bool> optional_boolean(std::string_view key) const;
  std::optional<std::string> optional_string(std::string_view key) const;
  /// A required non-empty array of numbers (integers accepted); its values are the model's to check.
  std::vector<double> number_array(std::string_view key) const;
  /// An array of strings (each one line of printable text); none if absent.
  std::optional<std::vector<std::string>> optional_string_array(std::string_view key) const;

  /// A required sub-table.
  TomlTable table(std::string_view key) const;
  std::optional<TomlTable> optional_table(std::string_view key) const;
  /// An array of tables ([[arm]] or [ {..}, {..} ]); empty if absent and not required.
  std::vector<TomlTable> table_array(std::string_view key, bool required) const;
  /// The raw node of a key (marks it as read), nullptr if absent.
  const toml::node* node(std::string_view key) const;

  /// Throws InputError naming the first key that no reader asked for (listing those it did).
  void reject_unknown_keys() const;
  /// Rejects every key but `keys` before any value is read, so that a misspelt key is
  /// reported as such rather than as the missing key it was meant to be.
  void accept_only(std::initializer_list<std::string_view> keys) const;
  /// A required string: "missing key '<key>' in [<table>]: expected <expected>" when absent.
  std::string required_string(std::string_view key, std::string_view expected) const;

  /// "<file>:<line>: " for the key's node (or for the table when the key is absent).
  std::string location(std::string_view key) const;
  std::string location_of(const toml::node& node) const;
  /// The key's full dotted path, e.g. "cable.jenkin[0].h".
  std::string qualified(std::string_view key) const;
  const std::string& file() const { return source_.name; }
  /// Whether the table comes from a file with lines (not from a front end's text).
  bool has_lines() const { return source_.lines; }
  const std::string& key_path() const { return key_path_; }

  /// "<location><qualified key>: ", where a message about the key starts.
  std::string where(std::string_view key) const;
  /// Throws InputError "<location><qualified key>: <message>".
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;

 private:
  const toml::node& required(std::string_view key, std::string_view expected) const;

  const toml::table* table_;
  TomlSource source_;
  std::string key_path_;
  mutable std::set<std::string, std::less<>> asked_;  // every key a reader asked for: the known keys
};

/// Describes a node's TOML type for messages ("a string", "an array", ...).
std::string describe_type(const toml::node& node);

/// "<file>:<line>: " for the node a field path names ("arm[1].cable.jenkin[0].h"),
/// or for its nearest ancestor present in the document; "<file>: " if none is.
std::string field_location(const toml::table& document, const TomlSource& source, std::string_view field);

/// Builds the model from a parsed file: the model validates itself, and an
/// InvalidParameter it throws (its field path as the file spells it) becomes an
/// InputError at that field's line, its message unchanged. The one place where the
/// model's validation meets the file.
template <class Build>
auto build_from_file(const toml::table& document, const TomlSource& source, Build&& build) -> decltype(build()) {
  try {
    return build();
  } catch (const InvalidParameter& e) {
    throw InputError(field_location(document, source, e.field()) + e.what());
  }
}

}  // namespace stockbridge::io
