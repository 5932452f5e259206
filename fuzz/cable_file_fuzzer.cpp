// libFuzzer target: cable description files. Any input either fails with one
// InputError line that names the file, or gives a cable (validated by construction)
// that carries a load; any other exception, crash or sanitizer report is a finding.

#include <cmath>
#include <optional>

#include "fuzz_support.hpp"
#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/cable_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stockbridge;
  const auto path = fuzz::as_file(data, size, "cable.toml");
  std::optional<cable::Cable> cable;
  try {
    cable = io::read_cable_file(path);
  } catch (const InputError& e) {
    fuzz::require_one_line_naming(e.what(), path);
    return 0;
  }
  cable::Cantilever cantilever{*cable};
  cantilever.set_trial_loads(0.1, 0.5);
  const cable::CableState& s = cantilever.trial();
  fuzz::require(std::isfinite(s.rotation) && std::isfinite(s.deflection) && s.dissipated >= 0.0,
                "an accepted cable carries a small load with finite kinematics");
  return 0;
}
