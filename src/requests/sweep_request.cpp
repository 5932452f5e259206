#include "stockbridge/requests/sweep_request.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "stockbridge/core/error.hpp"

namespace stockbridge::requests {

namespace {
constexpr const char* kOneAmplitudeKind = "give either velocity (m/s) or displacement (m) amplitudes, one of the two";
}  // namespace

damper::Excitation excitation(double frequency_hz, std::optional<double> velocity, std::optional<double> displacement) {
  if (velocity.has_value() == displacement.has_value()) throw InvalidParameter(kOneAmplitudeKind);
  const damper::Excitation e = velocity ? damper::Excitation::from_velocity(frequency_hz, *velocity)
                                        : damper::Excitation{frequency_hz, *displacement};
  e.validate();
  return e;
}

damper::SweepSpec sweep_spec(const SweepRequest& request) {
  damper::SweepSpec spec;
  if (request.velocities.empty() == request.displacements.empty()) throw InvalidParameter(kOneAmplitudeKind);
  spec.constant_displacement = !request.displacements.empty();
  spec.amplitudes = spec.constant_displacement ? request.displacements : request.velocities;
  spec.frequencies = request.frequencies.empty()
                         ? damper::log_spaced(request.grid.fmin, request.grid.fmax, request.grid.points)
                         : request.frequencies;
  spec.solver = solver_options(request.solver);
  spec.threads = request.threads;
  spec.validate();
  return spec;
}

namespace {

/// The columns every point has, whatever the damper.
const std::vector<std::string>& point_columns() {
  static const std::vector<std::string> columns{
      "frequency_hz", "velocity_m_s", "re_z_n_s_m", "im_z_n_s_m",         "abs_z_n_s_m", "phase_deg",
      "power_w",      "converged",    "displacement_m", "dissipated_power_w", "energy_error", "residual",
      "iterations",   "periods",      "non_unique"};
  return columns;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A value that is round-off of zero relative to `scale` (|value| < 1e-12 scale) as 0.
double without_round_off(double value, double scale) { return std::abs(value) < 1e-12 * scale ? 0.0 : value; }

/// The apparent power V^2 |Z| / 2 of an impedance at the velocity amplitude v.
double apparent_power(double v, std::complex<double> z) { return 0.5 * v * v * std::abs(z); }

}  // namespace

std::vector<std::string> impedance_columns(const damper::Damper& damper) {
  std::vector<std::string> columns = point_columns();
  const std::vector<std::string> figures = figure_columns(damper);
  columns.insert(columns.end(), figures.begin(), figures.end());
  return columns;
}

std::vector<double> impedance_row(const damper::ImpedancePoint& p) {
  const bool ok = p.converged();
  const auto masked = [ok](double value) { return ok ? value : kNaN; };
  // Where nothing slips, Re Z and P are zero but for round-off (1e-16 of |Z|): shown as 0.
  const double magnitude = std::abs(p.impedance);
  const std::complex<double> z(without_round_off(p.impedance.real(), magnitude), p.impedance.imag());
  std::vector<double> row{p.frequency_hz,
                          p.velocity_amplitude,
                          masked(z.real()),
                          masked(z.imag()),
                          masked(std::abs(z)),
                          masked(std::arg(z) * 180.0 / std::numbers::pi),
                          masked(without_round_off(p.power, apparent_power(p.velocity_amplitude, p.impedance))),
                          ok ? 1.0 : 0.0,
                          p.displacement_amplitude,
                          masked(p.dissipated_power),
                          masked(p.energy_error),
                          masked(p.residual),
                          static_cast<double>(p.newton_iterations),
                          static_cast<double>(p.periods),
                          p.non_unique ? 1.0 : 0.0};
  const std::vector<double> figures = figure_values(p);
  row.insert(row.end(), figures.begin(), figures.end());
  return row;
}

std::vector<std::string> figure_columns(const damper::Damper& damper) {
  std::vector<std::string> columns{"messenger_curvature_max_per_m"};
  for (const std::string& arm : arm_column_prefixes(damper)) {
    columns.push_back(arm + "_power_w");
    columns.push_back(arm + "_mass_amplitude_m");
  }
  return columns;
}

std::vector<double> figure_values(const damper::ImpedancePoint& p) {
  const bool ok = p.converged();
  std::vector<double> values{ok ? p.messenger_curvature_max : kNaN};
  for (const damper::ArmFigures& arm : p.arms) {
    // An arm that does not slip takes no power but for round-off of its own |Z_k|: 0, as the damper's.
    values.push_back(ok ? without_round_off(arm.power, apparent_power(p.velocity_amplitude, arm.impedance)) : kNaN);
    values.push_back(ok ? arm.mass_amplitude : kNaN);
  }
  return values;
}

std::vector<std::string> arm_column_prefixes(const damper::Damper& damper) {
  std::vector<std::string> names;
  bool usable = true;
  for (const damper::ArmDescription& arm : damper.description().arms) {
    const bool word = !arm.name.empty() && std::all_of(arm.name.begin(), arm.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    });
    // A name that would make one of an arm's columns one of the table's own
    // (dissipated_power_w of the impedance CSV, shaker_force_n of the response CSV).
    const bool reserved = arm.name == "dissipated" || arm.name == "shaker";
    usable = usable && word && !reserved && std::find(names.begin(), names.end(), arm.name) == names.end();
    names.push_back(arm.name);
  }
  if (usable) return names;
  for (std::size_t k = 0; k < names.size(); ++k) names[k] = "arm" + std::to_string(k + 1);
  return names;
}

SweepTally tally(const std::vector<damper::SweepRun>& runs) {
  SweepTally t;
  for (const damper::SweepRun& run : runs) {
    for (const damper::ImpedancePoint& p : run.points) {
      ++t.points;
      t.non_unique += p.non_unique;
      if (!p.converged()) continue;
      ++t.converged;
      t.max_energy_error = std::max(t.max_energy_error.value_or(0.0), p.energy_error);
    }
  }
  return t;
}

}  // namespace stockbridge::requests
