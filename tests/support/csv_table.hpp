#pragma once
// A program's CSV output read back for tests: a header and rows of numbers.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace stockbridge::testing {

/// A CSV file as a header and rows of cells (empty cells as NaN).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  std::size_t index(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return c;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  std::vector<double> column(const std::string& name) const {
    const std::size_t c = index(name);
    std::vector<double> values;
    for (const auto& row : rows) values.push_back(row.at(c));
    return values;
  }
};

/// A line's cells; a quoted cell may hold commas and doubled quotes (RFC 4180).
inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  if (line.empty()) cells.clear();
  return cells;
}

inline Csv read_csv(const std::filesystem::path& path) {
  Csv csv;
  std::istringstream in(read_text(path));
  std::string line;
  std::getline(in, line);
  csv.header = split_csv_line(line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& cell : split_csv_line(line)) row.push_back(cell.empty() ? std::nan("") : std::strtod(cell.c_str(), nullptr));
    EXPECT_EQ(row.size(), csv.header.size()) << line;
    csv.rows.push_back(row);
  }
  return csv;
}

}  // namespace stockbridge::testing
