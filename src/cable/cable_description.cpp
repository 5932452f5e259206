#include "stockbridge/cable/cable_description.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

void CableDescription::validate() const {
  require_plausible("length", length, "m");
  require_in_range("sections", sections, min_sections, max_sections);
  ei.check_values("ei", [](std::string_view name, double v) { require_plausible(name, v, "N m^2"); });
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
  ei.check_values("ei", check(typical::ei));
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

}  // namespace stockbridge::cable
