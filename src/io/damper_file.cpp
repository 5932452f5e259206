#include "stockbridge/io/damper_file.hpp"

#include <fmt/format.h>

#include "cable_table.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

namespace {

damper::ArmDescription read_arm(const TomlTable& table) {
  damper::ArmDescription arm;
  arm.name = table.optional_string("name").value_or("");
  arm.mass = table.number("mass");
  arm.inertia = table.number("inertia");
  arm.offset = table.number("offset");
  arm.cable = read_cable_table(table.table("cable"));
  table.reject_unknown_keys();
  return arm;
}

}  // namespace

damper::DamperDescription read_damper_table(const TomlTable& top) {
  damper::DamperDescription damper;
  const TomlTable clamp = top.table("clamp");
  damper.clamp_mass = clamp.number("mass");
  clamp.reject_unknown_keys();
  const std::vector<TomlTable> arms = top.table_array("arm", true);
  if (arms.empty()) top.fail("arm", "an empty array: expected at least one [[arm]]");
  for (const TomlTable& arm : arms) damper.arms.push_back(read_arm(arm));
  top.reject_unknown_keys();
  return damper;
}

damper::Damper read_damper_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlSource source{path.string(), true};
  return build_from_file(document, source, [&] { return damper::Damper(read_damper_table(TomlTable(document, source, ""))); });
}

damper::Damper read_damper_text(std::string_view text, std::string_view source) {
  const toml::table document = parse_toml_text(text, source);
  const TomlSource where{std::string(source), false};
  return build_from_file(document, where, [&] { return damper::Damper(read_damper_table(TomlTable(document, where, ""))); });
}

}  // namespace stockbridge::io
