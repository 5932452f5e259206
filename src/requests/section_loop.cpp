#include "stockbridge/requests/section_loop.hpp"

#include <algorithm>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/section/section_law.hpp"

namespace stockbridge::requests {

namespace {

/// The law `loop` was asked for by its name or a variant's.
const cable::SectionLawDescriptor* loop_law(std::string_view name) {
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    const std::vector<std::string_view> variants = law->loop_variants();
    if (law->name() == name || std::find(variants.begin(), variants.end(), name) != variants.end()) return law;
  }
  return nullptr;
}

std::string spelled_list(const std::vector<std::string_view>& keys, const LoopSpelling& spelling) {
  std::vector<std::string> spelled;
  for (std::string_view k : keys) spelled.push_back(spelling.key(k));
  return cable::joined_with_and(spelled);
}

}  // namespace

LoopSpelling command_line_spelling() {
  return {[](std::string_view key) {
            std::string option = "--" + std::string(key);
            std::replace(option.begin(), option.end(), '_', '-');
            return option;
          },
          [](std::string_view name) { return "--law " + std::string(name); }};
}

std::vector<std::string> loop_law_names() {
  std::vector<std::string> names;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    names.push_back(std::string(law->name()));
    for (std::string_view v : law->loop_variants()) names.push_back(std::string(v));
  }
  return names;
}

section::LoopRecord section_loop(const cable::LoopNumbers& given, const section::SinusoidalDrive& drive,
                                 const LoopSpelling& spelling) {
  const cable::SectionLawDescriptor* law = loop_law(given.law);
  if (!law) {
    throw InvalidParameter("law", fmt::format(" = '{}': expected {}", given.law, fmt::join(loop_law_names(), ", ")));
  }
  std::vector<std::string_view> own, foreign, missing;
  for (const cable::LawNumber& n : law->numbers()) {
    own.push_back(n.key);
    if (!given.find(n.key)) missing.push_back(n.key);
  }
  if (law->jenkin_elements()) own.push_back("jenkin");
  std::vector<std::string_view> accepted = own;
  for (const cable::LawNumber& n : law->loop_extras()) accepted.push_back(n.key);
  for (const auto& [key, value] : given.numbers) {
    if (std::find(accepted.begin(), accepted.end(), key) == accepted.end()) foreign.push_back(key);
  }
  if (!given.jenkin.empty() && !law->jenkin_elements()) foreign.push_back("jenkin");
  if (!foreign.empty()) {
    // The other law's keys, all of them: "--ei-min, --ei-max and --chi0 are the Bouc-Wen law's".
    const std::vector<const cable::SectionLawDescriptor*> owners = cable::owners_of(foreign.front(), law);
    std::vector<std::string_view> theirs;
    if (!owners.empty()) {
      for (const cable::LawNumber& n : owners.front()->numbers()) theirs.push_back(n.key);
      if (owners.front()->jenkin_elements()) theirs.push_back("jenkin");
    } else {
      theirs = foreign;
    }
    throw InvalidParameter(fmt::format("{} {} the {} law's: {} takes {}", spelled_list(theirs, spelling),
                                       theirs.size() > 1 ? "are" : "is",
                                       owners.empty() ? std::string("no") : std::string(owners.front()->title()),
                                       spelling.law(given.law), spelled_list(own, spelling)));
  }
  if (!missing.empty()) {
    // The law's numbers, each run of one unit followed by it: "--ei-min, --ei-max (N m^2) and --chi0 (1/m)".
    const auto numbers = law->numbers();
    std::vector<std::string> items;
    for (std::size_t k = 0; k < numbers.size(); ++k) {
      const bool last_of_unit = k + 1 == numbers.size() || numbers[k + 1].unit != numbers[k].unit;
      items.push_back(spelling.key(numbers[k].key) +
                      (last_of_unit && !numbers[k].unit.empty() ? fmt::format(" ({})", numbers[k].unit) : ""));
    }
    throw InvalidParameter(fmt::format("{} needs {}", spelling.law(given.law), cable::joined_with_and(items)));
  }
  const std::unique_ptr<section::SectionLaw> section = law->loop_section(given);
  return section::run_loop(*section, drive);
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
