#pragma once
// How a span is stepped in time (span/conductor_in_time.hpp; `stockbridge
// simulate` and `span --check-time`), as the span file gives it: the clamps' hold
// on the conductor ([span] ends) and the mesh, step and length of the run ([time]).
// The energy balance does not use them.

#include <string_view>

namespace stockbridge::span {

/// How the conductor is held at the span's two clamps.
enum class BeamEnds {
  pinned,   ///< no displacement, the slope free
  clamped,  ///< no displacement, no slope (the suspension clamps)
};
/// "pinned" or "clamped".
std::string_view beam_ends_name(BeamEnds ends);
/// "pinned" or "clamped"; InvalidParameter naming "ends" otherwise.
BeamEnds parse_beam_ends(std::string_view name);

/// A run in time's settings, the defaults fine enough that the dampers' third and
/// fifth harmonics are resolved too (10 elements a wavelength at 3 f;
/// docs/time-domain.md).
struct TimeSettings {
  BeamEnds ends = BeamEnds::clamped;  ///< [span] ends
  int elements_per_wavelength = 30;   ///< at the drive frequency, 4 to 1000
  int steps_per_period = 160;         ///< of the drive, 8 to 100000
  double duration_s = 60.0;           ///< simulated at most, > 0
};

}  // namespace stockbridge::span
