#include "stockbridge/damper/damper.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

bool ArmDescription::same_mechanics(const ArmDescription& other) const {
  return mass == other.mass && inertia == other.inertia && offset == other.offset && cable == other.cable;
}

bool DamperDescription::same_mechanics(const DamperDescription& other) const {
  if (clamp_mass != other.clamp_mass || arms.size() != other.arms.size()) return false;
  for (std::size_t k = 0; k < arms.size(); ++k) {
    if (!arms[k].same_mechanics(other.arms[k])) return false;
  }
  return true;
}

namespace {

/// The arm's own numbers (the cable validates itself when it is built).
ArmDescription validated_arm(ArmDescription d) {
  require_plausible("mass", d.mass, "kg");
  require_plausible("inertia", d.inertia, "kg m^2");
  require_finite("offset", d.offset, "m");
  return d;
}

void require_offset_on_arm(double offset, double length) {
  if (!(std::abs(offset) < length)) {
    throw_invalid("offset", offset,
                  fmt::format("|offset| < the cable length {} m (the centre of gravity lies on the arm)", length));
  }
}

}  // namespace

Arm::Arm(ArmDescription description)
    : description_(validated_arm(std::move(description))),
      cable_(within_field("cable", [&] { return cable::Cable(description_.cable); })) {
  require_offset_on_arm(description_.offset, cable_.length());
  const double m = description_.mass, b = description_.offset;
  mass_matrix_ << m, -m * b, -m * b, description_.inertia + m * b * b;
  load_vector_ << -m, m * b;
}

std::vector<UnusualValue> DamperDescription::unusual_values() const {
  std::vector<UnusualValue> found;
  if (clamp_mass != 0.0) check_typical(found, "clamp.mass", clamp_mass, typical::clamp_mass);
  for (std::size_t k = 0; k < arms.size(); ++k) {
    const ArmDescription& arm = arms[k];
    const std::string name = fmt::format("arm[{}]", k);
    check_typical(found, name + ".mass", arm.mass, typical::arm_mass);
    check_typical(found, name + ".inertia", arm.inertia, typical::arm_inertia);
    check_typical(found, name + ".offset", arm.offset, typical::arm_offset);
    for (UnusualValue& u : arm.cable.unusual_values()) {
      u.field = name + ".cable." + u.field;
      found.push_back(std::move(u));
    }
  }
  return found;
}

Damper::Damper(DamperDescription description) : description_(std::move(description)) {
  require_plausible_or_zero("clamp.mass", description_.clamp_mass, "kg");
  if (description_.arms.empty()) throw InvalidParameter("arm", ": expected at least one arm");
  arms_.reserve(description_.arms.size());
  for (std::size_t k = 0; k < description_.arms.size(); ++k) {
    arms_.push_back(within_field(fmt::format("arm[{}]", k), [&] { return Arm(description_.arms[k]); }));
  }
  representative_.resize(arms_.size());
  for (std::size_t k = 0; k < arms_.size(); ++k) {
    representative_[k] = k;
    for (std::size_t j = 0; j < k; ++j) {
      if (description_.arms[k].same_mechanics(description_.arms[j])) {
        representative_[k] = representative_[j];
        break;
      }
    }
    if (representative_[k] == k) distinct_.push_back(k);
  }
}

std::string Damper::arm_label(std::size_t k) const {
  const std::string& name = description_.arms[k].name;
  return name.empty() ? arm_name(k) : "arm " + name;
}

double Damper::total_mass() const {
  double total = clamp_mass();
  for (const Arm& arm : arms_) total += arm.description().mass;
  return total;
}

std::string Damper::arm_name(std::size_t k) const {
  const std::string& name = description_.arms[k].name;
  return name.empty() ? fmt::format("arm {}", k + 1) : name;
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
