#include "stockbridge/io/strand_file.hpp"

#include <initializer_list>
#include <string_view>

#include "stockbridge/core/error.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

/// Rejects unknown keys before any value is read, so that a misspelt key is
/// reported as such rather than as the missing key it was meant to be.
void accept_only(const TomlTable& table, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) table.contains(key);
  table.reject_unknown_keys();
}

strand::StrandLayer read_layer(const TomlTable& table) {
  accept_only(table, {"count", "wire_radius", "pitch_radius", "lay_length", "youngs_modulus"});
  strand::StrandLayer layer;
  layer.count = static_cast<int>(table.integer("count", 1, 1000));  // strand::validate's range
  layer.wire_radius = table.number("wire_radius");
  layer.pitch_radius = table.number("pitch_radius");
  layer.lay_length = table.number("lay_length");
  layer.youngs_modulus = table.optional_number("youngs_modulus");
  return layer;
}

}  // namespace

strand::Strand read_strand_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlTable root(document, TomlSource{path.string(), true}, "");
  accept_only(root, {"strand"});
  const TomlTable table = root.table("strand");
  accept_only(table, {"youngs_modulus", "core_radius", "core_youngs_modulus", "layer"});

  strand::Strand strand;
  strand.youngs_modulus = table.optional_number("youngs_modulus").value_or(strand.youngs_modulus);
  strand.core_radius = table.number("core_radius");
  strand.core_youngs_modulus = table.optional_number("core_youngs_modulus");
  for (const TomlTable& layer_table : table.table_array("layer", false)) strand.layers.push_back(read_layer(layer_table));
  // The reader checks types and keys; the ranges and the geometry are strand::validate's,
  // each error at the line of the key it names.
  return build_from_file(document, TomlSource{path.string(), true}, [&] {
    within_field("strand", [&] { strand::validate(strand); });
    return strand;
  });
}

}  // namespace stockbridge::io
