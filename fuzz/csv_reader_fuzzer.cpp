// libFuzzer target: measured records (CSV). Either one InputError line naming the
// file, or the asked-for columns, equally long, at least the minimum row count,
// every value finite.

#include <cmath>

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "record.csv");
  std::vector<std::vector<double>> columns;
  try {
    columns = io::read_csv_columns(path, {"curvature_per_m", "moment_n_m"}, 2);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  fuzz::require(columns.size() == 2, "the two columns asked for");
  fuzz::require(columns[0].size() == columns[1].size() && columns[0].size() >= 2, "equal columns of >= 2 rows");
  for (const auto& column : columns) {
    for (const double v : column) fuzz::require(std::isfinite(v), "finite values");
  }
  return 0;
}
