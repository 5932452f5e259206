#include "stockbridge/io/cable_file.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cable_table.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

namespace {

/// A parameter that is a number or a profile table { s = [...], value = [...] }
/// (its values are the model's to check).
cable::Profile read_profile(const TomlTable& table, std::string_view key) {
  const toml::node* n = table.node(key);
  if (n && n->is_table()) {
    const TomlTable profile = table.table(key);
    std::vector<double> s = profile.number_array("s");
    std::vector<double> value = profile.number_array("value");
    profile.reject_unknown_keys();
    return cable::Profile::table(std::move(s), std::move(value), table.qualified(key));
  }
  if (n && !n->is_number()) {
    table.fail(key, fmt::format("{}: expected a number or a profile {{ s = [...], value = [...] }}", describe_type(*n)));
  }
  return cable::Profile::constant(table.number(key));
}

const cable::SectionLawDescriptor& read_law(const TomlTable& table) {
  const std::optional<std::string> law = table.optional_string("law");
  if (!law) return cable::default_section_law();
  if (const cable::SectionLawDescriptor* found = cable::find_section_law(*law)) return *found;
  table.fail("law", fmt::format("\"{}\" is not a section law: expected {}", *law, cable::section_law_names(true)));
}

/// A key of another law in the table of a cable of this one: named, with what the law takes.
void reject_keys_of_other_laws(const TomlTable& table, const cable::SectionLawDescriptor& law) {
  const std::vector<std::string_view> own = cable::law_keys(law);
  for (const cable::SectionLawDescriptor* other : cable::section_laws()) {
    for (std::string_view key : cable::law_keys(*other)) {
      if (!table.present(key) || std::find(own.begin(), own.end(), key) != own.end()) continue;
      const bool default_note = &law == &cable::default_section_law() && !table.present("law");
      table.fail(key, cable::foreign_key_message(key, law) +
                          (default_note ? fmt::format(" (the default law is \"{}\": {})", law.name(), law.takes()) : ""));
    }
  }
}

}  // namespace

cable::CableDescription read_cable_table(const TomlTable& table) {
  cable::CableDescription d;
  d.law = &read_law(table);
  reject_keys_of_other_laws(table, *d.law);
  d.length = table.number("length");
  d.sections = static_cast<int>(table.integer("sections", cable::min_sections, cable::max_sections));
  for (const cable::LawNumber& n : d.law->numbers()) d.number(n.key) = read_profile(table, n.key);
  if (d.law->jenkin_elements()) {
    for (const TomlTable& element : table.table_array("jenkin", false)) {
      cable::JenkinProfile jenkin;
      jenkin.c = read_profile(element, "c");
      jenkin.h = read_profile(element, "h");
      jenkin.k0 = element.optional_number("k0").value_or(0.0);
      element.reject_unknown_keys();
      d.jenkin.push_back(std::move(jenkin));
    }
  }
  d.mirror_length = table.optional_number("mirror_length");
  if (d.law->jenkin_elements()) d.lever_arm_cap = table.optional_number("lever_arm_cap");
  table.reject_unknown_keys();
  return d;
}

namespace {

CableFile build_cable(const toml::table& document, const TomlSource& source, SlipPolicy policy) {
  cable::CableDescription description = build_from_file(document, source, [&] {
    const TomlTable top(document, source, "");
    cable::CableDescription read = read_cable_table(top.table("cable"));
    top.reject_unknown_keys();
    return read;
  });
  std::vector<std::string> warnings;
  for (UnusualValue& u : description.unusual_values()) {
    u.field = "cable." + u.field;
    judge_unusual(u, field_location(document, source, u.field), policy, warnings);
  }
  cable::Cable cable = build_from_file(document, source, [&] {
    return within_field("cable", [&] { return cable::Cable(std::move(description)); });
  });
  return CableFile{std::move(cable), std::move(warnings)};
}

std::string profile_toml(const cable::Profile& p) {
  if (p.is_constant()) return format_value(p.values()[0]);
  std::string s, v;
  for (std::size_t i = 0; i < p.values().size(); ++i) {
    s += fmt::format("{}{}", i ? ", " : "", format_value(p.positions()[i]));
    v += fmt::format("{}{}", i ? ", " : "", format_value(p.values()[i]));
  }
  return fmt::format("{{ s = [{}], value = [{}] }}", s, v);
}

}  // namespace

CableFile load_cable_file(const std::filesystem::path& path, SlipPolicy policy) {
  return build_cable(parse_toml_file(path), TomlSource{path.string(), true}, policy);
}

cable::Cable read_cable_file(const std::filesystem::path& path, SlipPolicy policy) {
  return load_cable_file(path, policy).cable;
}

CableFile load_cable_text(std::string_view text, std::string_view source, SlipPolicy policy) {
  const TomlSource where{std::string(source), false};
  return build_cable(parse_toml_text(text, source), where, policy);
}

cable::Cable read_cable_text(std::string_view text, std::string_view source, SlipPolicy policy) {
  return load_cable_text(text, source, policy).cable;
}

std::string cable_table_toml(const cable::CableDescription& c) {
  std::string text = c.law == &cable::default_section_law() ? "" : fmt::format("law = \"{}\"\n", c.law->name());
  text += fmt::format("length = {}   # m\nsections = {}\n", format_value(c.length), c.sections);
  for (const cable::LawNumber& n : c.law->numbers()) {
    text += fmt::format("{} = {}   # {}\n", n.key, profile_toml(c.number(n.key)), n.unit.empty() ? "-" : n.unit);
  }
  if (c.law->jenkin_elements()) {
    text += "jenkin = [";
    for (std::size_t j = 0; j < c.jenkin.size(); ++j) {
      const cable::JenkinProfile& e = c.jenkin[j];
      text += fmt::format("{} {{ c = {}, h = {}{} }}", j ? "," : "", profile_toml(e.c), profile_toml(e.h),
                          e.k0 > 0.0 ? fmt::format(", k0 = {}", format_value(e.k0)) : "");
    }
    text += " ]   # N m^2, N m\n";
  }
  if (c.mirror_length) text += fmt::format("mirror_length = {}   # m\n", format_value(*c.mirror_length));
  if (c.lever_arm_cap) text += fmt::format("lever_arm_cap = {}   # m\n", format_value(*c.lever_arm_cap));
  return text;
}

std::string toml_comment_lines(std::string_view comment) {
  std::string text;
  std::size_t start = 0;
  while (start < comment.size()) {
    const std::size_t end = std::min(comment.find('\n', start), comment.size());
    text += fmt::format("# {}\n", comment.substr(start, end - start));
    start = end + 1;
  }
  return text;
}

std::string cable_file_toml(const cable::CableDescription& description, std::string_view comment) {
  return toml_comment_lines(comment) + "[cable]\n" + cable_table_toml(description);
}

}  // namespace stockbridge::io
