#include "stockbridge/io/sn_curve_file.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/toml_text.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

span::SnCurve read_sn_curve_file(const std::filesystem::path& path) {
  const toml::table document = parse_toml_file(path);
  const TomlSource source{path.string()};
  const TomlTable top(document, source, "");
  top.accept_only({"sn_curve"});
  const TomlTable table = top.table("sn_curve");
  table.accept_only({"name", "source", "stress_mpa", "cycles"});
  const std::string name = table.required_string("name", "the curve's name, as reports show it");
  (void)table.optional_string("source");
  const std::vector<double> stress = table.number_array("stress_mpa");
  const std::vector<double> cycles = table.number_array("cycles");
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
