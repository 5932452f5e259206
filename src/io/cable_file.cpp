#include "stockbridge/io/cable_file.hpp"

#include <fmt/format.h>

#include "cable_table.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::io {

namespace {

using CheckFn = std::function<void(std::string_view, double)>;

/// A positive value within the magnitudes a description may hold (require_plausible).
CheckFn plausible(std::string_view unit) {
  return [unit](std::string_view name, double v) { require_plausible(name, v, unit); };
}

std::vector<double> number_array(const TomlTable& table, std::string_view key) {
  const toml::node* n = table.node(key);
  if (!n) {
    throw InputError(fmt::format("{}missing key '{}' in [{}]: expected an array of numbers",
                                 table.location(key), key, table.key_path()));
  }
  const toml::array* array = n->as_array();
  if (!array || array->empty()) {
    table.fail(key, fmt::format("{}: expected a non-empty array of numbers", describe_type(*n)));
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    if (element.is_floating_point()) {
      values.push_back(*element.value<double>());
    } else if (element.is_integer()) {
      values.push_back(static_cast<double>(*element.value<long long>()));
    } else {
      table.fail(key, fmt::format("element {} is {}: expected a number", i, describe_type(element)));
    }
  }
  return values;
}

/// A parameter that is a number or a profile table { s = [...], value = [...] }.
cable::Profile read_profile(const TomlTable& table, std::string_view key, std::string_view unit) {
  const toml::node* n = table.node(key);
  if (n && n->is_table()) {
    const TomlTable profile = table.table(key);
    std::vector<double> s = number_array(profile, "s");
    std::vector<double> value = number_array(profile, "value");
    profile.reject_unknown_keys();
    cable::Profile result = cable::Profile::constant(0.0);
    try {
      result = cable::Profile::table(std::move(s), std::move(value), table.qualified(key));
    } catch (const InvalidParameter& e) {
      throw InputError(fmt::format("{}{}", table.location(key), e.what()));
    }
    result.check_values(table.qualified(key), [&](std::string_view name, double v) {
      try {
        require_plausible(name, v, unit);
      } catch (const InvalidParameter& e) {
        throw InputError(fmt::format("{}{}", table.location(key), e.what()));
      }
    });
    return result;
  }
  if (n && !n->is_number()) {
    table.fail(key, fmt::format("{}: expected a number or a profile {{ s = [...], value = [...] }}", describe_type(*n)));
  }
  return cable::Profile::constant(table.number(key, plausible(unit)));
}

}  // namespace

cable::CableDescription read_cable_table(const TomlTable& table) {
  cable::CableDescription d;
  d.length = table.number("length", plausible("m"));
  d.sections = static_cast<int>(table.integer("sections", cable::min_sections, cable::max_sections));
  d.ei = read_profile(table, "ei", "N m^2");
  for (const TomlTable& element : table.table_array("jenkin", false)) {
    cable::JenkinProfile jenkin;
    jenkin.c = read_profile(element, "c", "N m^2");
    jenkin.h = read_profile(element, "h", "N m");
    jenkin.k0 = element.optional_number("k0", [](std::string_view name, double v) {
      require_plausible_or_zero(name, v, "N");
    }).value_or(0.0);
    element.reject_unknown_keys();
    d.jenkin.push_back(std::move(jenkin));
  }
  d.mirror_length = table.optional_number("mirror_length", plausible("m"));
  d.lever_arm_cap = table.optional_number("lever_arm_cap", plausible("m"));
  table.reject_unknown_keys();
  try {
    d.validate();
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}[{}] {}", table.location("length"), table.key_path(), e.what()));
  }
  return d;
}

cable::CableDescription read_cable_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlTable top(document, path.string(), "");
  const cable::CableDescription description = read_cable_table(top.table("cable"));
  top.reject_unknown_keys();
  return description;
}

}  // namespace stockbridge::io
