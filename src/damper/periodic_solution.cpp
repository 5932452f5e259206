#include "stockbridge/damper/periodic_solution.hpp"

#include <cmath>
#include <numbers>

namespace stockbridge::damper {

std::complex<double> first_harmonic(const Eigen::Ref<const Eigen::RowVectorXd>& samples) {
  const Eigen::Index n = samples.size();
  std::complex<double> sum = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n);
    sum += samples(j) * std::complex<double>(std::cos(angle), -std::sin(angle));
  }
  return 2.0 * sum / static_cast<double>(n);
}

std::complex<double> arm_force_first_harmonic(const ArmPeriod& period) {
  return -first_harmonic(period.loads.row(0));
}

double energy_error(const ArmPeriod& period, const Excitation& excitation) {
  const double v = excitation.velocity_amplitude();
  const std::complex<double> f1 = arm_force_first_harmonic(period);
  const double power = 0.5 * v * f1.real();  // V^2 Re(Z) / 2 with Z = F1 / V
  const double dissipated_power = period.dissipated / excitation.period();
  const double apparent = 0.5 * v * std::abs(f1);
  return apparent > 0.0 ? std::abs(power - dissipated_power) / apparent : std::abs(power - dissipated_power);
}

}  // namespace stockbridge::damper
