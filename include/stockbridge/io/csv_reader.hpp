#pragma once
// Reading measured records from CSV: a header row of column names, ',' between
// cells, '.' as decimal separator; a UTF-8 byte-order mark and CRLF line ends are
// accepted, blank lines skipped, columns not asked for ignored.

#include <filesystem>
#include <string>
#include <vector>

namespace stockbridge::io {

/// The named columns, in the order asked, one value per data row. Throws InputError
/// with one line naming the file (and line and column where it applies) for a
/// missing file, an empty file or header, a missing or duplicated column, a row of
/// more or fewer cells than the header (a decimal comma splits a cell in two), a
/// non-numeric or non-finite cell, or fewer than `min_rows` rows.
std::vector<std::vector<double>> read_csv_columns(const std::filesystem::path& path,
                                                  const std::vector<std::string>& names, std::size_t min_rows);

/// The named columns as read_csv_columns reads them, and the file's line number of
/// each data row (for messages about a row's values).
struct CsvRows {
  std::vector<std::vector<double>> columns;
  std::vector<std::size_t> lines;
};
CsvRows read_csv_rows(const std::filesystem::path& path, const std::vector<std::string>& names, std::size_t min_rows);

/// Every cell as text (trimmed; cells with ',' are not supported), with the header
/// and each data row's line number: for files of labels and numbers (a line's spans).
/// InputError for a missing or empty file, a header separated by ';' or tabs, or a
/// row of more or fewer cells than the header.
struct CsvCells {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< each as long as the header
  std::vector<std::size_t> lines;
};
CsvCells read_csv_cells(const std::filesystem::path& path);

/// The header's column names (to choose between alternative columns); InputError
/// for a missing or empty file, or a header of one cell separated by ';' or tabs.
std::vector<std::string> read_csv_header(const std::filesystem::path& path);

}  // namespace stockbridge::io
