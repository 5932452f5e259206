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
    throw InvalidParameter("law", fmt::format(" = '{}': expected exact or regularised (bouc-wen takes ei_min, ei_max "
                                              "and chi0 instead of ei and Jenkin elements)",
                                              law));
  }
  return section::run_loop(*section, drive);
}

section::LoopRecord bouc_wen_loop(const section::BoucWenParameters& parameters, const section::SinusoidalDrive& drive) {
  section::BoucWenSection section(parameters);
  return section::run_loop(section, drive);
}

std::vector<LoopSample> loop_samples(const section::LoopRecord& record) {
  std::vector<LoopSample> samples;
  for (std::size_t k = 0; k < record.curvature.size(); ++k) samples.push_back({&record, k});
  return samples;
}

Table<LoopSample> loop_table() {
  using S = LoopSample;
  return Table<S>({
      {"step", "", "the sample k = 0 .. cycles x points", ColumnKind::count,
       [](const S& s, std::size_t) { return static_cast<double>(s.step); }, {}},
      {"curvature_per_m", "1/m", "the prescribed curvature kappa = A sin(2 pi k / points)", ColumnKind::number,
       [](const S& s, std::size_t) { return s.record->curvature[s.step]; }, {}},
      {"moment_n_m", "N m", "the section's bending moment M", ColumnKind::number,
       [](const S& s, std::size_t) { return s.record->moment[s.step]; }, {}},
      {"dissipated_energy_j_per_m", "J/m", "what the sliders dissipated since the virgin state, per unit length",
       ColumnKind::number, [](const S& s, std::size_t) { return s.record->dissipated[s.step]; }, {}},
  });
}

}  // namespace stockbridge::requests
