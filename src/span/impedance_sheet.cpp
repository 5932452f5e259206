#include "stockbridge/span/impedance_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

ImpedanceSheet::ImpedanceSheet(damper::ImpedanceMeasurement measurement, std::string name)
    : held_(measurement.held), name_(std::move(name)) {
  measurement.validate();
  for (const std::vector<std::size_t>& indices : damper::measured_curves(measurement)) {
    Curve curve;
    for (const std::size_t i : indices) {
      const damper::MeasuredImpedance& p = measurement.points[i];
      const double log_f = std::log(p.excitation.frequency_hz);
      if (!curve.log_f.empty() && !(log_f > curve.log_f.back())) continue;  // a repeated frequency: the first
      curve.log_f.push_back(log_f);
      curve.z.push_back(p.impedance);
      curve.amplitude = held_ == damper::HeldAmplitude::velocity ? p.excitation.velocity_amplitude()
                                                                 : p.excitation.displacement_amplitude;
    }
    if (curve.log_f.size() >= 2) curves_.push_back(std::move(curve));
  }
  if (curves_.size() < 2) {
    throw InvalidParameter(name_, fmt::format(": {} curve(s) of two or more frequencies: expected at least two "
                                              "amplitudes measured over the band (Z between them is interpolated); "
                                              "a sheet of one amplitude takes fit_from = the damper's file (its "
                                              "drawing) and free = [its numbers to fit]: the damper's model fitted to "
                                              "the sheet, as identify impedance --free",
                                              curves_.size()));
  }
  const Interval covered = frequency_range();
  if (!(covered.lo < covered.hi)) {
    throw InvalidParameter(name_, ": no two curves were measured over a common band of frequencies: expected at "
                                  "least two amplitudes measured over the same frequencies (Z between them is "
                                  "interpolated)");
  }
}

ImpedanceSheet::ImpedanceSheet(std::vector<Curve> curves, damper::HeldAmplitude held, std::string name)
    : curves_(std::move(curves)), held_(held), name_(std::move(name)) {}

Interval ImpedanceSheet::frequency_range() const {
  // The frequencies covered by at least two curves: sort the curves' ends.
  std::vector<double> starts, ends;
  for (const Curve& c : curves_) {
    starts.push_back(c.log_f.front());
    ends.push_back(c.log_f.back());
  }
  std::sort(starts.begin(), starts.end());
  std::sort(ends.begin(), ends.end(), std::greater<>());
  return {std::exp(starts[1]), std::exp(ends[1])};
}

std::vector<SheetNode> ImpedanceSheet::nodes_at(double frequency) const {
  const double log_f = std::log(frequency);
  std::vector<SheetNode> nodes;
  for (const Curve& c : curves_) {
    if (log_f < c.log_f.front() || log_f > c.log_f.back()) continue;
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(c.log_f.begin(), c.log_f.end(), log_f) - c.log_f.begin()),
        c.log_f.size() - 1);
    const double t = (log_f - c.log_f[k - 1]) / (c.log_f[k] - c.log_f[k - 1]);
    const double velocity = held_ == damper::HeldAmplitude::velocity
                                ? c.amplitude
                                : 2.0 * std::numbers::pi * frequency * c.amplitude;
    nodes.push_back({velocity, (1.0 - t) * c.z[k - 1] + t * c.z[k]});
  }
  std::sort(nodes.begin(), nodes.end(), [](const SheetNode& a, const SheetNode& b) { return a.velocity < b.velocity; });
  return nodes;
}

std::optional<ImpedanceSheet> ImpedanceSheet::every_other(int parity) const {
  std::vector<Curve> kept;
  for (std::size_t k = static_cast<std::size_t>(parity); k < curves_.size(); k += 2) kept.push_back(curves_[k]);
  if (kept.size() < 2) return std::nullopt;
  return ImpedanceSheet(std::move(kept), held_, fmt::format("{} (every other curve)", name_));
}

}  // namespace stockbridge::span
