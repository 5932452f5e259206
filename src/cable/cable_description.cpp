#include "stockbridge/cable/cable_description.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

namespace {

void check_number_count(const CableDescription& d) {
  const std::size_t expected = d.law->numbers().size() - (number_index(*d.law, "ei") >= 0 ? 1 : 0);
  if (d.numbers.size() != expected) {
    throw InvalidParameter("numbers", fmt::format(": {} profiles for the {} law, which takes {}", d.numbers.size(),
                                                  d.law->title(), d.law->takes()));
  }
}

bool is_unset(const Profile& p) { return p == Profile::constant(0.0); }

}  // namespace

const Profile& CableDescription::number(std::string_view key) const {
  const int k = number_index(*law, key);
  if (k < 0) throw InvalidParameter(std::string(key), ": " + foreign_key_message(key, *law));
  if (key == "ei") return ei;
  const int ei_before = number_index(*law, "ei");
  const std::size_t index = static_cast<std::size_t>(ei_before >= 0 && ei_before < k ? k - 1 : k);
  if (index >= numbers.size()) {
    throw InvalidParameter(std::string(key), fmt::format(": not given (the cable has {} of the {} law's numbers)",
                                                         numbers.size(), law->title()));
  }
  return numbers[index];
}

Profile& CableDescription::number(std::string_view key) {
  const std::size_t expected = law->numbers().size() - (number_index(*law, "ei") >= 0 ? 1 : 0);
  if (numbers.size() < expected && number_index(*law, key) >= 0) numbers.resize(expected, Profile::constant(0.0));
  return const_cast<Profile&>(std::as_const(*this).number(key));
}

void CableDescription::validate() const {
  require_plausible("length", length, "m");
  require_in_range("sections", sections, min_sections, max_sections);
  const auto foreign = [this](std::string_view field) {
    throw InvalidParameter(std::string(field), ": " + foreign_key_message(field, *law));
  };
  if (number_index(*law, "ei") < 0 && !is_unset(ei)) foreign("ei");
  if (!law->jenkin_elements()) {
    if (!jenkin.empty()) foreign("jenkin");
    if (lever_arm_cap) foreign("lever_arm_cap");
  }
  check_number_count(*this);
  law->validate(*this);
  if (mirror_length) {
    require_plausible("mirror_length", *mirror_length, "m");
    if (length > 2.0 * *mirror_length) {
      throw_invalid("length", length,
                    fmt::format("at most twice mirror_length = {} m for the mirror method", *mirror_length));
    }
  }
  if (lever_arm_cap) require_plausible("lever_arm_cap", *lever_arm_cap, "m");
}

std::vector<UnusualValue> CableDescription::unusual_values() const {
  std::vector<UnusualValue> found;
  const auto check = [&found](const TypicalRange& range) {
    return [&found, &range](std::string_view name, double v) { check_typical(found, std::string(name), v, range); };
  };
  check_typical(found, "length", length, typical::cable_length);
  for (const LawNumber& n : law->numbers()) number(n.key).check_values(n.key, check(n.typical));
  for (std::size_t j = 0; j < jenkin.size(); ++j) {
    const std::string name = fmt::format("jenkin[{}]", j);
    jenkin[j].c.check_values(name + ".c", check(typical::jenkin_c));
    jenkin[j].h.check_values(name + ".h", check(typical::jenkin_h));
  }
  if (mirror_length) check_typical(found, "mirror_length", *mirror_length, typical::cable_length);
  return found;
}

double CableDescription::profile_position(double s) const {
  if (!mirror_length || s <= 0.5 * length) return s;
  return length - s;
}

std::vector<double> CableDescription::zone_boundaries() const {
  const std::vector<const Profile*> profiles = law->profiles(*this);
  const double ramp = zone_ramp_fraction * length;
  std::vector<double> boundaries;
  auto add = [&](double s) {
    if (s > ramp && s < length - ramp) boundaries.push_back(s);
  };
  for (const Profile* p : profiles) {
    const auto s = p->positions();
    for (std::size_t k = 1; k < s.size(); ++k) {
      if (s[k] - s[k - 1] >= ramp) continue;
      const double middle = 0.5 * (s[k - 1] + s[k]);
      if (!mirror_length) {
        add(middle);
        continue;
      }
      if (middle <= 0.5 * length) add(middle);  // read at s on the first half
      if (middle < 0.5 * length) add(length - middle);  // and at l - s on the second
    }
  }
  std::sort(boundaries.begin(), boundaries.end());
  // Boundaries closer than a ramp are one (the same zone edge in several profiles).
  std::vector<double> distinct;
  for (double b : boundaries) {
    if (distinct.empty() || b - distinct.back() >= ramp) distinct.push_back(b);
  }
  return distinct;
}

bool CableDescription::uses_modified_masing() const {
  for (const JenkinProfile& e : jenkin) {
    if (e.k0 > 0.0) return true;
  }
  return false;
}

CableDescription CableDescription::uniform(double length, int sections, double ei,
                                           std::vector<std::pair<double, double>> jenkin_c_h) {
  CableDescription d;
  d.length = length;
  d.sections = sections;
  d.ei = Profile::constant(ei);
  for (const auto& [c, h] : jenkin_c_h) d.jenkin.push_back({Profile::constant(c), Profile::constant(h), 0.0});
  return d;
}

CableDescription CableDescription::uniform(const SectionLawDescriptor& law, double length, int sections,
                                           const std::vector<double>& values) {
  CableDescription d;
  d.length = length;
  d.sections = sections;
  d.law = &law;
  for (std::size_t k = 0; k < law.numbers().size() && k < values.size(); ++k) {
    d.number(law.numbers()[k].key) = Profile::constant(values[k]);
  }
  return d;
}

LawValues CableDescription::values() const {
  LawValues out{law, {}};
  for (const LawNumber& n : law->numbers()) out.values.push_back(number(n.key).at(0.0));
  return out;
}

}  // namespace stockbridge::cable
