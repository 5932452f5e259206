#include "stockbridge/cable/cable_description.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

std::string_view section_law_name(SectionLawKind law) { return law == SectionLawKind::bouc_wen ? "bouc-wen" : "masing"; }

namespace {

/// A field of the other law set on a cable of this one (the words of the cable file's reader).
[[noreturn]] void throw_other_law(std::string_view field, SectionLawKind law) {
  throw InvalidParameter(std::string(field), law == SectionLawKind::bouc_wen
                                                 ? ": is a number of the Masing law: law = \"bouc-wen\" takes ei_min, "
                                                   "ei_max and chi0"
                                                 : ": is a number of the Bouc-Wen law: set law = \"bouc-wen\"");
}

bool is_unset(const Profile& p) { return p == Profile::constant(0.0); }

/// ei_max >= ei_min everywhere: both piecewise linear and held beyond their ends, so
/// their difference is too, with its corners at either table's points.
void require_ei_max_at_least_ei_min(const BoucWenProfiles& p) {
  std::vector<double> corners(p.ei_min.positions().begin(), p.ei_min.positions().end());
  corners.insert(corners.end(), p.ei_max.positions().begin(), p.ei_max.positions().end());
  for (double s : corners) {
    if (p.ei_max.at(s) < p.ei_min.at(s)) {
      throw InvalidParameter("ei_max", fmt::format(" = {} at s = {} m: below ei_min = {} N m^2 there (EI_max is the "
                                                   "no-slip stiffness, EI_min the free wires')",
                                                   p.ei_max.at(s), s, p.ei_min.at(s)));
    }
  }
}

void validate_bouc_wen(const CableDescription& d) {
  if (!is_unset(d.ei)) throw_other_law("ei", d.law);
  if (!d.jenkin.empty()) throw_other_law("jenkin", d.law);
  if (d.lever_arm_cap) throw_other_law("lever_arm_cap", d.law);
  const auto plausible = [](const char* unit) {
    return [unit](std::string_view name, double v) { require_plausible(name, v, unit); };
  };
  d.bouc_wen.ei_min.check_values("ei_min", plausible("N m^2"));
  d.bouc_wen.ei_max.check_values("ei_max", plausible("N m^2"));
  d.bouc_wen.chi0.check_values("chi0", plausible("1/m"));
  require_ei_max_at_least_ei_min(d.bouc_wen);
}

}  // namespace

void CableDescription::validate() const {
  require_plausible("length", length, "m");
  require_in_range("sections", sections, min_sections, max_sections);
  if (law == SectionLawKind::bouc_wen) {
    validate_bouc_wen(*this);
  } else {
    if (!(bouc_wen == BoucWenProfiles{})) throw_other_law("ei_min", law);
    ei.check_values("ei", [](std::string_view name, double v) { require_plausible(name, v, "N m^2"); });
  }
  for (std::size_t j = 0; j < jenkin.size(); ++j) {
    const std::string name = fmt::format("jenkin[{}]", j);
    jenkin[j].c.check_values(name + ".c", [](std::string_view n, double v) { require_plausible(n, v, "N m^2"); });
    jenkin[j].h.check_values(name + ".h", [](std::string_view n, double v) { require_plausible(n, v, "N m"); });
    require_plausible_or_zero(name + ".k0", jenkin[j].k0, "N");
  }
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
  if (law == SectionLawKind::bouc_wen) {
    bouc_wen.ei_min.check_values("ei_min", check(typical::ei));
    bouc_wen.ei_max.check_values("ei_max", check(typical::ei));
    bouc_wen.chi0.check_values("chi0", check(typical::bouc_wen_chi0));
  } else {
    ei.check_values("ei", check(typical::ei));
  }
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
  std::vector<const Profile*> profiles;
  if (law == SectionLawKind::bouc_wen) {
    profiles = {&bouc_wen.ei_min, &bouc_wen.ei_max, &bouc_wen.chi0};
  } else {
    profiles.push_back(&ei);
    for (const JenkinProfile& e : jenkin) profiles.insert(profiles.end(), {&e.c, &e.h});
  }
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

CableDescription CableDescription::uniform_bouc_wen(double length, int sections, double ei_min, double ei_max,
                                                    double chi0) {
  CableDescription d;
  d.length = length;
  d.sections = sections;
  d.law = SectionLawKind::bouc_wen;
  d.bouc_wen = {Profile::constant(ei_min), Profile::constant(ei_max), Profile::constant(chi0)};
  return d;
}

}  // namespace stockbridge::cable
