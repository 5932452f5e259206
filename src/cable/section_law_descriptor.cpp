#include "stockbridge/cable/section_law_descriptor.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "section_law_registry.hpp"
#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/section/section_law.hpp"

namespace stockbridge::cable {

const double* LoopNumbers::find(std::string_view key) const {
  for (const auto& [k, v] : numbers) {
    if (k == key) return &v;
  }
  return nullptr;
}

std::string joined_with_and(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t k = 0; k < items.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == items.size() ? " and " : ", ") + items[k];
  }
  return out;
}

int number_index(const SectionLawDescriptor& law, std::string_view key) {
  const std::span<const LawNumber> numbers = law.numbers();
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    if (numbers[k].key == key) return static_cast<int>(k);
  }
  return -1;
}

std::vector<std::string_view> law_keys(const SectionLawDescriptor& law) {
  std::vector<std::string_view> keys;
  for (const LawNumber& n : law.numbers()) keys.push_back(n.key);
  if (law.jenkin_elements()) keys.insert(keys.end(), {"jenkin", "lever_arm_cap"});
  return keys;
}

std::vector<const SectionLawDescriptor*> owners_of(std::string_view key, const SectionLawDescriptor* law) {
  std::vector<const SectionLawDescriptor*> owners;
  for (const SectionLawDescriptor* other : section_laws()) {
    if (other == law) continue;
    const std::vector<std::string_view> keys = law_keys(*other);
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) owners.push_back(other);
  }
  return owners;
}

std::string foreign_key_message(std::string_view key, const SectionLawDescriptor& law) {
  const std::vector<const SectionLawDescriptor*> owners = owners_of(key, &law);
  std::vector<std::string> titles, names;
  for (const SectionLawDescriptor* o : owners) {
    titles.push_back(std::string(o->title()));
    names.push_back(fmt::format("\"{}\"", o->name()));
  }
  const std::string whose = owners.empty() ? std::string("is a number of no section law")
                                           : fmt::format("is a number of the {} law{}", joined_with_and(titles),
                                                         owners.size() > 1 ? "s" : "");
  if (&law == &default_section_law() && !owners.empty()) {
    std::string set = names.front();
    for (std::size_t k = 1; k < names.size(); ++k) set += (k + 1 == names.size() ? " or " : ", ") + names[k];
    return fmt::format("{}: set law = {}", whose, set);
  }
  return fmt::format("{}: law = \"{}\" takes {}", whose, law.name(), law.takes());
}

std::span<const SectionLawDescriptor* const> section_laws() {
  static const std::vector<const SectionLawDescriptor*> laws = [] {
    std::vector<const SectionLawDescriptor*> all = registered_section_laws();
    std::sort(all.begin(), all.end(), [](auto* a, auto* b) { return a->order() < b->order(); });
    return all;
  }();
  return laws;
}

const SectionLawDescriptor& default_section_law() { return *section_laws().front(); }

const SectionLawDescriptor* find_section_law(std::string_view name) {
  for (const SectionLawDescriptor* law : section_laws()) {
    if (law->name() == name) return law;
  }
  return nullptr;
}

std::string section_law_names(bool quote) {
  std::string out;
  const auto laws = section_laws();
  for (std::size_t k = 0; k < laws.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == laws.size() ? " or " : ", ") +
           (quote ? fmt::format("\"{}\"", laws[k]->name()) : std::string(laws[k]->name()));
  }
  return out;
}

const SectionLawDescriptor& section_law(std::string_view name, std::string_view field) {
  if (const SectionLawDescriptor* law = find_section_law(name)) return *law;
  throw InvalidParameter(std::string(field), fmt::format(" = '{}': expected {}", name, section_law_names()));
}

std::string SectionLawDescriptor::takes() const {
  std::vector<std::string> keys;
  for (const LawNumber& n : numbers()) keys.push_back(std::string(n.key));
  if (jenkin_elements()) keys.push_back("jenkin");
  return joined_with_and(keys);
}

void SectionLawDescriptor::validate(const CableDescription& d) const {
  for (const LawNumber& n : numbers()) {
    d.number(n.key).check_values(n.key, [&n](std::string_view name, double v) { require_plausible(name, v, n.unit); });
  }
}

std::vector<const Profile*> SectionLawDescriptor::profiles(const CableDescription& d) const {
  std::vector<const Profile*> out;
  for (const LawNumber& n : numbers()) out.push_back(&d.number(n.key));
  return out;
}

std::unique_ptr<section::SectionLaw> SectionLawDescriptor::loop_section(const LoopNumbers& given) const {
  std::vector<double> values;
  for (const LawNumber& n : numbers()) values.push_back(*given.find(n.key));
  return section(values);
}

std::vector<std::vector<double>> SectionLawDescriptor::starts(const MasingEstimate&, FitKind) const {
  throw InvalidParameter("law", fmt::format(" = '{}': the {} law has no fit", name(), title()));
}

std::vector<double> SectionLawDescriptor::pack(const std::vector<double>& values) const {
  std::vector<double> x;
  const auto n = numbers();
  for (std::size_t k = 0; k < n.size(); ++k) {
    x.push_back(n[k].fit_scale == FitScale::logarithmic ? std::log(values[k]) : values[k]);
  }
  return x;
}

std::vector<double> SectionLawDescriptor::unpack(const std::vector<double>& x) const {
  std::vector<double> values;
  const auto n = numbers();
  for (std::size_t k = 0; k < n.size(); ++k) {
    values.push_back(n[k].fit_scale == FitScale::logarithmic ? std::exp(x[k]) : x[k]);
  }
  return values;
}

void SectionLawDescriptor::check_start(const std::vector<double>&, const std::string&) const {}

}  // namespace stockbridge::cable
