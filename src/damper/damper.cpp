#include "stockbridge/damper/damper.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

void ArmDescription::validate(std::string_view name_in_messages) const {
  const std::string p(name_in_messages);
  require_plausible(p + ".mass", mass, "kg");
  require_plausible(p + ".inertia", inertia, "kg m^2");
  require_finite(p + ".offset", offset, "m");
  if (std::isfinite(cable.length) && cable.length > 0.0 && !(std::abs(offset) < cable.length)) {
    throw_invalid(p + ".offset", offset,
                  fmt::format("|offset| < the cable length {} m (the centre of gravity lies on the arm)", cable.length));
  }
  try {
    cable.validate();
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(fmt::format("{}.cable.{}", p, e.what()));
  }
}

bool ArmDescription::same_mechanics(const ArmDescription& other) const {
  return mass == other.mass && inertia == other.inertia && offset == other.offset && cable == other.cable;
}

void DamperDescription::validate() const {
  require_plausible_or_zero("clamp.mass", clamp_mass, "kg");
  if (arms.empty()) throw InvalidParameter("arm: expected at least one arm");
  for (std::size_t k = 0; k < arms.size(); ++k) arms[k].validate(fmt::format("arm[{}]", k));
}

namespace {
ArmDescription validated(ArmDescription d) {
  d.validate(d.name.empty() ? "arm" : d.name);
  return d;
}
}  // namespace

Arm::Arm(ArmDescription description)
    : description_(validated(std::move(description))), cable_(description_.cable) {
  const double m = description_.mass, b = description_.offset;
  mass_matrix_ << m, -m * b, -m * b, description_.inertia + m * b * b;
  load_vector_ << -m, m * b;
}

Eigen::Matrix2d Arm::stick_stiffness() const {
  return cable::CableState::virgin(cable_).tip_stiffness(cable_.length());
}

Eigen::Vector2d Arm::natural_frequencies(double uniform_ei) const {
  const double l = cable_.length();
  Eigen::Matrix2d k;  // classical clamped-free beam tip stiffness, (F, Q) over (x, phi)
  k << 12.0 * uniform_ei / (l * l * l), -6.0 * uniform_ei / (l * l), -6.0 * uniform_ei / (l * l), 4.0 * uniform_ei / l;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(k, mass_matrix_);
  return solver.eigenvalues().cwiseSqrt() / (2.0 * std::numbers::pi);
}

Excitation Excitation::from_velocity(double frequency_hz, double velocity_amplitude) {
  require_positive("frequency", frequency_hz, "Hz");
  require_positive("velocity", velocity_amplitude, "m/s");
  return {frequency_hz, velocity_amplitude / (2.0 * std::numbers::pi * frequency_hz)};
}

double Excitation::angular_frequency() const { return 2.0 * std::numbers::pi * frequency_hz; }
double Excitation::velocity_amplitude() const { return angular_frequency() * displacement_amplitude; }
double Excitation::period() const { return 1.0 / frequency_hz; }

void Excitation::validate() const {
  require_positive("frequency", frequency_hz, "Hz");
  require_positive("displacement amplitude", displacement_amplitude, "m");
}

}  // namespace stockbridge::damper
