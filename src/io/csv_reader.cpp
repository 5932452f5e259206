#include "stockbridge/io/csv_reader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/input_file.hpp"

namespace stockbridge::io {

namespace {

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    std::string cell = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t first = cell.find_first_not_of(" \t");
    const std::size_t last = cell.find_last_not_of(" \t");
    cells.push_back(first == std::string::npos ? std::string() : cell.substr(first, last - first + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

/// The file opened at its header: the first non-blank line, split into cells (a
/// byte-order mark and a CR removed); `line_number` is the header's line.
struct OpenedCsv {
  std::ifstream in;
  std::string header_line;
  std::vector<std::string> header;
  std::size_t line_number = 0;
};

OpenedCsv open_csv(const std::filesystem::path& path) {
  const std::string file = path.string();
  existing_input_file(path);
  OpenedCsv csv{std::ifstream(path, std::ios::binary), {}, {}, 0};
  std::string line;
  while (std::getline(csv.in, line)) {
    ++csv.line_number;
    if (csv.line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    csv.header_line = line;
    csv.header = split_cells(line);
    return csv;
  }
  throw InputError(fmt::format("{}: empty file: expected a header row and data", file));
}

/// A data row's cells, as many as the header's: fewer (a cell left out) or more (a
/// decimal comma, "1,5", or a ',' inside a cell) is refused, naming the line.
void require_cells(const std::string& file, std::size_t line_number, std::size_t cells, std::size_t header_cells) {
  if (cells == header_cells) return;
  throw InputError(fmt::format("{}:{}: {} cells: expected {}, as the header has ({})", file, line_number, cells,
                               header_cells,
                               cells > header_cells ? "a decimal comma? '.' is the decimal separator, and a cell "
                                                      "cannot hold a ','"
                                                    : "an empty cell is written as nothing between two commas"));
}

}  // namespace

std::vector<std::string> read_csv_header(const std::filesystem::path& path) {
  const OpenedCsv csv = open_csv(path);
  const std::string& line = csv.header_line;
  if (csv.header.size() == 1 && line.find_first_of(";\t") != std::string::npos) {
    throw InputError(fmt::format("{}:{}: header '{}' is separated by ';' or tabs: expected ',' between columns and "
                                 "'.' as decimal separator",
                                 path.string(), csv.line_number, printable(line)));
  }
  return csv.header;
}

CsvRows read_csv_rows(const std::filesystem::path& path, const std::vector<std::string>& names, std::size_t min_rows) {
  const std::string file = path.string();
  OpenedCsv csv = open_csv(path);
  std::vector<std::size_t> index(names.size(), std::string::npos);
  const std::vector<std::string>& header = csv.header;
  const std::size_t header_cells = header.size();
  for (std::size_t c = 0; c < header.size(); ++c) {
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (header[c] != names[k]) continue;
      if (index[k] != std::string::npos) {
        throw InputError(fmt::format("{}:{}: column '{}' appears twice (columns {} and {})", file, csv.line_number,
                                     names[k], index[k] + 1, c + 1));
      }
      index[k] = c;
    }
  }
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& line = csv.header_line;
    if (index[k] == std::string::npos && (line.find(';') != std::string::npos || line.find('\t') != std::string::npos)) {
      throw InputError(fmt::format("{}:{}: header '{}' is separated by ';' or tabs: expected ',' between columns and "
                                   "'.' as decimal separator",
                                   file, csv.line_number, printable(line)));
    }
    if (index[k] == std::string::npos) {
      throw InputError(fmt::format("{}:{}: missing column '{}': expected a header with {}", file, csv.line_number,
                                   names[k], fmt::join(names, ",")));
    }
  }
  CsvRows rows;
  rows.columns.resize(names.size());
  std::string line;
  std::size_t line_number = csv.line_number;
  while (std::getline(csv.in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> cells = split_cells(line);
    require_cells(file, line_number, cells.size(), header_cells);
    for (std::size_t k = 0; k < names.size(); ++k) {
      const std::string& cell = cells[index[k]];
      double value = 0.0;
      const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
      if (cell.empty() || error != std::errc() || end != cell.data() + cell.size()) {
        throw InputError(fmt::format("{}:{}: column '{}' = '{}': expected a number ('.' as decimal separator)", file,
                                     line_number, names[k], printable(cell)));
      }
      if (!std::isfinite(value)) {
        throw InputError(fmt::format("{}:{}: column '{}' = {}: expected a finite number", file, line_number, names[k],
                                     cell));
      }
      rows.columns[k].push_back(value);
    }
    rows.lines.push_back(line_number);
  }
  if (rows.lines.size() < min_rows) {
    throw InputError(fmt::format("{}: {} data rows: expected at least {}", file, rows.lines.size(), min_rows));
  }
  return rows;
}

CsvCells read_csv_cells(const std::filesystem::path& path) {
  CsvCells out;
  out.header = read_csv_header(path);
  OpenedCsv csv = open_csv(path);
  std::string line;
  std::size_t line_number = csv.line_number;
  while (std::getline(csv.in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::vector<std::string> cells = split_cells(line);
    require_cells(path.string(), line_number, cells.size(), out.header.size());
    out.rows.push_back(std::move(cells));
    out.lines.push_back(line_number);
  }
  return out;
}

std::vector<std::vector<double>> read_csv_columns(const std::filesystem::path& path,
                                                  const std::vector<std::string>& names, std::size_t min_rows) {
  return read_csv_rows(path, names, min_rows).columns;
}

}  // namespace stockbridge::io
