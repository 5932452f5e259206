#include "stockbridge/requests/sweep_request.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
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

const std::vector<std::string>& impedance_columns() {
  static const std::vector<std::string> columns{
      "frequency_hz", "velocity_m_s", "re_z_n_s_m", "im_z_n_s_m",         "abs_z_n_s_m", "phase_deg",
      "power_w",      "converged",    "displacement_m", "dissipated_power_w", "energy_error", "residual",
      "iterations",   "periods",      "non_unique"};
  return columns;
}

namespace {
/// A value that is round-off of zero relative to `scale` (|value| < 1e-12 scale) as 0.
double without_round_off(double value, double scale) { return std::abs(value) < 1e-12 * scale ? 0.0 : value; }
}  // namespace

std::vector<double> impedance_row(const damper::ImpedancePoint& p) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const bool ok = p.converged();
  const auto masked = [ok](double value) { return ok ? value : kNaN; };
  // Where nothing slips, Re Z and P are zero but for round-off (1e-16 of |Z|): shown as 0.
  const double magnitude = std::abs(p.impedance);
  const double apparent_power = 0.5 * p.velocity_amplitude * p.velocity_amplitude * magnitude;
  const std::complex<double> z(without_round_off(p.impedance.real(), magnitude), p.impedance.imag());
  return {p.frequency_hz,
          p.velocity_amplitude,
          masked(z.real()),
          masked(z.imag()),
          masked(std::abs(z)),
          masked(std::arg(z) * 180.0 / std::numbers::pi),
          masked(without_round_off(p.power, apparent_power)),
          ok ? 1.0 : 0.0,
          p.displacement_amplitude,
          masked(p.dissipated_power),
          masked(p.energy_error),
          masked(p.residual),
          static_cast<double>(p.newton_iterations),
          static_cast<double>(p.periods),
          p.non_unique ? 1.0 : 0.0};
}

std::vector<std::string> arm_column_prefixes(const damper::Damper& damper) {
  std::vector<std::string> names;
  bool usable = true;
  for (const damper::ArmDescription& arm : damper.description().arms) {
    const bool word = !arm.name.empty() && std::all_of(arm.name.begin(), arm.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    });
    usable = usable && word && std::find(names.begin(), names.end(), arm.name) == names.end();
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
