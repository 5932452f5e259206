#pragma once
// CSV output in the project's convention: a header row of snake_case names with
// the unit as suffix, one row per point, '.' as decimal separator, numbers in
// their shortest round-trip form. A NaN is written as an empty cell: it marks a
// value the program does not trust (a point that did not converge).

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stockbridge::io {

class CsvWriter {
 public:
  explicit CsvWriter(std::vector<std::string> header);

  /// Appends one row; it must have as many values as the header has names.
  void add_row(std::span<const double> values);
  void add_row(std::initializer_list<double> values) { add_row(std::span<const double>(values.begin(), values.size())); }
  /// Appends one row of labels and numbers: `labels` fill the first columns (a cell
  /// with ',', '"' or a line break is quoted, RFC 4180), `values` the rest, as add_row
  /// writes them.
  void add_row(std::span<const std::string> labels, std::span<const double> values);

  std::size_t columns() const { return columns_; }
  const std::string& text() const { return text_; }

 private:
  std::size_t columns_;
  std::string text_;
};

}  // namespace stockbridge::io
