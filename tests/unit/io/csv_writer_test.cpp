// CSV output: numbers in shortest round-trip form, NaN as an empty cell, text cells
// (labels) before the numbers, quoted only when they must be (RFC 4180).

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
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

}  // namespace
}  // namespace stockbridge::io
