#include "stockbridge/io/damper_file.hpp"

#include <fmt/format.h>

#include "cable_table.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

namespace {

void plausible_kg(std::string_view name, double v) { require_plausible(name, v, "kg"); }

damper::ArmDescription read_arm(const TomlTable& table, std::size_t index) {
  damper::ArmDescription arm;
  arm.name = table.optional_string("name").value_or(fmt::format("arm{}", index + 1));
  arm.mass = table.number("mass", plausible_kg);
  arm.inertia = table.number("inertia", [](std::string_view n, double v) { require_plausible(n, v, "kg m^2"); });
  arm.offset = table.number("offset", [](std::string_view n, double v) { require_finite(n, v, "m"); });
  arm.cable = read_cable_table(table.table("cable"));
  table.reject_unknown_keys();
  try {
    arm.validate(table.key_path());
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}{}", table.location("offset"), e.what()));
  }
  return arm;
}

}  // namespace

damper::DamperDescription read_damper_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlTable top(document, path.string(), "");
  damper::DamperDescription damper;
  const TomlTable clamp = top.table("clamp");
  damper.clamp_mass = clamp.number("mass", [](std::string_view n, double v) { require_plausible_or_zero(n, v, "kg"); });
  clamp.reject_unknown_keys();
  const std::vector<TomlTable> arms = top.table_array("arm", true);
  if (arms.empty()) top.fail("arm", "an empty array: expected at least one [[arm]]");
  for (std::size_t k = 0; k < arms.size(); ++k) damper.arms.push_back(read_arm(arms[k], k));
  top.reject_unknown_keys();
  return damper;
}

}  // namespace stockbridge::io
