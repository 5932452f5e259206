// libFuzzer target: strand description files. Either one InputError line naming
// the file, or a strand whose bending-stiffness bounds are finite and ordered
// (or a NumericalError for sizes outside a double's range, as documented).

#include <cmath>

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/strand_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "strand.toml");
  strand::Strand strand;
  try {
    strand = io::read_strand_file(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  try {
    const strand::StrandBounds bounds = strand::strand_bounds(strand);
    fuzz::require(std::isfinite(bounds.ei_min) && std::isfinite(bounds.ei_max), "finite bounds");
    fuzz::require(bounds.ei_min > 0.0 && bounds.ei_min <= bounds.ei_max * (1.0 + 1e-12), "0 < ei_min <= ei_max");
  } catch (const NumericalError&) {
  }
  return 0;
}
