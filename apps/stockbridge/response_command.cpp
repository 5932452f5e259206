// stockbridge response: one steady period of a damper at one frequency and amplitude.

#include <cmath>
#include <limits>
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
#include "stockbridge/io/csv_writer.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/plausibility.hpp"
#include "stockbridge/requests/sweep_request.hpp"

namespace stockbridge::cli {

namespace {

constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

struct ResponseOptions {
  std::string damper_file;
  double frequency = 0.0;
  std::optional<double> velocity;
  std::optional<double> displacement;
  SolverFlags solver;
  bool json = false;
  std::string output;
};

/// One period of every arm; a point that did not converge is written as its last
/// iterate with converged = 0, an arm without any period as empty cells.
std::string response_csv(const damper::Damper& damper, const damper::Excitation& excitation,
                         const damper::DamperSteadyState& state) {
  std::vector<std::string> header{"time_s", "clamp_displacement_m", "clamp_velocity_m_s", "shaker_force_n"};
  for (const std::string& arm : requests::arm_column_prefixes(damper)) {
    for (const char* column : {"x_m", "phi_rad", "force_n", "clamp_moment_n_m", "tip_moment_n_m",
                               "clamp_curvature_per_m", "clamp_section_moment_n_m"}) {
      header.push_back(fmt::format("{}_{}", arm, column));
    }
  }
  header.push_back("converged");
  io::CsvWriter csv(header);
  Eigen::Index n = 0;
  std::vector<const damper::ArmSolution*> arms;
  for (const damper::ArmSolution& s : state.arms) {
    arms.push_back(&s);
    n = std::max(n, s.period.loads.cols());
  }
  const Eigen::RowVectorXd force = damper::shaker_force(damper, excitation, arms);
  const bool complete = force.size() == n;
  const std::vector<double> time = damper::time_grid(excitation, static_cast<int>(n));
  const double w = excitation.angular_frequency(), x = excitation.displacement_amplitude;
  std::vector<double> row;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double t = time[static_cast<std::size_t>(j)];
    row = {t, x * std::sin(w * t), w * x * std::cos(w * t), complete ? force(j) : kNotComputed};
    for (const damper::ArmSolution& s : state.arms) {
      const damper::ArmPeriod& p = s.period;
      if (j >= p.loads.cols()) {
        row.insert(row.end(), 7, kNotComputed);
        continue;
      }
      const auto i = static_cast<std::size_t>(j);
      row.insert(row.end(), {p.kinematics(0, j), p.kinematics(1, j), p.loads(0, j), p.clamp_moment[i], p.loads(1, j),
                             p.clamp_curvature[i], p.clamp_section_moment[i]});
    }
    row.push_back(state.point.converged() ? 1.0 : 0.0);
    csv.add_row(row);
  }
  return csv.text();
}

int run_response_command(const ResponseOptions& options) {
  if (options.velocity.has_value() == options.displacement.has_value()) {  // named by the flags
    throw InvalidParameter("give either --velocity V (m/s) or --displacement X (m)");
  }
  const damper::Excitation excitation = requests::excitation(options.frequency, options.velocity, options.displacement);
  const damper::SolverOptions solver = requests::solver_options(options.solver.settings());
  const damper::Damper damper = read_damper_input(options.damper_file, {{"-o", options.output}});
  warn_unusual_options(requests::unusual_excitation(options.frequency, options.velocity, options.displacement));
  const damper::DamperSteadyState state = damper::solve_steady_state(damper, excitation, solver);
  const damper::ImpedancePoint& p = state.point;
  // Written even when not converged (the last iterate, marked), so that it can be inspected.
  io::write_file_atomically(options.output, response_csv(damper, excitation, state));
  // The design figures by the impedance CSV's names, through the same function.
  const std::vector<std::string> figure_names = requests::figure_columns(damper);
  const std::vector<double> figures = requests::figure_values(p);
  if (options.json) {
    io::JsonObject json;
    json.add("frequency_hz", p.frequency_hz)
        .add("velocity_m_s", p.velocity_amplitude)
        .add("displacement_m", p.displacement_amplitude)
        .add("converged", p.converged())
        .add("termination", termination_name(p.termination))
        .add("re_z_n_s_m", p.converged() ? p.impedance.real() : kNotComputed)
        .add("im_z_n_s_m", p.converged() ? p.impedance.imag() : kNotComputed)
        .add("power_w", p.converged() ? p.power : kNotComputed)
        .add("dissipated_power_w", p.converged() ? p.dissipated_power : kNotComputed)
        .add("energy_error", p.energy_error);
    for (std::size_t i = 0; i < figure_names.size(); ++i) json.add(figure_names[i], figures[i]);
    fmt::print("{}\n", json.str());
  }
  if (!p.converged()) {
    fmt::print(stderr, "response: no steady state at {} Hz: {}; {} holds the last iterate, not a solution\n",
               options.frequency, p.failure, options.output);
    return kNotConverged;
  }
  fmt::print(stderr, "response: {} Hz, V = {:.4g} m/s: Z = {:.5g} {:+.5g}i N s/m, P = {:.4g} W (sliders {:.4g} W)\n",
             p.frequency_hz, p.velocity_amplitude, p.impedance.real(), p.impedance.imag(), p.power, p.dissipated_power);
  // figures: the messenger's curvature, then (power, mass amplitude) per arm.
  std::string arms;
  for (std::size_t k = 0; k < damper.arms().size(); ++k) {
    arms += fmt::format("; {}: P = {:.4g} W, mass amplitude {:.4g} mm", damper.arm_label(k), figures[1 + 2 * k],
                        1e3 * figures[2 + 2 * k]);
  }
  fmt::print(stderr, "response: messenger curvature amplitude {:.4g} 1/m (the largest at the arms' clamps){}\n", figures[0], arms);
  return kSuccess;
}

}  // namespace

void add_response_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ResponseOptions>();
  CLI::App* sub = app.add_subcommand("response", "One steady period of a damper: clamp motion, shaker force, each arm's motion and cable loads");
  sub->add_option("damper", options->damper_file, "Damper description (TOML)")->required();
  sub->add_option("--frequency", options->frequency, "Frequency, Hz")->required();
  sub->add_option("--velocity", options->velocity, "Clamp velocity amplitude V, m/s");
  sub->add_option("--displacement", options->displacement, "Clamp displacement amplitude X, m (instead of --velocity)");
  options->solver.add_to(*sub);
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout");
  sub->add_option("-o,--output", options->output, "Output CSV file")->required();
  sub->callback([options, &exit_code] { exit_code = run_response_command(*options); });
}

}  // namespace stockbridge::cli
