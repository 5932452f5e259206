#include "stockbridge/io/damper_file.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include <fmt/format.h>

#include "cable_table.hpp"
#include "damper_reading.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/cable_file.hpp"
#include "stockbridge/io/input_file.hpp"
#include "stockbridge/io/toml_text.hpp"

namespace stockbridge::io {

namespace {

/// The keys an [arm.cable] table may give beside `file`: how the referenced cable
/// is cut and integrated, never its identified parameters.
constexpr std::array<std::string_view, 4> kCableOverrides{"length", "sections", "mirror_length", "lever_arm_cap"};

/// An arm's cable read from a referenced cable file.
struct CableReference {
  std::filesystem::path path;
  std::vector<std::string> warnings;  ///< the cable file's own, located there
};

/// A damper file's contents before the model validates them.
struct DamperReading {
  damper::DamperDescription description;
  std::vector<std::optional<CableReference>> references;  ///< per arm
};

std::filesystem::path resolve(const std::filesystem::path& file, const std::filesystem::path& base_directory) {
  return file.is_absolute() ? file : base_directory / file;
}

/// `[arm.cable] file = "..."`: the referenced cable file's cable (validated and
/// located there), then the overrides of this table.
cable::CableDescription read_referenced_cable(const TomlTable& table, const std::filesystem::path& base_directory,
                                              SlipPolicy policy, CableReference& reference) {
  const std::string file = *table.optional_string("file");
  reference.path = existing_input_file(table.where("file"), {file, resolve(file, base_directory), "cable file",
                                                              "the damper file's folder"});
  CableFile referenced = load_cable_file(reference.path, policy);
  reference.warnings = std::move(referenced.warnings);
  cable::CableDescription description = referenced.cable.description();
  for (const std::string_view parameter : {"ei", "jenkin"}) {
    if (table.contains(parameter)) {
      table.fail(parameter, fmt::format("given beside file = \"{}\": the cable's parameters come from that file; "
                                        "beside it only length, sections, mirror_length and lever_arm_cap may be given",
                                        printable(file)));
    }
  }
  if (const auto length = table.optional_number("length")) description.length = *length;
  if (const auto sections = table.optional_integer("sections", cable::min_sections, cable::max_sections)) {
    description.sections = static_cast<int>(*sections);
  }
  if (const auto mirror = table.optional_number("mirror_length")) description.mirror_length = *mirror;
  if (const auto cap = table.optional_number("lever_arm_cap")) description.lever_arm_cap = *cap;
  table.reject_unknown_keys();
  return description;
}

damper::ArmDescription read_arm(const TomlTable& table, const std::filesystem::path& base_directory, SlipPolicy policy,
                                std::optional<CableReference>& reference) {
  damper::ArmDescription arm;
  arm.name = table.optional_string("name").value_or("");
  arm.mass = table.number("mass");
  arm.inertia = table.number("inertia");
  arm.offset = table.number("offset");
  const TomlTable cable = table.table("cable");
  if (cable.contains("file")) {
    reference.emplace();
    arm.cable = read_referenced_cable(cable, base_directory, policy, *reference);
  } else {
    arm.cable = read_cable_table(cable);
  }
  table.reject_unknown_keys();
  return arm;
}

DamperReading read_damper_table(const TomlTable& top, const std::filesystem::path& base_directory, SlipPolicy policy) {
  DamperReading reading;
  const TomlTable clamp = top.table("clamp");
  reading.description.clamp_mass = clamp.number("mass");
  clamp.reject_unknown_keys();
  const std::vector<TomlTable> arms = top.table_array("arm", true);
  if (arms.empty()) top.fail("arm", "an empty array: expected at least one [[arm]]");
  reading.references.resize(arms.size());
  for (std::size_t k = 0; k < arms.size(); ++k) {
    reading.description.arms.push_back(read_arm(arms[k], base_directory, policy, reading.references[k]));
  }
  top.reject_unknown_keys();
  return reading;
}

/// The warnings of a damper: those of each referenced cable file (once per file),
/// then each unusual value the damper file itself holds, at its line (one a unit
/// slip explains refused where `policy` says so). A referenced cable's values that
/// this file does not override are the cable file's to report.
std::vector<std::string> damper_warnings(const DamperReading& reading, const toml::table& document,
                                         const TomlSource& source, SlipPolicy policy) {
  std::vector<std::string> warnings;
  const auto add = [&warnings](std::string line) {
    if (std::find(warnings.begin(), warnings.end(), line) == warnings.end()) warnings.push_back(std::move(line));
  };
  for (const auto& reference : reading.references) {
    if (reference) std::for_each(reference->warnings.begin(), reference->warnings.end(), add);
  }
  std::vector<std::string> own;
  for (const UnusualValue& u : reading.description.unusual_values()) {
    if (!document.at_path(u.field)) continue;  // in a referenced cable file
    judge_unusual(u, field_location(document, source, u.field), policy, own);
  }
  std::for_each(own.begin(), own.end(), add);
  return warnings;
}

}  // namespace

DamperFile build_damper(const toml::table& document, const TomlSource& source, const std::filesystem::path& base_directory,
                        SlipPolicy policy) {
  DamperReading reading = build_from_file(document, source, [&] {
    return read_damper_table(TomlTable(document, source, ""), base_directory, policy);
  });
  std::vector<std::string> warnings = damper_warnings(reading, document, source, policy);
  std::vector<std::filesystem::path> cable_files;
  for (const auto& reference : reading.references) {
    if (reference) cable_files.push_back(reference->path);
  }
  damper::Damper damper = build_from_file(document, source, [&] { return damper::Damper(std::move(reading.description)); });
  return DamperFile{std::move(damper), std::move(cable_files), std::move(warnings)};
}

DamperFile load_damper_file(const std::filesystem::path& path, SlipPolicy policy) {
  return build_damper(parse_toml_file(path), TomlSource{path.string(), true}, path.parent_path(), policy);
}

damper::Damper read_damper_file(const std::filesystem::path& path, SlipPolicy policy) {
  return load_damper_file(path, policy).damper;
}

DamperFile load_damper_text(std::string_view text, std::string_view source, SlipPolicy policy) {
  return build_damper(parse_toml_text(text, source), TomlSource{std::string(source), false}, std::filesystem::path(),
                      policy);
}

damper::Damper read_damper_text(std::string_view text, std::string_view source, SlipPolicy policy) {
  return load_damper_text(text, source, policy).damper;
}

std::string damper_file_toml(const damper::DamperDescription& description, std::string_view comment) {
  std::string text = toml_comment_lines(comment);
  text += fmt::format("\n[clamp]\nmass = {}   # kg\n", format_value(description.clamp_mass));
  for (const damper::ArmDescription& arm : description.arms) {
    text += "\n[[arm]]\n";
    if (!arm.name.empty()) text += fmt::format("name = {}\n", toml_basic_string(arm.name));
    text += fmt::format("mass = {}   # kg\ninertia = {}   # kg m^2\noffset = {}   # m\n[arm.cable]\n",
                        format_value(arm.mass), format_value(arm.inertia), format_value(arm.offset));
    text += cable_table_toml(arm.cable);
  }
  return text;
}

}  // namespace stockbridge::io
