// stockbridge loop: drive one Masing section with a sinusoidal curvature and
// write its moment-curvature loop.

#include <memory>
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
  double ei = 0.0;
  std::vector<std::string> jenkin;
  section::SinusoidalDrive drive;
  std::string law{requests::default_section_law};
  double exponent = requests::default_regularised_exponent;
  std::string output;
};

int run_loop_command(const LoopOptions& options) {
  section::MasingParameters parameters{options.ei, {}};
  for (std::size_t j = 0; j < options.jenkin.size(); ++j) {
    parameters.jenkin.push_back(parse_jenkin_pair(options.jenkin[j], fmt::format("--jenkin #{}", j + 1)));
  }
  const section::LoopRecord record = requests::section_loop(parameters, options.drive, options.law, options.exponent);

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
  sub->add_option("--ei", options->ei, "Elastic (minimum) bending stiffness, N m^2")->required();
  sub->add_option("--jenkin", options->jenkin, "A Jenkin element as c:h (N m^2 : N m); repeat for more");
  sub->add_option("--amplitude", options->drive.amplitude, "Curvature amplitude A, 1/m")->required();
  sub->add_option("--cycles", options->drive.cycles, "Number of cycles")->capture_default_str();
  sub->add_option("--points", options->drive.points, "Samples per cycle")->capture_default_str();
  sub->add_option("--law", options->law, "Section law")
      ->check(CLI::IsMember({"exact", "regularised"}))
      ->capture_default_str();
  sub->add_option("--exponent", options->exponent, "Exponent n of the regularised law (3.15)")->capture_default_str();
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &exit_code] { exit_code = run_loop_command(*options); });
}

}  // namespace stockbridge::cli
