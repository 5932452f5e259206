#include "stockbridge/io/sn_curve_file.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/toml_text.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

/// The key's non-empty array of numbers (integers accepted).
std::vector<double> sn_number_array(const TomlTable& table, std::string_view key) {
  const toml::node* n = table.node(key);
  if (!n) {
    throw InputError(fmt::format("{}missing key '{}' in [{}]: expected an array of numbers", table.location(key), key,
                                 table.key_path()));
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

}  // namespace

span::SnCurve read_sn_curve_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlSource source{path.string()};
  const TomlTable top(document, source, "");
  top.accept_only({"sn_curve"});
  const TomlTable table = top.table("sn_curve");
  table.accept_only({"name", "source", "stress_mpa", "cycles"});
  const std::string name = table.required_string("name", "the curve's name, as reports show it");
  (void)table.optional_string("source");
  const std::vector<double> stress = sn_number_array(table, "stress_mpa");
  const std::vector<double> cycles = sn_number_array(table, "cycles");
  return build_from_file(document, source, [&] {
    return within_field("sn_curve", [&] { return span::SnCurve::from_table(stress, cycles, name, path.string()); });
  });
}

std::string sn_curve_toml(std::string_view name, std::string_view source, const std::vector<double>& stress_mpa,
                          const std::vector<double>& cycles) {
  std::string stresses, counts;
  for (std::size_t i = 0; i < stress_mpa.size(); ++i) {
    stresses += fmt::format("{}{:.10g}", i ? ", " : "", stress_mpa[i]);
    counts += fmt::format("{}{:.10g}", i ? ", " : "", cycles[i]);
  }
  return fmt::format("# An S-N curve (docs/file-formats.md): zero-to-peak Poffenberger-Swart stress, MPa, against\n"
                     "# cycles to failure, log-log piecewise linear, the end segments extrapolated.\n"
                     "[sn_curve]\nname = {}\nsource = {}\nstress_mpa = [{}]\ncycles = [{}]\n",
                     toml_basic_string(name), toml_basic_string(source), stresses, counts);
}

}  // namespace stockbridge::io
