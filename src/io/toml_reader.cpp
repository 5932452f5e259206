#include "toml_reader.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/input_file.hpp"

namespace stockbridge::io {

namespace {

/// A syntax error's description; where the text is not UTF-8, the line of its first
/// such byte as a message quotes it (printable: that byte as \xNN), which the
/// parser's description does not show.
std::string toml_syntax_error(const toml::parse_error& e, std::string_view text) {
  const std::string what = printable(e.description(), 200);
  const std::size_t bad = first_non_utf8(text);
  if (what.find("utf-8") == std::string::npos || bad == std::string_view::npos) return what;
  const std::size_t newline = text.rfind('\n', bad);
  const std::size_t start = newline == std::string_view::npos ? 0 : newline + 1;
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + start, '\n'));
  // A long line from a little before the byte, at a character's start.
  std::size_t from = bad - start > 40 ? bad - 20 : start;
  while (from > start && (static_cast<unsigned char>(text[from]) & 0xC0) == 0x80) --from;
  const std::string_view rest = text.substr(from);
  return fmt::format("{}: line {} reads '{}{}'", what, line, from > start ? "..." : "",
                     printable(rest.substr(0, rest.find('\n'))));
}

}  // namespace

toml::table parse_toml_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(fmt::format("{}: is a directory, expected a TOML file", path.string()));
  }
  existing_input_file(path);
  try {
    return toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    throw InputError(
        fmt::format("{}:{}:{}: TOML syntax error: {}", path.string(), where.line, where.column, toml_syntax_error(e, text)));
  }
}

toml::table parse_toml_text(std::string_view text, std::string_view source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}: TOML syntax error: {}", source, toml_syntax_error(e, text)));
  }
}

std::string describe_type(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return fmt::format("the string \"{}\"", printable(*node.value<std::string>()));
    case toml::node_type::integer: return fmt::format("the integer {}", *node.value<long long>());
    case toml::node_type::floating_point: return fmt::format("the number {}", format_value(*node.value<double>()));
    case toml::node_type::boolean: return *node.value<bool>() ? "true" : "false";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

std::string field_location(const toml::table& document, const TomlSource& source, std::string_view field) {
  const std::string& file = source.name;
  std::string path(source.lines ? field : std::string_view());
  while (!path.empty()) {
    const toml::node_view<const toml::node> node = document.at_path(path);
    if (node) {
      const auto line = node.node()->source().begin.line;
      if (line > 0) return fmt::format("{}:{}: ", file, line);
    }
    // The nearest ancestor: drop the last ".key" or "[index]".
    const std::size_t cut = path.find_last_of(".[");
    path.resize(cut == std::string::npos ? 0 : cut);
  }
  return fmt::format("{}: ", file);
}

TomlTable::TomlTable(const toml::table& table, TomlSource source, std::string key_path)
    : table_(&table), source_(std::move(source)), key_path_(std::move(key_path)) {}

bool TomlTable::contains(std::string_view key) const {
  asked_.insert(std::string(key));
  return table_->contains(key);
}

bool TomlTable::present(std::string_view key) const { return table_->contains(key); }

std::string TomlTable::qualified(std::string_view key) const {
  return key_path_.empty() ? std::string(key) : fmt::format("{}.{}", key_path_, key);
}

std::string TomlTable::location_of(const toml::node& node) const {
  const auto line = node.source().begin.line;
  return line > 0 && source_.lines ? fmt::format("{}:{}: ", source_.name, line) : fmt::format("{}: ", source_.name);
}

std::string TomlTable::location(std::string_view key) const {
  const toml::node* n = table_->get(key);
  return location_of(n ? *n : static_cast<const toml::node&>(*table_));
}

std::string TomlTable::where(std::string_view key) const {
  return fmt::format("{}{}: ", location(key), qualified(key));
}

void TomlTable::fail(std::string_view key, std::string_view message) const {
  throw InputError(where(key) + std::string(message));
}

const toml::node* TomlTable::node(std::string_view key) const {
  asked_.insert(std::string(key));
  return table_->get(key);
}

const toml::node& TomlTable::required(std::string_view key, std::string_view expected) const {
  const toml::node* n = node(key);
  if (!n) {
    const std::string where = key_path_.empty() ? "the top level" : fmt::format("[{}]", key_path_);
    throw InputError(fmt::format("{}missing key '{}' in {}: expected {}", location_of(*table_), key, where, expected));
  }
  return *n;
}

namespace {
double as_number(const TomlTable& t, const toml::node& n, std::string_view key) {
  if (n.is_floating_point()) return *n.value<double>();
  if (n.is_integer()) return static_cast<double>(*n.value<long long>());
  t.fail(key, fmt::format("{}: expected a number", describe_type(n)));
}
}  // namespace

double TomlTable::number(std::string_view key, const std::function<void(std::string_view, double)>& check) const {
  const toml::node& n = required(key, "a number");
  const double value = as_number(*this, n, key);
  if (!check) return value;
  try {
    check(qualified(key), value);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}{}", location_of(n), e.what()));
  }
  return value;
}

std::optional<double> TomlTable::optional_number(std::string_view key,
                                                 const std::function<void(std::string_view, double)>& check) const {
  if (!contains(key)) return std::nullopt;
  return number(key, check);
}

long long TomlTable::integer(std::string_view key, long long lo, long long hi) const {
  const toml::node& n = required(key, "an integer");
  if (!n.is_integer()) fail(key, fmt::format("{}: expected an integer from {} to {}", describe_type(n), lo, hi));
  const long long value = *n.value<long long>();
  if (value < lo || value > hi) {
    fail(key, fmt::format("{}: expected an integer from {} to {}", value, lo, hi));
  }
  return value;
}

std::optional<long long> TomlTable::optional_integer(std::string_view key, long long lo, long long hi) const {
  if (!contains(key)) return std::nullopt;
  return integer(key, lo, hi);
}

std::optional<bool> TomlTable::optional_boolean(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (!n->is_boolean()) fail(key, fmt::format("{}: expected true or false", describe_type(*n)));
  return *n->value<bool>();
}

std::optional<std::string> TomlTable::optional_string(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (!n->is_string()) fail(key, fmt::format("{}: expected a string", describe_type(*n)));
  std::string text = *n->value<std::string>();
  // Strings end up in messages and output files: one line of printable text.
  if (printable(text, text.size()) != text) {
    fail(key, fmt::format("\"{}\": expected text without line breaks, tabs or other control characters", printable(text)));
  }
  return text;
}

std::vector<double> TomlTable::number_array(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) {
    throw InputError(fmt::format("{}missing key '{}' in [{}]: expected an array of numbers",
                                 location(key), key, key_path()));
  }
  const toml::array* array = n->as_array();
  if (!array || array->empty()) {
    fail(key, fmt::format("{}: expected a non-empty array of numbers", describe_type(*n)));
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    if (element.is_floating_point()) {
      values.push_back(*element.value<double>());
    } else if (element.is_integer()) {
      values.push_back(static_cast<double>(*element.value<long long>()));
    } else {
      fail(key, fmt::format("element {} is {}: expected a number", i, describe_type(element)));
    }
  }
  return values;
}

std::optional<std::vector<std::string>> TomlTable::optional_string_array(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* array = n->as_array();
  if (!array) fail(key, fmt::format("{}: expected an array of strings", describe_type(*n)));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = (*array)[i];
    const auto* text = element.as_string();
    if (!text) {
      throw InputError(fmt::format("{}{}[{}]: {}: expected a string", location_of(element), qualified(key), i,
                                   describe_type(element)));
    }
    if (printable(text->get(), text->get().size()) != text->get()) {
      throw InputError(fmt::format("{}{}[{}]: \"{}\": expected text without line breaks, tabs or other control "
                                   "characters",
                                   location_of(element), qualified(key), i, printable(text->get())));
    }
    out.push_back(text->get());
  }
  return out;
}

TomlTable TomlTable::table(std::string_view key) const {
  const toml::node& n = required(key, "a table");
  if (!n.is_table()) fail(key, fmt::format("{}: expected a table", describe_type(n)));
  return TomlTable(*n.as_table(), source_, qualified(key));
}

std::optional<TomlTable> TomlTable::optional_table(std::string_view key) const {
  if (!contains(key)) return std::nullopt;
  return table(key);
}

std::vector<TomlTable> TomlTable::table_array(std::string_view key, bool required_key) const {
  std::vector<TomlTable> tables;
  const toml::node* n = required_key ? &required(key, "an array of tables") : node(key);
  if (!n) return tables;
  const toml::array* array = n->as_array();
  if (!array) fail(key, fmt::format("{}: expected an array of tables", describe_type(*n)));
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const std::string path = fmt::format("{}[{}]", qualified(key), i);
    if (!element.is_table()) {
      throw InputError(fmt::format("{}{}: {}: expected a table", location_of(element), path, describe_type(element)));
    }
    tables.emplace_back(*element.as_table(), source_, path);
  }
  return tables;
}

void TomlTable::accept_only(std::initializer_list<std::string_view> keys) const {
  for (const std::string_view key : keys) contains(key);
  reject_unknown_keys();
}

std::string TomlTable::required_string(std::string_view key, std::string_view expected) const {
  if (!contains(key)) {
    throw InputError(fmt::format("{}missing key '{}' in [{}]: expected {}", location(key), key, key_path_, expected));
  }
  return *optional_string(key);
}

void TomlTable::reject_unknown_keys() const {
  for (const auto& [key, value] : *table_) {
    if (!asked_.contains(std::string_view(key.str()))) {
      std::string known;
      for (const auto& k : asked_) known += (known.empty() ? "" : ", ") + k;
      throw InputError(fmt::format("{}unknown key '{}': expected one of {}", location_of(value), printable(qualified(key.str())),
                                   known.empty() ? "(none)" : known));
    }
  }
}

}  // namespace stockbridge::io
