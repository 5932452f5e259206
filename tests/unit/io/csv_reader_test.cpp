// Reading measured CSV records: what is accepted, and one precise line for each mistake.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "support/temp_file.hpp"

namespace stockbridge::io {
namespace {

std::filesystem::path csv_directory() {
  return std::filesystem::temp_directory_path() / ("stockbridge-csv-" + std::to_string(::getpid()));
}

std::vector<std::vector<double>> read_columns(const std::string& contents, std::size_t min_rows = 1) {
  return read_csv_columns(testing::write_temp_file(csv_directory(), "r.csv", contents), {"curvature_per_m", "moment_n_m"},
                          min_rows);
}

std::string csv_error_of(const std::string& contents, std::size_t min_rows = 1) {
  try {
    read_columns(contents, min_rows);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(CsvReader, ReadsNamedColumnsInAnyOrderIgnoringOthers) {
  const auto c = read_columns("step,moment_n_m,extra,curvature_per_m\n0,1.5,x,0.1\n1,-2e-1,y,-0.25\n");
  EXPECT_EQ(c[0], (std::vector<double>{0.1, -0.25}));
  EXPECT_EQ(c[1], (std::vector<double>{1.5, -0.2}));
}

TEST(CsvReader, AcceptsBomCrlfAndBlankLines) {
  const auto c = read_columns("\xEF\xBB\xBF" "curvature_per_m,moment_n_m\r\n0.1,1\r\n\r\n0.2, 2 \r\n");
  EXPECT_EQ(c[0], (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(c[1], (std::vector<double>{1.0, 2.0}));
}

TEST(CsvReader, EachMistakeGetsOnePreciseLine) {
  const std::string f = (csv_directory() / "r.csv").string();
  EXPECT_EQ(csv_error_of(""), f + ": empty file: expected a header row and data");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment\n0.1,1\n"),
            f + ":1: missing column 'moment_n_m': expected a header with curvature_per_m,moment_n_m");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m,moment_n_m\n0.1,1,2\n"),
            f + ":1: column 'moment_n_m' appears twice (columns 2 and 3)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0.1,1\n0.2,abc\n"),
            f + ":3: column 'moment_n_m' = 'abc': expected a number ('.' as decimal separator)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0,1\n0;2\n"),
            f + ":3: 1 cells: expected 2, as the header has (an empty cell is written as nothing between two commas)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0,1\n0;2,\n"),
            f + ":3: column 'curvature_per_m' = '0;2': expected a number ('.' as decimal separator)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0,1\n2\n"),
            f + ":3: 1 cells: expected 2, as the header has (an empty cell is written as nothing between two commas)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0.1,nan\n"), f + ":2: column 'moment_n_m' = nan: expected a finite number");
  // A decimal comma splits a cell in two: the row is refused, not read as two numbers.
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0.1,1,5\n0,\n"),
            f + ":2: 3 cells: expected 2, as the header has (a decimal comma? '.' is the decimal separator, and a cell "
                "cannot hold a ',')");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0.1,1\n0,\n"),
            f + ":3: column 'moment_n_m' = '': expected a number ('.' as decimal separator)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n", 8), f + ": 0 data rows: expected at least 8");
  // Fuzzing finding: a lone CR or other control character inside a quoted cell or
  // header made the message two lines; they are escaped (and long text is cut).
  EXPECT_EQ(csv_error_of("curvature_per_m;moment\rx\n0,1\n"),
            f + ":1: header 'curvature_per_m;moment\\rx' is separated by ';' or tabs: expected ',' between columns and "
                "'.' as decimal separator");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0.1,1\x1b[2J\n"),
            f + ":2: column 'moment_n_m' = '1\\x1b[2J': expected a number ('.' as decimal separator)");
  EXPECT_EQ(csv_error_of("curvature_per_m,moment_n_m\n0.1," + std::string(100, '9') + "x\n"),
            f + ":2: column 'moment_n_m' = '" + std::string(60, '9') + "...': expected a number ('.' as decimal separator)");
  EXPECT_THROW(read_csv_columns(csv_directory() / "missing.csv", {"a"}, 1), InputError);
}

}  // namespace
}  // namespace stockbridge::io
