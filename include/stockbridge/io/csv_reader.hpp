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
/// missing file, an empty file or header, a missing or duplicated column, a row with
/// too few cells, a non-numeric or non-finite cell, or fewer than `min_rows` rows.
std::vector<std::vector<double>> read_csv_columns(const std::filesystem::path& path,
                                                  const std::vector<std::string>& names, std::size_t min_rows);

}  // namespace stockbridge::io
