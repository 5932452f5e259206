#include "stockbridge/io/strand_file.hpp"

#include <initializer_list>
#include <string_view>

#include "stockbridge/core/error.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

void positive_length(std::string_view name, double value) { require_positive(name, value, "m"); }

/// Rejects unknown keys before any value is read, so that a misspelt key is
/// reported as such rather than as the missing key it was meant to be.
void accept_only(const TomlTable& table, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) table.contains(key);
  table.reject_unknown_keys();
}

strand::StrandLayer read_layer(const TomlTable& table) {
  accept_only(table, {"count", "wire_radius", "pitch_radius", "lay_length"});
  strand::StrandLayer layer;
  layer.count = static_cast<int>(table.integer("count", 1, 1000));
  layer.wire_radius = table.number("wire_radius", positive_length);
  layer.pitch_radius = table.number("pitch_radius", positive_length);
  layer.lay_length = table.number("lay_length", positive_length);
  return layer;
}

}  // namespace

strand::Strand read_strand_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlTable root(document, TomlSource{path.string(), true}, "");
  accept_only(root, {"strand"});
  const TomlTable table = root.table("strand");
  accept_only(table, {"youngs_modulus", "core_radius", "layer"});

  strand::Strand strand;
  if (const auto e = table.optional_number(
          "youngs_modulus", [](std::string_view name, double value) { require_positive(name, value, "Pa"); })) {
    strand.youngs_modulus = *e;
  }
  strand.core_radius = table.number("core_radius", positive_length);
  double inner_radius = strand.core_radius;
  for (const TomlTable& layer_table : table.table_array("layer", false)) {
    const strand::StrandLayer layer = read_layer(layer_table);
    // The geometry, with the line of the key it names.
    try {
      strand::check_layer_position(layer, inner_radius, layer_table.key_path());
    } catch (const InvalidParameter& e) {
      throw InputError(layer_table.location("pitch_radius") + e.what());
    }
    try {
      strand::check_lay_angle(layer, layer_table.key_path());
    } catch (const InvalidParameter& e) {
      throw InputError(layer_table.location("lay_length") + e.what());
    }
    inner_radius = layer.pitch_radius + layer.wire_radius;
    strand.layers.push_back(layer);
  }

  // Every field was checked against the same ranges as strand::validate; this
  // keeps the two in step (a failure here would name the field without a line).
  try {
    strand::validate(strand);
  } catch (const InvalidParameter& e) {
    throw InputError(path.string() + ": " + e.what());
  }
  return strand;
}

}  // namespace stockbridge::io
