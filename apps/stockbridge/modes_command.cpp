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
#include "stockbridge/damper/modes.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/csv_writer.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::cli {

namespace {

struct ModesOptions {
  std::string damper_file;
  bool json = false;
  std::string output;
};

/// The CSV's name of the whole damper in the arm column.
constexpr const char* kWholeDamper = "damper";

std::vector<double> modes_hz(const damper::ArmModes& arm) { return {arm.frequencies_hz(0), arm.frequencies_hz(1)}; }

std::vector<double> modes_hz(const std::vector<damper::DamperMode>& modes) {
  std::vector<double> hz;
  for (const damper::DamperMode& mode : modes) hz.push_back(mode.frequency_hz);
  return hz;
}

/// Rows arm,state,mode,frequency_hz: each arm's clamp-held modes, then the whole
/// damper's ("damper"). An arm named "damper" makes every arm arm1, arm2, ...
std::string modes_csv(const damper::DamperModes& modes, std::vector<std::string> names) {
  if (std::find(names.begin(), names.end(), kWholeDamper) != names.end()) {
    for (std::size_t k = 0; k < names.size(); ++k) names[k] = fmt::format("arm{}", k + 1);
  }
  io::CsvWriter csv({"arm", "state", "mode", "frequency_hz"});
  auto add = [&](const std::string& arm, const damper::LimitModes& limit, const std::vector<double>& hz) {
    const std::string labels[] = {arm, std::string(damper::cable_limit_name(limit.limit))};
    for (std::size_t i = 0; i < hz.size(); ++i) {
      const double values[] = {static_cast<double>(i + 1), hz[i]};
      csv.add_row(labels, values);
    }
  };
  for (std::size_t k = 0; k < names.size(); ++k) {
    for (const damper::LimitModes* limit : {&modes.stick, &modes.slip}) add(names[k], *limit, modes_hz(limit->arms[k]));
  }
  for (const damper::LimitModes* limit : {&modes.stick, &modes.slip}) add(kWholeDamper, *limit, modes_hz(limit->damper));
  return csv.text();
}

std::vector<io::JsonObject> damper_modes_json(const std::vector<damper::DamperMode>& modes,
                                              const std::vector<std::string>& names) {
  std::vector<io::JsonObject> out;
  for (const damper::DamperMode& mode : modes) {
    std::vector<io::JsonObject> arms;
    for (std::size_t k = 0; k < names.size(); ++k) {
      arms.push_back(io::JsonObject()
                         .add("name", names[k])
                         .add("x", mode.arms[k](0))
                         .add("phi", mode.arms[k](1))
                         .add("energy_share", mode.arm_energy_share[k]));
    }
    out.push_back(io::JsonObject()
                      .add("frequency_hz", mode.frequency_hz)
                      .add("dominant_arm", names[mode.dominant_arm])
                      .add("clamp_x", mode.clamp_deflection)
                      .add("clamp_energy_share", mode.clamp_energy_share)
                      .add("arms", arms));
  }
  return out;
}

std::string modes_json(const damper::Damper& damper, const damper::DamperModes& modes,
                       const std::vector<std::string>& names) {
  std::vector<io::JsonObject> arms;
  for (std::size_t k = 0; k < names.size(); ++k) {
    arms.push_back(io::JsonObject()
                       .add("name", names[k])
                       .add("stick_hz", modes_hz(modes.stick.arms[k]))
                       .add("slip_hz", modes_hz(modes.slip.arms[k])));
  }
  return io::JsonObject()
      .add("arms", arms)
      .add("damper", io::JsonObject()
                         .add("clamp_mass_kg", damper.clamp_mass())
                         .add("stick_hz", modes_hz(modes.stick.damper))
                         .add("slip_hz", modes_hz(modes.slip.damper))
                         .add("stick_modes", damper_modes_json(modes.stick.damper, names))
                         .add("slip_modes", damper_modes_json(modes.slip.damper, names)))
      .str();
}

void print_modes_table(const damper::Damper& damper, const damper::DamperModes& modes,
                       const std::vector<std::string>& names) {
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
             format_value(damper.clamp_mass()),
             damper.clamp_mass() == 0.0 ? "; a massless clamp has one mode at infinite frequency, not listed" : "");
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

int run_modes_command(const ModesOptions& options) {
  const damper::Damper damper = read_damper_input(options.damper_file, {{"-o", options.output}});
  const damper::DamperModes modes = damper::damper_modes(damper);
  const std::vector<std::string> names = requests::arm_column_prefixes(damper);
  if (!options.output.empty()) io::write_file_atomically(options.output, modes_csv(modes, names));
  if (options.json) {
    fmt::print("{}\n", modes_json(damper, modes, names));
  } else {
    print_modes_table(damper, modes, names);
  }
  return kSuccess;
}

}  // namespace

void add_modes_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* sub = app.add_subcommand(
      "modes", "Linear natural frequencies, every element sticking and every one slipping: each arm (clamp held) "
               "and the whole damper (clamp free)");
  sub->add_option("damper", options->damper_file, "Damper description (TOML)")->required();
  sub->add_flag("--json", options->json,
                "Print {\"arms\": [{\"name\", \"stick_hz\", \"slip_hz\"}], \"damper\": {...}} instead of the table");
  sub->add_option("-o,--output", options->output, "Also write a CSV: arm,state,mode,frequency_hz");
  sub->callback([options, &exit_code] { exit_code = run_modes_command(*options); });
}

}  // namespace stockbridge::cli
