#include "stockbridge/damper/damper_numbers.hpp"

#include <charconv>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

namespace {

/// What a path may name: the damper's numbers and each law's.
std::string expected_paths() {
  std::string laws;
  for (const cable::SectionLawDescriptor* law : cable::section_laws()) {
    std::vector<std::string> keys;
    for (const cable::LawNumber& n : law->numbers()) keys.push_back(fmt::format("cable.{}", n.key));
    if (law->jenkin_elements()) keys.insert(keys.end(), {"cable.lever_arm_cap", "cable.jenkin[<k>].c, .h, .k0"});
    laws += fmt::format("{}({}) {}", laws.empty() ? "" : ", ", law->title(), fmt::join(keys, ", "));
  }
  return "clamp.mass, or arm.<name or [index]>. followed by mass, inertia, offset, cable.length, cable.mirror_length, "
         "or a number of the cable's law: " +
         laws;
}

[[noreturn]] void fail(std::string_view path, std::string_view why) {
  throw InvalidParameter(std::string(path), fmt::format(": {}", why));
}

[[noreturn]] void unknown(std::string_view path) {
  fail(path, fmt::format("names no number of the damper (expected {})", expected_paths()));
}

/// "[k]" at the start of `text`: k, and the text after it.
std::optional<std::pair<std::size_t, std::string_view>> leading_index(std::string_view text) {
  if (text.empty() || text.front() != '[') return std::nullopt;
  const std::size_t close = text.find(']');
  if (close == std::string_view::npos) return std::nullopt;
  std::size_t k = 0;
  const auto [end, ec] = std::from_chars(text.data() + 1, text.data() + close, k);
  if (ec != std::errc() || end != text.data() + close) return std::nullopt;
  return std::make_pair(k, text.substr(close + 1));
}

/// The profile of a cable parameter as one number.
double constant_of(const cable::Profile& profile, std::string_view path) {
  if (!profile.is_constant()) {
    fail(path, fmt::format("a profile along the cable ({} values), not one number", profile.values().size()));
  }
  return profile.values().front();
}

/// The cable's number at `field` ("length", "jenkin[0].h"): a pointer to a plain
/// number, or the profile that holds it.
struct CableNumber {
  double* number = nullptr;
  cable::Profile* profile = nullptr;
  std::optional<double>* optional = nullptr;
};

CableNumber cable_number(cable::CableDescription& c, std::string_view field, std::string_view path) {
  if (field == "length") return {&c.length};
  if (cable::number_index(*c.law, field) >= 0) return {nullptr, &c.number(field)};
  if (field == "mirror_length") return {nullptr, nullptr, &c.mirror_length};
  if (c.law->jenkin_elements() && field == "lever_arm_cap") return {nullptr, nullptr, &c.lever_arm_cap};
  if (!cable::owners_of(field, c.law).empty()) fail(path, cable::foreign_key_message(field, *c.law));
  if (c.law->jenkin_elements() && field.starts_with("jenkin")) {
    const auto index = leading_index(field.substr(6));
    if (!index || !index->second.starts_with('.')) unknown(path);
    if (index->first >= c.jenkin.size()) {
      fail(path, fmt::format("the cable has {} Jenkin element(s): expected jenkin[0] to jenkin[{}]", c.jenkin.size(),
                             c.jenkin.size() - 1));
    }
    cable::JenkinProfile& e = c.jenkin[index->first];
    const std::string_view key = index->second.substr(1);
    if (key == "c") return {nullptr, &e.c};
    if (key == "h") return {nullptr, &e.h};
    if (key == "k0") return {&e.k0};
  }
  unknown(path);
}

/// The number at `path` of `damper` (a copy for reading, the description for writing).
struct Located {
  double* number = nullptr;
  cable::Profile* profile = nullptr;
  std::optional<double>* optional = nullptr;
};

Located locate(DamperDescription& damper, std::string_view path) {
  if (path == "clamp.mass") return {&damper.clamp_mass};
  const ArmPath arm = split_arm_path(damper, path);
  ArmDescription& a = damper.arms[arm.arm];
  if (arm.field == "mass") return {&a.mass};
  if (arm.field == "inertia") return {&a.inertia};
  if (arm.field == "offset") return {&a.offset};
  if (arm.field.starts_with("cable.")) {
    const CableNumber n = cable_number(a.cable, std::string_view(arm.field).substr(6), path);
    return {n.number, n.profile, n.optional};
  }
  unknown(path);
}

}  // namespace

ArmPath split_arm_path(const DamperDescription& damper, std::string_view path) {
  if (!path.starts_with("arm")) unknown(path);
  std::string_view rest = path.substr(3);
  ArmPath out;
  if (const auto index = leading_index(rest)) {
    if (index->first >= damper.arms.size()) {
      fail(path, fmt::format("the damper has {} arm(s): expected arm[0] to arm[{}]", damper.arms.size(),
                             damper.arms.size() - 1));
    }
    out.arm = index->first;
    rest = index->second;
  } else {
    if (!rest.starts_with('.')) unknown(path);
    rest = rest.substr(1);
    const std::size_t dot = rest.find('.');
    const std::string_view name = rest.substr(0, dot);
    std::size_t k = 0;
    while (k < damper.arms.size() && damper.arms[k].name != name) ++k;
    if (k == damper.arms.size()) {
      std::string names;
      for (const auto& a : damper.arms) names += (names.empty() ? "" : ", ") + (a.name.empty() ? "(unnamed)" : a.name);
      fail(path, fmt::format("no arm is named '{}' (the arms: {}; or arm[<index>])", name, names));
    }
    out.arm = k;
    rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot);
  }
  if (!rest.starts_with('.') || rest.size() < 2) unknown(path);
  out.field = std::string(rest.substr(1));
  return out;
}

double damper_number(const DamperDescription& damper, std::string_view path) {
  DamperDescription copy = damper;
  const Located at = locate(copy, path);
  if (at.number) return *at.number;
  if (at.profile) return constant_of(*at.profile, path);
  if (!at.optional->has_value()) fail(path, "not given in the damper (the cable's default applies): give it to vary it");
  return **at.optional;
}

void set_damper_number(DamperDescription& damper, std::string_view path, double value) {
  const Located at = locate(damper, path);
  if (at.number) {
    *at.number = value;
  } else if (at.profile) {
    constant_of(*at.profile, path);
    *at.profile = cable::Profile::constant(value);
  } else {
    *at.optional = value;
  }
}

}  // namespace stockbridge::damper
