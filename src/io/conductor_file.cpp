#include "stockbridge/io/conductor_file.hpp"

#include <cctype>
#include <initializer_list>

#include <fmt/format.h>

#include "conductor_catalogue_data.hpp"
#include "stockbridge/core/error.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

// Names in this unnamed namespace are unique across the library (the sanitizer
// presets compile it in unity batches).

span::WireMaterial read_material(const TomlTable& table) {
  const std::string name = table.required_string("material", "a string: steel, aluminium, aluminium-alloy or aluminium-clad-steel");
  try {
    return span::parse_wire_material(name);
  } catch (const InvalidParameter& e) {
    throw InputError(table.location("material") + e.within(table.key_path()).what());
  }
}

span::ConductorLayer read_core(const TomlTable& table) {
  table.accept_only({"material", "youngs_modulus", "wire_diameter"});
  span::ConductorLayer core;
  core.material = read_material(table);
  core.youngs_modulus = table.number("youngs_modulus");
  core.wire_diameter = table.number("wire_diameter");
  return core;
}

span::ConductorLayer read_conductor_layer(const TomlTable& table) {
  table.accept_only({"material", "youngs_modulus", "count", "wire_diameter", "lay_length", "lay_ratio"});
  span::ConductorLayer layer;
  layer.material = read_material(table);
  layer.youngs_modulus = table.number("youngs_modulus");
  layer.count = static_cast<int>(table.integer("count", 1, 1000));  // StrandedConductor::validate's range
  layer.wire_diameter = table.number("wire_diameter");
  const std::optional<double> length = table.optional_number("lay_length");
  const std::optional<double> ratio = table.optional_number("lay_ratio");
  if (!length && !ratio) {
    throw InputError(fmt::format("{}missing key 'lay_ratio' in [{}]: expected lay_ratio (lay length / the layer's "
                                 "outer diameter) or lay_length (m), one of the two",
                                 table.location("lay_ratio"), table.key_path()));
  }
  if (length && ratio) {
    table.fail("lay_ratio", fmt::format("given beside {}: expected one of lay_length (m) and lay_ratio",
                                        table.qualified("lay_length")));
  }
  layer.lay_length = length.value_or(0.0);
  layer.lay_ratio = ratio.value_or(0.0);
  return layer;
}

span::StrandedConductor read_conductor_document(const toml::table& document, const TomlSource& source) {
  const TomlTable root(document, source, "");
  root.accept_only({"conductor"});
  const TomlTable table = root.table("conductor");
  table.accept_only({"type", "source", "mass_per_length", "diameter", "rated_tensile_strength", "core", "layer"});
  span::StrandedConductor conductor;
  conductor.type = table.required_string("type", "a string: the conductor's name, e.g. \"ACSR Drake\"");
  conductor.source = table.optional_string("source").value_or("");
  conductor.mass_per_length = table.number("mass_per_length");
  conductor.diameter = table.number("diameter");
  conductor.rated_tensile_strength = table.number("rated_tensile_strength");
  conductor.core = read_core(table.table("core"));
  for (const TomlTable& layer : table.table_array("layer", true)) conductor.layers.push_back(read_conductor_layer(layer));
  // The reader checks types and keys; the ranges and the geometry are the model's,
  // each error at the line of the key it names.
  return build_from_file(document, source, [&] {
    within_field("conductor", [&] { conductor.validate(); });
    return conductor;
  });
}

/// Lower case, without spaces, hyphens and underscores.
std::string normalized_type(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    if (ch == ' ' || ch == '-' || ch == '_' || ch == '\t') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  }
  return out;
}

std::vector<span::StrandedConductor> read_catalogue() {
  std::vector<span::StrandedConductor> entries;
  for (const EmbeddedConductorFile& file : embedded_conductor_files()) {
    const std::string name = fmt::format("conductor catalogue {}", file.name);
    toml::table document;
    try {
      document = toml::parse(file.text, name);
    } catch (const toml::parse_error& e) {
      throw InputError(fmt::format("{}:{}: TOML syntax error: {}", name, e.source().begin.line,
                                   printable(e.description(), 200)));
    }
    entries.push_back(read_conductor_document(document, TomlSource{name, true}));
  }
  return entries;
}

}  // namespace

span::StrandedConductor read_conductor_file(const std::filesystem::path& path) {
  return read_conductor_document(parse_toml_file(path), TomlSource{path.string(), true});
}

const std::vector<span::StrandedConductor>& conductor_catalogue() {
  static const std::vector<span::StrandedConductor> catalogue = read_catalogue();
  return catalogue;
}

bool conductor_type_matches(std::string_view query, std::string_view type) {
  const std::string wanted = normalized_type(query);
  if (wanted.empty()) return false;
  if (wanted == normalized_type(type)) return true;
  const std::size_t space = type.find(' ');
  return space != std::string_view::npos && wanted == normalized_type(type.substr(space + 1));
}

const span::StrandedConductor& catalogue_conductor(std::string_view query) {
  const std::vector<span::StrandedConductor>& catalogue = conductor_catalogue();
  for (const span::StrandedConductor& entry : catalogue) {
    if (conductor_type_matches(query, entry.type)) return entry;
  }
  std::string known;
  for (const span::StrandedConductor& entry : catalogue) known += (known.empty() ? "" : ", ") + entry.type;
  throw InvalidParameter("type", fmt::format(" = \"{}\": expected a conductor of the catalogue: {} (case, spaces and "
                                             "hyphens aside; stockbridge conductors lists them)",
                                             printable(query), known));
}

}  // namespace stockbridge::io
