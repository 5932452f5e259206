// CSV output: numbers in shortest round-trip form, NaN as an empty cell, text cells
// (labels) before the numbers, quoted only when they must be (RFC 4180); a file
// written piece by piece appears whole at its commit or not at all.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/csv_writer.hpp"

namespace stockbridge::io {
namespace {

TEST(CsvWriter, WritesLabelsThenNumbers) {
  CsvWriter csv({"arm", "state", "mode", "frequency_hz"});
  const std::vector<std::string> plain{"left", "stick"}, awkward{"a,b", "say \"hi\""};
  const std::vector<double> values{1.0, 21.25}, missing{2.0, std::nan("")};
  csv.add_row(plain, values);
  csv.add_row(awkward, missing);
  csv.add_row({3.0, 4.0, 5.0, 0.1});
  EXPECT_EQ(csv.text(), "arm,state,mode,frequency_hz\nleft,stick,1,21.25\n\"a,b\",\"say \"\"hi\"\"\",2,\n3,4,5,0.1\n");
  EXPECT_THROW(csv.add_row(plain, std::vector<double>{1.0}), Error);
}

std::string text_of(const std::filesystem::path& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

std::size_t files_in(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

// Pieces written and committed replace the file; pieces written and dropped (an
// error, Ctrl-C) leave the old file as it was and no temporary file beside it.
TEST(AtomicFileWriter, ReplacesTheFileAtItsCommitOnly) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "stockbridge-atomic-writer";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "rows.csv";
  std::ofstream(path) << "old\n";
  {
    AtomicFileWriter file(path);
    file.write("a,b\n");
    file.write("1,2\n");
    EXPECT_EQ(text_of(path), "old\n");
    EXPECT_EQ(files_in(dir), 2u);  // the old file and the temporary one
  }
  EXPECT_EQ(text_of(path), "old\n");
  EXPECT_EQ(files_in(dir), 1u);
  {
    AtomicFileWriter file(path);
    file.write("a,b\n");
    file.write("1,2\n");
    file.commit();
  }
  EXPECT_EQ(text_of(path), "a,b\n1,2\n");
  EXPECT_EQ(files_in(dir), 1u);
  EXPECT_THROW(AtomicFileWriter(dir / "missing" / "rows.csv"), OutputError);
  EXPECT_THROW(AtomicFileWriter{dir}, OutputError);  // a directory
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace stockbridge::io
