// libFuzzer target: damper description files. Either one InputError line naming
// the file, or a damper whose arms the model builds; nothing else.

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/io/damper_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "damper.toml");
  damper::DamperDescription description;
  try {
    description = io::read_damper_file(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  fuzz::require(!description.arms.empty(), "an accepted damper has an arm");
  for (const damper::ArmDescription& arm : description.arms) {
    const damper::Arm built(arm);  // InvalidParameter here would be a reader bug
    fuzz::require(built.mass_matrix().allFinite() && built.load_vector().allFinite(), "finite arm matrices");
  }
  return 0;
}
