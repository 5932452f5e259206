// libFuzzer target: measured impedance sheets (identify impedance's input, a span's
// [[damper]] impedance = ...). Either one InputError line naming the file, or a
// measurement whose sheet (at least two curves) or refusal (InvalidParameter, one
// line) is clean, and whose interpolated Z is finite wherever the sheet gives it.

#include <cmath>
#include <optional>

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/span/impedance_sheet.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "sheet.csv");
  std::optional<io::MeasuredImpedanceFile> file;
  try {
    file = io::load_measured_impedance(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  try {
    const span::ImpedanceSheet sheet(file->measurement, "sheet");
    const span::Interval range = sheet.frequency_range();
    fuzz::require(range.lo <= range.hi, "a sheet's frequencies in order");
    for (const double t : {0.0, 0.37, 1.0}) {
      const double f = range.lo * std::pow(range.hi / range.lo, t);
      for (const span::SheetNode& node : sheet.nodes_at(f)) {
        fuzz::require(std::isfinite(node.velocity) && std::isfinite(std::abs(node.impedance)), "finite nodes");
      }
    }
  } catch (const InvalidParameter& e) {
    const std::string message = e.what();
    fuzz::require(!message.empty() && message.find('\n') == std::string::npos, "a refused sheet is one line");
  }
  return 0;
}
