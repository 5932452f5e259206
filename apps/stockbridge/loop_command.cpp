// stockbridge loop: drive one cable section (the exact Masing law, the regularised
// one, or Bouc-Wen) with a sinusoidal curvature and write its moment-curvature loop.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "option_parsing.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/requests/section_loop.hpp"

namespace stockbridge::cli {

namespace {

struct LoopOptions {
  std::optional<double> ei;
  std::vector<std::string> jenkin;
  std::optional<double> ei_min, ei_max, chi0;
  section::SinusoidalDrive drive;
  std::string law{requests::default_section_law};
  double exponent = requests::default_regularised_exponent;
  std::string output;
};

/// The loop of the law asked for, each law given its own numbers only.
section::LoopRecord loop_of(const LoopOptions& options) {
  const bool bouc_wen = options.law == "bouc-wen";
  const bool masing_numbers = options.ei || !options.jenkin.empty();
  const bool bouc_wen_numbers = options.ei_min || options.ei_max || options.chi0;
  if (bouc_wen) {
    if (masing_numbers) {
      throw InvalidParameter("--law bouc-wen takes --ei-min, --ei-max and --chi0, not --ei or --jenkin");
    }
    if (!options.ei_min || !options.ei_max || !options.chi0) {
      throw InvalidParameter("--law bouc-wen needs --ei-min, --ei-max (N m^2) and --chi0 (1/m)");
    }
    return requests::bouc_wen_loop({*options.ei_min, *options.ei_max, *options.chi0}, options.drive);
  }
  if (bouc_wen_numbers) {
    throw InvalidParameter(fmt::format("--ei-min, --ei-max and --chi0 are the Bouc-Wen law's: --law {} takes --ei and "
                                       "--jenkin",
                                       options.law));
  }
  if (!options.ei) throw InvalidParameter(fmt::format("--law {} needs --ei (N m^2)", options.law));
  section::MasingParameters parameters{*options.ei, {}};
  for (std::size_t j = 0; j < options.jenkin.size(); ++j) {
    parameters.jenkin.push_back(parse_jenkin_pair(options.jenkin[j], fmt::format("--jenkin #{}", j + 1)));
  }
  return requests::section_loop(parameters, options.drive, options.law, options.exponent);
}

int run_loop_command(const LoopOptions& options) {
  const section::LoopRecord record = loop_of(options);

  io::write_file_atomically(options.output, requests::loop_table().values(requests::loop_samples(record)).csv());
  fmt::print(stderr, "loop: {} law, {} cycles x {} points: dissipated energy in the last cycle {} J/m\n",
             options.law, options.drive.cycles, options.drive.points, record.last_cycle_dissipation());
  return kSuccess;
}

}  // namespace

void add_loop_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<LoopOptions>();
  CLI::App* sub = app.add_subcommand(
      "loop", "Drive one cable section with kappa = A sin(2 pi k / points) and write its moment-curvature loop");
  sub->add_option("--ei", options->ei, "Elastic (minimum) bending stiffness, N m^2 (exact and regularised laws)");
  sub->add_option("--jenkin", options->jenkin, "A Jenkin element as c:h (N m^2 : N m); repeat for more");
  sub->add_option("--ei-min", options->ei_min, "Bouc-Wen: the free wires' (asymptotic) stiffness EI_min, N m^2");
  sub->add_option("--ei-max", options->ei_max, "Bouc-Wen: the no-slip (initial) stiffness EI_max, N m^2");
  sub->add_option("--chi0", options->chi0, "Bouc-Wen: the curvature scale chi0 of the transition, 1/m");
  sub->add_option("--amplitude", options->drive.amplitude, "Curvature amplitude A, 1/m")->required();
  sub->add_option("--cycles", options->drive.cycles, "Number of cycles")->capture_default_str();
  sub->add_option("--points", options->drive.points, "Samples per cycle")->capture_default_str();
  sub->add_option("--law", options->law,
                  "Section law: exact (Masing), regularised (3.15) or bouc-wen (MODEL.md 13: --ei-min, --ei-max, --chi0)")
      ->check(CLI::IsMember({"exact", "regularised", "bouc-wen"}))
      ->capture_default_str();
  sub->add_option("--exponent", options->exponent, "Exponent n of the regularised law (3.15)")->capture_default_str();
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &exit_code] { exit_code = run_loop_command(*options); });
}

}  // namespace stockbridge::cli
