// stockbridge strand: the bending-stiffness bounds EI_min and EI_max of a strand
// described in a TOML file (MODEL.md section 7).

#include <cstddef>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/strand_file.hpp"
#include "stockbridge/requests/strand_request.hpp"
#include "stockbridge/strand/strand_bounds.hpp"

namespace stockbridge::cli {

namespace {

struct StrandOptions {
  std::string file;
  bool json = false;
};

int run_strand_command(const StrandOptions& options) {
  const strand::Strand description = io::read_strand_file(options.file);
  const strand::StrandBounds bounds = strand::strand_bounds(description);
  if (options.json) {
    fmt::print("{}\n", requests::strand_summary(bounds).str());
    return kSuccess;
  }
  std::size_t wires = 1;
  for (const strand::StrandLayer& layer : description.layers) wires += static_cast<std::size_t>(layer.count);
  if (strand::single_modulus(description)) {
    fmt::print("strand: {} wires (core + {} layers), E = {} Pa\n", wires, description.layers.size(),
               format_value(strand::core_modulus(description)));
  } else {
    std::string layers;
    for (const strand::StrandLayer& layer : description.layers) {
      layers += fmt::format(", {}", format_value(strand::layer_modulus(description, layer)));
    }
    fmt::print("strand: {} wires (core + {} layers), E = {} Pa (core){} Pa (layers, from the inside out)\n", wires,
               description.layers.size(), format_value(strand::core_modulus(description)), layers);
  }
  fmt::print("ei_min = {} N m^2 (no friction: every wire bends on its own)\n", format_value(bounds.ei_min));
  fmt::print("ei_max = {} N m^2 (no slip: the strand bends as one beam, Lanteigne)\n", format_value(bounds.ei_max));
  return kSuccess;
}

}  // namespace

void add_strand_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<StrandOptions>();
  CLI::App* sub = app.add_subcommand(
      "strand", "Bending-stiffness bounds EI_min (no friction) and EI_max (no slip) of a strand, N m^2");
  sub->add_option("strand_file", options->file, "Strand description (TOML, see docs/strand.md)")->required();
  sub->add_flag("--json", options->json, "Print {\"ei_min_n_m2\": ..., \"ei_max_n_m2\": ...} instead of text");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_strand_command(*options)); });
}

}  // namespace stockbridge::cli
