// The damper numbers the impedance fit frees or holds (impedance_fit_variables.hpp).
#include "impedance_fit_variables.hpp"

namespace stockbridge::identification::impedance_fit {

/// The constant value of a profile, or InvalidParameter naming it.
double constant_value(const cable::Profile& profile, const std::string& name) {
  if (!profile.is_constant()) {
    throw InvalidParameter(name, ": a profile along the cable: identify impedance fits constant parameters (give the "
                                 "starting value as a number)");
  }
  return profile.values()[0];
}

std::string arm_key(std::size_t arm) { return fmt::format("arm[{}].cable.", arm); }



/// An option's path refused: InvalidParameter naming the option and the path.
[[noreturn]] void refuse_free(const std::string& path, std::string_view why) {
  throw InvalidParameter("free", fmt::format(" = {}: {}", printable(path), why));
}

/// The fitted numbers of options.free (the clamp mass apart: it has its own variable).
std::vector<DamperNumber> damper_numbers(const damper::DamperDescription& start, const std::vector<std::string>& free) {
  std::vector<DamperNumber> out;
  std::vector<std::pair<std::size_t, std::string>> seen;  // (arm, field) of each
  bool clamp_mass = false;
  for (const std::string& path : free) {
    if (path == "clamp.mass") {
      if (clamp_mass) refuse_free(path, "given twice: expected each number once");
      clamp_mass = true;
      continue;
    }
    damper::ArmPath arm;
    try {
      arm = damper::split_arm_path(start, path);
    } catch (const InvalidParameter& e) {
      refuse_free(path, e.detail().substr(e.detail().starts_with(": ") ? 2 : 0));
    }
    static const std::pair<const char*, const char*> kFields[] = {
        {"mass", "kg"}, {"inertia", "kg m^2"}, {"offset", "m"}, {"cable.length", "m"}};
    const auto field = std::find_if(std::begin(kFields), std::end(kFields),
                                    [&](const auto& f) { return arm.field == f.first; });
    if (field == std::end(kFields)) {
      refuse_free(path, fmt::format("{}: expected {} (every cable type's own numbers, ei, c and h or ei_min, ei_max and chi0, are fitted anyway)",
                                    arm.field.starts_with("cable.") ? "a cable parameter or setting, not fitted as a "
                                                                      "number of the damper"
                                                                    : "not a number the fit can free",
                                    free_damper_numbers));
    }
    if (std::find(seen.begin(), seen.end(), std::make_pair(arm.arm, arm.field)) != seen.end()) {
      refuse_free(path, "given twice (perhaps once by name and once by index): expected each number once");
    }
    seen.emplace_back(arm.arm, arm.field);
    const damper::ArmDescription& a = start.arms[arm.arm];
    DamperNumber n;
    n.path = a.name.empty() ? fmt::format("arm[{}].{}", arm.arm, arm.field) : fmt::format("arm.{}.{}", a.name, arm.field);
    n.arm = arm.arm;
    n.field = arm.field;
    n.unit = field->second;
    n.start = damper::damper_number(start, path);
    n.logarithmic = arm.field != "offset";
    if (n.logarithmic && !(n.start > 0.0)) {
      refuse_free(path, fmt::format("is {} in the damper: fitted in logarithms, it must start > 0", format_value(n.start)));
    }
    // An offset moves in units of its start's magnitude, at least 1 cm.
    n.scale = n.logarithmic ? 1.0 : std::max(std::abs(n.start), 0.01);
    out.push_back(n);
  }
  return out;
}

/// The numbers of the damper options.free leaves fixed (the lack of fit's suspects):
/// each arm's mass, inertia, offset and cable length not freed, parametrised as `free`
/// would fit them (a mass, inertia or length that is not > 0 is left out: it has no
/// logarithm). The clamp mass apart (its column is analytic).
std::vector<DamperNumber> fixed_numbers(const damper::DamperDescription& start, const std::vector<DamperNumber>& free) {
  static const std::pair<const char*, const char*> kFields[] = {
      {"mass", "kg"}, {"inertia", "kg m^2"}, {"offset", "m"}, {"cable.length", "m"}};
  std::vector<DamperNumber> out;
  for (std::size_t k = 0; k < start.arms.size(); ++k) {
    const damper::ArmDescription& a = start.arms[k];
    for (const auto& entry : kFields) {
      // Not a structured binding: clang before 16 cannot capture one in the lambda.
      const char* const field = entry.first;
      const char* const unit = entry.second;
      auto same = [&](const DamperNumber& n) { return n.arm == k && n.field == field; };
      if (std::any_of(free.begin(), free.end(), same)) continue;
      DamperNumber n;
      n.path = a.name.empty() ? fmt::format("arm[{}].{}", k, field) : fmt::format("arm.{}.{}", a.name, field);
      n.arm = k;
      n.field = field;
      n.unit = unit;
      n.start = damper::damper_number(start, n.path);
      n.logarithmic = n.field != "offset";
      if (n.logarithmic && !(n.start > 0.0)) continue;
      n.scale = n.logarithmic ? 1.0 : std::max(std::abs(n.start), 0.01);
      out.push_back(n);
    }
  }
  return out;
}

}  // namespace stockbridge::identification::impedance_fit
