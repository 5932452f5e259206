// stockbridge modes: the linear natural frequencies of a damper with every element
// sticking and every element slipping, each arm with the clamp held and the whole
// damper with the clamp free (damper/modes.hpp).

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/requests/modes_request.hpp"

namespace stockbridge::cli {

namespace {

struct ModesOptions {
  std::string damper_file;
  bool json = false;
  bool allow_unusual = false;
  std::string output;
};

void print_modes_table(const requests::ModesResult& result) {
  const damper::DamperModes& modes = result.modes;
  const std::vector<std::string>& names = result.arm_names;
  const double clamp_mass = result.clamp_mass_kg;
  std::size_t width = 6;
  for (const std::string& name : names) width = std::max(width, name.size());
  fmt::print("linear modes: every element sticking (ei + sum c) or slipping (ei)\n");
  fmt::print("each arm, clamp held:\n");
  fmt::print("  {:<{}}  {:>9}  {:>9}  {:>9}  {:>9}\n", "arm", width, "stick 1", "stick 2", "slip 1", "slip 2");
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Eigen::Vector2d& stick = modes.stick.arms[k].frequencies_hz;
    const Eigen::Vector2d& slip = modes.slip.arms[k].frequencies_hz;
    fmt::print("  {:<{}}  {:>9.2f}  {:>9.2f}  {:>9.2f}  {:>9.2f}  Hz\n", names[k], width, stick(0), stick(1), slip(0),
               slip(1));
  }
  fmt::print("whole damper, clamp free (clamp {} kg; the rigid-body mode at 0 Hz is not listed{}):\n",
             format_value(clamp_mass), clamp_mass == 0.0 ? "; a massless clamp has one mode at infinite frequency, not listed" : "");
  std::string header =
      fmt::format("  {:<5}  {:>4}  {:>14}  kinetic energy:  {:>6}", "state", "mode", "frequency (Hz)", "clamp");
  for (const std::string& name : names) header += fmt::format("  {:>{}}", name, width);
  fmt::print("{}\n", header);
  for (const damper::LimitModes* limit : {&modes.stick, &modes.slip}) {
    for (std::size_t i = 0; i < limit->damper.size(); ++i) {
      const damper::DamperMode& mode = limit->damper[i];
      std::string line = fmt::format("  {:<5}  {:>4}  {:>14.2f}                   {:>5.0f}%",
                                     damper::cable_limit_name(limit->limit), i + 1, mode.frequency_hz,
                                     100.0 * mode.clamp_energy_share);
      for (std::size_t k = 0; k < names.size(); ++k) {
        line += fmt::format("  {:>{}.0f}%", 100.0 * mode.arm_energy_share[k], width - 1);
      }
      fmt::print("{}\n", line);
    }
  }
}

int run_modes_command(const ModesOptions& options, Invocation& invocation) {
  const damper::Damper damper =
      read_damper_input(invocation, options.damper_file, {{"-o", options.output}}, slip_policy(options.allow_unusual));
  const requests::ModesResult result = requests::run_modes(damper);
  if (!options.output.empty()) {
    io::write_file_atomically(options.output, requests::modes_table().values(requests::mode_rows(result)).csv());
  }
  if (options.json) {
    fmt::print("{}\n", requests::modes_summary(result).str());
  } else {
    print_modes_table(result);
  }
  return kSuccess;
}

}  // namespace

void add_modes_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* sub = app.add_subcommand(
      "modes", "Linear natural frequencies, every element sticking and every one slipping: each arm (clamp held) "
               "and the whole damper (clamp free)");
  sub->add_option("damper", options->damper_file, "Damper description (TOML)")->required();
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_flag("--json", options->json,
                "Print {\"arms\": [{\"name\", \"stick_hz\", \"slip_hz\"}], \"damper\": {...}} instead of the table");
  sub->add_option("-o,--output", options->output, "Also write a CSV: arm,state,mode,frequency_hz");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_modes_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
