#include "stockbridge/span/time_settings.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

std::string_view beam_ends_name(BeamEnds ends) { return ends == BeamEnds::pinned ? "pinned" : "clamped"; }

BeamEnds parse_beam_ends(std::string_view name) {
  if (name == "pinned") return BeamEnds::pinned;
  if (name == "clamped") return BeamEnds::clamped;
  throw InvalidParameter("ends", fmt::format(" = '{}': expected \"pinned\" or \"clamped\"", name));
}

}  // namespace stockbridge::span
