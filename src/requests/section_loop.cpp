#include "stockbridge/requests/section_loop.hpp"

#include <memory>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/section/masing_section.hpp"
#include "stockbridge/section/regularised_section.hpp"

namespace stockbridge::requests {

section::LoopRecord section_loop(const section::MasingParameters& parameters, const section::SinusoidalDrive& drive,
                                 std::string_view law, double exponent) {
  std::unique_ptr<section::SectionLaw> section;
  if (law == "exact") {
    section = std::make_unique<section::MasingSection>(parameters);
  } else if (law == "regularised") {
    section::RegularisedOptions regularised;
    regularised.exponent = exponent;
    section = std::make_unique<section::RegularisedSection>(parameters, regularised);
  } else {
    throw InvalidParameter("law", fmt::format(" = '{}': expected exact or regularised", law));
  }
  return section::run_loop(*section, drive);
}

}  // namespace stockbridge::requests
