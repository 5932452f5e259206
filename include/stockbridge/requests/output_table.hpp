#pragma once
// Outputs described once. Every table the front ends show (a CSV file, Python's
// arrays, a --json object of one row, the docs' column tables) is a list of
// quantities, each with its name (snake_case, the unit as suffix), unit, meaning
// and how to read it from a row. A family of quantities, one per arm or one per
// damper and end, has a pattern name ("<arm>_power_w"); a table expands it with
// the members' prefixes ("left_power_w", "right_power_w"); a family named by its
// placeholder alone ("<variable>") is a column per member, named as the member. Adding a column is
// adding one quantity: the CSV header and rows, the JSON keys, Python's keys and
// the docs' table (a test compares them with docs/) all follow from it.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/json_writer.hpp"

namespace stockbridge::requests {

/// A value with nothing to show: an empty cell (CSV), null (JSON), NaN (Python).
inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
/// Pa in a MPa: the outputs give stresses in MPa.
inline constexpr double kPascalPerMegapascal = 1e6;
/// A stress as the outputs give it: MPa from Pa.
inline constexpr double megapascal_of(double pascal) { return pascal / kPascalPerMegapascal; }

/// What a column holds: a number (NaN where not trusted: an empty cell, null), a
/// count, a flag (1 or 0, NaN where not trusted; Python: bool, false there), or a label (text).
enum class ColumnKind { number, count, flag, label };

/// One output quantity of rows of type Row.
template <class Row>
struct Quantity {
  std::string name;     ///< "velocity_m_s"; a family's pattern starts with its placeholder ("<arm>_power_w")
  std::string unit;     ///< as the docs write it ("m/s", "N s/m"); empty: a pure number
  std::string meaning;  ///< one line, the docs' table's third cell
  ColumnKind kind = ColumnKind::number;
  /// The value of a row (member `member` of a family; 0 otherwise), for every kind but label.
  std::function<double(const Row&, std::size_t member)> number;
  /// The text of a row, for a label.
  std::function<std::string(const Row&, std::size_t member)> label;
};

/// A number only a converged row has: `value` where `converged(row)`, NaN (an empty
/// cell, null) elsewhere: a number the program cannot stand behind is never shown.
template <class Row>
Quantity<Row> masked_quantity(std::string name, std::string unit, std::string meaning,
                              std::function<bool(const Row&)> converged,
                              std::function<double(const Row&, std::size_t member)> value) {
  return {std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
          [converged = std::move(converged), value = std::move(value)](const Row& row, std::size_t member) {
            return converged(row) ? value(row, member) : std::numeric_limits<double>::quiet_NaN();
          },
          {}};
}

/// How the docs list a quantity.
struct QuantityDoc {
  std::string name;  ///< the pattern for a family
  std::string unit;
  std::string meaning;
  bool operator==(const QuantityDoc&) const = default;
};

/// A table's values, column by column: what a CSV writes and Python's arrays hold.
struct TableValues {
  struct Column {
    std::string name;  ///< as the CSV's header names it
    ColumnKind kind = ColumnKind::number;
    std::vector<double> numbers;      ///< one per row, every kind but label
    std::vector<std::string> labels;  ///< one per row, a label
    /// A family member's column: the family's name without its placeholder ("x_m"),
    /// and the member's index; empty for a column of its own.
    std::string family;
    std::size_t member = 0;
  };
  std::vector<Column> columns;
  std::size_t rows = 0;

  std::vector<std::string> names() const;
  /// The column of that name; std::out_of_range if there is none.
  const Column& column(std::string_view name) const;
  /// The CSV text (io::CsvWriter: the label columns first, then the rest); without
  /// its header row with `header` false (rows streamed to a file one by one).
  std::string csv(bool header = true) const;
  /// Row r as a JSON object: a number (null where NaN), a count as an integer, a
  /// flag as true or false (null where NaN), a label as a string.
  io::JsonObject json_row(std::size_t r) const;
};

/// A family's placeholder and its members' prefixes ({"<arm>", {"left", "right"}}).
using Members = std::vector<std::pair<std::string, std::vector<std::string>>>;

template <class Row>
class Table {
 public:
  /// Consecutive quantities of one family are expanded member by member (each
  /// member's quantities together); a placeholder without members is an error.
  explicit Table(std::vector<Quantity<Row>> quantities, Members members = {})
      : quantities_(std::move(quantities)), members_(std::move(members)) {
    for (std::size_t q = 0; q < quantities_.size();) {
      const std::string placeholder = placeholder_of(quantities_[q].name);
      std::size_t end = q + 1;
      while (!placeholder.empty() && end < quantities_.size() && placeholder_of(quantities_[end].name) == placeholder) {
        ++end;
      }
      const std::vector<std::string>* prefixes = placeholder.empty() ? nullptr : &members_of(placeholder);
      const std::size_t count = prefixes ? prefixes->size() : 1;
      for (std::size_t m = 0; m < count; ++m) {
        for (std::size_t i = q; i < end; ++i) {
          const std::string& name = quantities_[i].name;
          // A family named by its placeholder alone is its members' names ("<variable>").
          const std::string base =
              prefixes && name.size() > placeholder.size() ? name.substr(placeholder.size() + 1) : std::string();
          const std::string column = !prefixes ? name : base.empty() ? (*prefixes)[m] : (*prefixes)[m] + "_" + base;
          columns_.push_back({i, m, column, base});
        }
      }
      q = end;
    }
  }

  const std::vector<Quantity<Row>>& quantities() const { return quantities_; }
  /// The CSV's header.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Expanded& c : columns_) out.push_back(c.name);
    return out;
  }
  /// The quantities as the docs' table lists them (families by their pattern).
  std::vector<QuantityDoc> docs() const {
    std::vector<QuantityDoc> out;
    for (const Quantity<Row>& q : quantities_) out.push_back({q.name, q.unit, q.meaning});
    return out;
  }
  /// The values of `rows`, in order.
  TableValues values(const std::vector<const Row*>& rows) const {
    TableValues out;
    out.rows = rows.size();
    for (const Expanded& c : columns_) {
      const Quantity<Row>& q = quantities_[c.quantity];
      TableValues::Column column{c.name, q.kind, {}, {}, c.family, c.member};
      if (q.kind == ColumnKind::label) {
        column.labels.reserve(rows.size());
      } else {
        column.numbers.reserve(rows.size());
      }
      for (const Row* row : rows) {
        if (q.kind == ColumnKind::label) {
          column.labels.push_back(q.label(*row, c.member));
        } else {
          column.numbers.push_back(q.number(*row, c.member));
        }
      }
      out.columns.push_back(std::move(column));
    }
    return out;
  }
  TableValues values(const std::vector<Row>& rows) const {
    std::vector<const Row*> pointers;
    for (const Row& row : rows) pointers.push_back(&row);
    return values(pointers);
  }
  TableValues values(const Row& row) const { return values(std::vector<const Row*>{&row}); }

 private:
  struct Expanded {
    std::size_t quantity;
    std::size_t member;
    std::string name;
    std::string family;
  };
  /// "<arm>" of "<arm>_power_w", "<damper>_end<k>" of "<damper>_end<k>_power_w"; empty for a plain name.
  std::string placeholder_of(const std::string& name) const {
    for (const auto& [placeholder, prefixes] : members_) {
      if (name == placeholder || name.starts_with(placeholder + "_")) return placeholder;
    }
    if (name.starts_with("<")) throw std::logic_error("output table: no members for the family " + name);
    return {};
  }
  const std::vector<std::string>& members_of(const std::string& placeholder) const {
    for (const auto& [p, prefixes] : members_) {
      if (p == placeholder) return prefixes;
    }
    throw std::logic_error("output table: no members for " + placeholder);
  }

  std::vector<Quantity<Row>> quantities_;
  Members members_;
  std::vector<Expanded> columns_;
};

/// A CSV file of `table`'s rows, written as they come: in the end the text
/// `table.values(rows).csv()` gives, but nothing held beyond one row's text. It
/// appears whole at `commit` or not at all (io::AtomicFileWriter).
template <class Row>
class CsvFile {
 public:
  CsvFile(const std::filesystem::path& path, const Table<Row>& table) : table_(table), file_(path) {
    file_.write(table.values(std::vector<const Row*>{}).csv());
  }
  void add(const Row& row) { file_.write(table_.values(row).csv(false)); }
  void commit() { file_.commit(); }

 private:
  const Table<Row>& table_;
  io::AtomicFileWriter file_;
};

/// Writes `rows` (Row values or pointers) to a CSV file at `path`, row by row (CsvFile).
template <class Row, class Rows>
void write_csv_file(const std::filesystem::path& path, const Table<Row>& table, const Rows& rows) {
  CsvFile<Row> file(path, table);
  for (const auto& row : rows) {
    if constexpr (std::is_pointer_v<std::decay_t<decltype(row)>>) {
      file.add(*row);
    } else {
      file.add(row);
    }
  }
  file.commit();
}

/// The markdown table the docs give for these quantities:
/// "| column | unit | meaning |" rows, names in backticks, '|' in a meaning escaped.
std::string docs_table(const std::vector<QuantityDoc>& quantities);

/// How tables name each member of a family from the names a file gives (an arm's,
/// a damper file's stem): the names themselves where every one is unique, made of
/// letters, digits and '_', and none of them `reserved`; else `fallback`1,
/// `fallback`2, ... for all.
std::vector<std::string> column_prefixes(const std::vector<std::string>& names, std::string_view fallback,
                                         const std::vector<std::string>& reserved = {});

}  // namespace stockbridge::requests
