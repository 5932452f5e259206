#include "stockbridge/damper/periodic_solution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stockbridge::damper {

void ArmPeriod::resize(int samples) {
  kinematics.resize(2, samples);
  loads.resize(2, samples);
  clamp_moment.resize(static_cast<std::size_t>(samples));
  clamp_curvature.resize(static_cast<std::size_t>(samples));
  clamp_section_moment.resize(static_cast<std::size_t>(samples));
}

void ArmPeriod::complete_half_wave() {
  const Eigen::Index half = loads.cols() / 2;
  loads.rightCols(half) = -loads.leftCols(half);
  for (std::vector<double>* samples : {&clamp_moment, &clamp_curvature, &clamp_section_moment}) {
    const auto h = static_cast<std::ptrdiff_t>(half);
    std::transform(samples->begin(), samples->begin() + h, samples->begin() + h, [](double v) { return -v; });
  }
}

void ArmPeriod::record_loads(int j, const cable::CableState& state, const cable::Cable& cable) {
  const auto k = static_cast<std::size_t>(j);
  loads(0, j) = state.tip_force;
  loads(1, j) = state.tip_moment(cable.length());
  clamp_moment[k] = state.clamp_moment;
  clamp_curvature[k] = state.curvature.front();
  clamp_section_moment[k] = state.clamp_moment - state.tip_force * cable.positions().front();
}

std::vector<double> time_grid(const Excitation& excitation, int samples) {
  std::vector<double> t(static_cast<std::size_t>(samples));
  for (int j = 0; j < samples; ++j) t[static_cast<std::size_t>(j)] = excitation.period() * j / samples;
  return t;
}

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

namespace {

/// Half the range of `values`: the amplitude of their oscillation about its centre.
template <class Values>
double half_range(const Values& values) {
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return low == values.end() ? 0.0 : 0.5 * (*high - *low);
}

}  // namespace

ArmFigures arm_figures(const ArmPeriod& period, const Arm& arm, const Excitation& excitation) {
  const double v = excitation.velocity_amplitude();
  ArmFigures figures;
  figures.impedance = arm_force_first_harmonic(period) / v;
  figures.power = 0.5 * v * v * figures.impedance.real();
  const Eigen::RowVectorXd mass = period.kinematics.row(0) - arm.description().offset * period.kinematics.row(1);
  figures.mass_amplitude = half_range(mass);
  figures.clamp_curvature_amplitude = half_range(period.clamp_curvature);
  return figures;
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
