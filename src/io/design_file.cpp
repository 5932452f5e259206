#include "stockbridge/io/design_file.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/input_file.hpp"
#include "stockbridge/io/span_file.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

// Names in this unnamed namespace are unique across the library (unity batches).

/// A file a design file names, relative to its folder; InputError at the key if missing.
std::filesystem::path design_input(const TomlTable& table, std::string_view key, const std::string& file,
                                   const std::filesystem::path& base_directory, std::string_view what) {
  const std::filesystem::path path =
      std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : base_directory / file;
  return existing_input_file(table.where(key), {file, path, what, "the design file's folder"});
}

std::vector<std::string> design_span_names(const TomlTable& top) {
  const toml::node* node = top.node("spans");
  if (!node) top.fail("spans", "missing: expected an array of span files, e.g. spans = [\"span.toml\"]");
  const toml::array* array = node->as_array();
  if (!array || array->empty()) top.fail("spans", "expected a non-empty array of span files, e.g. spans = [\"span.toml\"]");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto* text = (*array)[i].as_string();
    if (!text) {
      throw InputError(fmt::format("{}{}[{}]: expected a span file's path (a string)", top.location_of((*array)[i]),
                                   top.qualified("spans"), i));
    }
    names.push_back(text->get());
  }
  return names;
}

struct DesignReading {
  damper::DamperDescription base;
  std::vector<design::DesignSpan> spans;
  design::Objective objective = design::Objective::max_stress;
  std::vector<design::DesignVariable> variables;
  std::vector<design::DesignTie> ties;
  design::DesignConstraints constraints;
  int points = 100;
  design::SearchOptions search;
  std::filesystem::path damper_file;
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> warnings;
};

DesignReading read_design(const TomlTable& top, const std::filesystem::path& base_directory, SlipPolicy policy) {
  DesignReading r;
  const std::string damper = top.optional_string("damper").value_or("");
  if (!top.contains("damper")) top.fail("damper", "missing: expected the base damper file, e.g. damper = \"damper.toml\"");
  r.damper_file = design_input(top, "damper", damper, base_directory, "damper file");
  DamperFile d = load_damper_file(r.damper_file, policy);
  r.base = d.damper.description();
  r.inputs.push_back(r.damper_file);
  r.inputs.insert(r.inputs.end(), d.cable_files.begin(), d.cable_files.end());
  r.warnings = std::move(d.warnings);
  for (const std::string& name : design_span_names(top)) {
    const std::filesystem::path path = design_input(top, "spans", name, base_directory, "span file");
    SpanFile s = load_span_file(path, policy);
    r.inputs.push_back(path);
    r.inputs.insert(r.inputs.end(), s.inputs.begin(), s.inputs.end());
    r.warnings.insert(r.warnings.end(), s.warnings.begin(), s.warnings.end());
    r.spans.push_back({std::move(s.span), path.stem().string(), s.balance});
  }
  if (const auto objective = top.optional_string("objective")) {
    try {
      r.objective = design::parse_objective(*objective);
    } catch (const InvalidParameter& e) {
      throw InputError(top.location("objective") + e.what());
    }
  }
  r.search.samples = static_cast<int>(top.optional_integer("samples", 1, 1000000).value_or(r.search.samples));
  r.search.polish = static_cast<int>(top.optional_integer("polish", 0, 10000).value_or(r.search.polish));
  r.search.polish_evaluations =
      static_cast<int>(top.optional_integer("polish_evaluations", 2, 100000).value_or(r.search.polish_evaluations));
  r.search.seed = static_cast<std::uint64_t>(top.optional_integer("seed", 0, 1LL << 62).value_or(1));
  r.points = static_cast<int>(top.optional_integer("points", 2, 100000).value_or(100));
  for (const TomlTable& v : top.table_array("variable", true)) {
    r.variables.push_back({v.optional_string("name").value_or(""), v.number("min"), v.number("max")});
    if (!v.contains("name")) v.fail("name", "missing: expected a damper number's path (\"arm.left.mass\") or \"position\"");
    v.reject_unknown_keys();
  }
  for (const TomlTable& t : top.table_array("tie", false)) {
    if (!t.contains("name")) t.fail("name", "missing: expected a damper number's path (\"arm.right.mass\")");
    if (!t.contains("equals")) t.fail("equals", "missing: expected the name of the [[variable]] it follows");
    r.ties.push_back({*t.optional_string("name"), *t.optional_string("equals")});
    t.reject_unknown_keys();
  }
  if (const auto c = top.optional_table("constraints")) {
    r.constraints.total_mass_max = c->optional_number("total_mass_max");
    r.constraints.messenger_curvature_max = c->optional_number("messenger_curvature_max");
    c->reject_unknown_keys();
  }
  top.reject_unknown_keys();
  return r;
}

}  // namespace

DesignFile load_design_file(const std::filesystem::path& path, SlipPolicy policy) {
  const toml::table document = parse_toml_file(path);
  const TomlSource source{path.string(), true};
  DesignReading r = read_design(TomlTable(document, source, ""), path.parent_path(), policy);
  design::DesignStudy study = build_from_file(document, source, [&] {
    return design::DesignStudy(std::move(r.base), std::move(r.spans), r.objective, std::move(r.variables),
                               std::move(r.ties), r.constraints, r.points);
  });
  return DesignFile{std::move(study), r.search, std::move(r.damper_file), std::move(r.inputs), std::move(r.warnings)};
}

}  // namespace stockbridge::io
