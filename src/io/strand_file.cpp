#include "stockbridge/io/strand_file.hpp"

#include "stockbridge/core/error.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

strand::StrandLayer read_layer(const TomlTable& table) {
  table.accept_only({"count", "wire_radius", "pitch_radius", "lay_length", "youngs_modulus"});
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
  root.accept_only({"strand"});
  const TomlTable table = root.table("strand");
  table.accept_only({"youngs_modulus", "core_radius", "core_youngs_modulus", "layer"});

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
