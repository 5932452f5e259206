// libFuzzer target: cable description files. Any input either fails with one
// InputError line that names the file, or gives a description the model accepts
// (the cable builds and carries a load); any other exception, crash or sanitizer
// report is a finding.

#include <cmath>

#include "fuzz_support.hpp"
#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/cable_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "cable.toml");
  cable::CableDescription description;
  try {
    description = io::read_cable_file(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  // Accepted: the model must accept it too (InvalidParameter here is a reader bug).
  cable::Cantilever cantilever{cable::Cable(description)};
  cantilever.set_trial_loads(0.1, 0.5);
  const cable::CableState& s = cantilever.trial();
  fuzz::require(std::isfinite(s.rotation) && std::isfinite(s.deflection) && s.dissipated >= 0.0,
                "an accepted cable carries a small load with finite kinematics");
  return 0;
}
