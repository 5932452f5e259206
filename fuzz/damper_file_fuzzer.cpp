// libFuzzer target: damper description files. Either one InputError line naming
// the file, or a damper (validated by construction) with finite arm matrices; nothing else.

#include <optional>

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/io/damper_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "damper.toml");
  std::optional<damper::Damper> damper;
  try {
    damper = io::read_damper_file(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  fuzz::require(!damper->arms().empty(), "an accepted damper has an arm");
  for (const damper::Arm& arm : damper->arms()) {
    fuzz::require(arm.mass_matrix().allFinite() && arm.load_vector().allFinite(), "finite arm matrices");
  }
  return 0;
}
