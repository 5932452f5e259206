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

std::string_view wind_in_time_name(WindInTime wind) { return wind == WindInTime::wake ? "wake" : "ebm"; }

WindInTime parse_wind_in_time(std::string_view name) {
  if (name == "ebm") return WindInTime::ebm;
  if (name == "wake") return WindInTime::wake;
  throw InvalidParameter("wind", fmt::format(" = '{}': expected \"ebm\" (the energy balance's own) or \"wake\" (the "
                                             "wake oscillator)",
                                             name));
}

void WakeParameters::validate() const {
  require_positive("epsilon", epsilon, "");
  require_positive("coupling", coupling, "");
  require_positive("lift_coefficient", lift_coefficient, "");
  require_positive("air_density", air_density, "kg/m^3");
}

}  // namespace stockbridge::span
