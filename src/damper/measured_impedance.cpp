// A measured impedance checked, and its points grouped into curves
// (damper/measured_impedance.hpp).
#include "stockbridge/damper/measured_impedance.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

namespace {

/// Points whose held amplitudes lie within this ratio of a curve's smallest belong to it.
constexpr double kCurveAmplitudeRatio = 1.1;

double held_amplitude(const Excitation& e, HeldAmplitude held) {
  return held == HeldAmplitude::velocity ? e.velocity_amplitude() : e.displacement_amplitude;
}

}  // namespace

void ImpedanceMeasurement::validate() const {
  if (points.empty()) throw InvalidParameter("measurement", ": no points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const MeasuredImpedance& p = points[i];
    const std::string at = fmt::format("point {}: ", i + 1);
    require_plausible(at + "frequency_hz", p.excitation.frequency_hz, "Hz");
    require_positive(at + "displacement_m", p.excitation.displacement_amplitude, "m");
    if (!std::isfinite(p.impedance.real()) || !std::isfinite(p.impedance.imag()) || p.impedance == 0.0) {
      throw InvalidParameter(at + "Z", fmt::format(" = {} + {} i N s/m: expected finite and nonzero",
                                                   format_value(p.impedance.real()), format_value(p.impedance.imag())));
    }
    // The misfit divides by |Z|: a magnitude no damper has (a unit mistake) would
    // overflow it (|Z| = 1e-310 made every residual infinite).
    if (const double magnitude = std::abs(p.impedance); magnitude < smallest_magnitude || magnitude > largest_magnitude) {
      throw InvalidParameter(at + "|Z|", fmt::format(" = {} N s/m: expected a value from {:g} to {:g}; one outside is a "
                                                     "unit mistake",
                                                     format_value(magnitude), smallest_magnitude, largest_magnitude));
    }
  }
}

std::vector<std::vector<std::size_t>> measured_curves(const ImpedanceMeasurement& m) {
  std::vector<std::size_t> order(m.points.size());
  std::iota(order.begin(), order.end(), 0);
  auto amplitude = [&](std::size_t i) { return held_amplitude(m.points[i].excitation, m.held); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return amplitude(a) < amplitude(b); });
  std::vector<std::vector<std::size_t>> curves;
  double smallest = 0.0;
  for (const std::size_t i : order) {
    if (curves.empty() || amplitude(i) > kCurveAmplitudeRatio * smallest) {
      curves.emplace_back();
      smallest = amplitude(i);
    }
    curves.back().push_back(i);
  }
  for (std::vector<std::size_t>& curve : curves) {
    std::stable_sort(curve.begin(), curve.end(), [&](std::size_t a, std::size_t b) {
      return m.points[a].excitation.frequency_hz < m.points[b].excitation.frequency_hz;
    });
  }
  return curves;
}

}  // namespace stockbridge::damper
