// stockbridge response: one steady period of a damper at one frequency and amplitude.

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "solver_options.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/plausibility.hpp"
#include "stockbridge/requests/response_request.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::cli {

namespace {

struct ResponseOptions {
  std::string damper_file;
  double frequency = 0.0;
  std::optional<double> velocity;
  std::optional<double> displacement;
  SolverFlags solver;
  bool json = false;
  bool allow_unusual = false;
  std::string output;
};

int run_response_command(const ResponseOptions& options, Invocation& invocation) {
  if (options.velocity.has_value() == options.displacement.has_value()) {  // named by the flags
    throw InvalidParameter("give either --velocity V (m/s) or --displacement X (m)");
  }
  const requests::ResponseRequest request{options.frequency, options.velocity, options.displacement,
                                          options.solver.settings()};
  requests::validate(request);  // before the damper file is read: a bad option is named first
  refuse_slipped_options(requests::unusual_excitation(request.frequency, request.velocity, request.displacement),
                         slip_policy(options.allow_unusual));
  const damper::Damper damper =
      read_damper_input(invocation, options.damper_file, {{"-o", options.output}}, slip_policy(options.allow_unusual));
  const requests::ResponseResult result = requests::run_response(damper, request);
  print_warnings(invocation, result.warnings);
  const damper::ImpedancePoint& p = result.state.point;
  // Written even when not converged (the last iterate, marked), so that it can be inspected.
  io::write_file_atomically(options.output,
                            requests::response_table(damper).values(requests::response_samples(result)).csv());
  if (options.json) fmt::print("{}\n", requests::response_summary(damper, result).str());
  if (!p.converged()) {
    fmt::print(stderr, "response: no steady state at {} Hz: {}; {} holds the last iterate, not a solution\n",
               options.frequency, p.failure, options.output);
    return kNotConverged;
  }
  fmt::print(stderr, "response: {} Hz, V = {:.4g} m/s: Z = {:.5g} {:+.5g}i N s/m, P = {:.4g} W (sliders {:.4g} W)\n",
             p.frequency_hz, p.velocity_amplitude, p.impedance.real(), p.impedance.imag(), p.power, p.dissipated_power);
  // The design figures by the impedance CSV's names, through the same quantities.
  const requests::TableValues figures = requests::point_summary_table(damper).values(p);
  const std::vector<std::string> prefixes = requests::arm_column_prefixes(damper);
  std::string arms;
  for (std::size_t k = 0; k < damper.arms().size(); ++k) {
    arms += fmt::format("; {}: P = {:.4g} W, mass amplitude {:.4g} mm", damper.arm_label(k),
                        figures.column(prefixes[k] + "_power_w").numbers[0],
                        1e3 * figures.column(prefixes[k] + "_mass_amplitude_m").numbers[0]);
  }
  fmt::print(stderr, "response: messenger curvature amplitude {:.4g} 1/m (the largest at the arms' clamps){}\n",
             figures.column("messenger_curvature_max_per_m").numbers[0], arms);
  return kSuccess;
}

}  // namespace

void add_response_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<ResponseOptions>();
  CLI::App* sub = app.add_subcommand("response", "One steady period of a damper: clamp motion, shaker force, each arm's motion and cable loads");
  sub->add_option("damper", options->damper_file, "Damper description (TOML)")->required();
  sub->add_option("--frequency", options->frequency, "Frequency, Hz")->required();
  sub->add_option("--velocity", options->velocity, "Clamp velocity amplitude V, m/s");
  sub->add_option("--displacement", options->displacement, "Clamp displacement amplitude X, m (instead of --velocity)");
  options->solver.add_to(*sub);
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &invocation] { invocation.set_exit_code(run_response_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
