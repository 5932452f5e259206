#include "stockbridge/section/sinusoidal_drive.hpp"

#include <cmath>
#include <numbers>

#include "stockbridge/core/error.hpp"

namespace stockbridge::section {

void SinusoidalDrive::validate() const {
  require_non_negative("amplitude", amplitude, "1/m");
  require_in_range("cycles", cycles, 1, 100000);
  require_in_range("points", points, 4, 10000000);
  if (static_cast<long long>(cycles) * points > 100000000LL) {
    throw InvalidParameter("cycles * points = " + std::to_string(static_cast<long long>(cycles) * points) +
                           ": expected at most 100000000 samples");
  }
}

double SinusoidalDrive::curvature(int k) const {
  return amplitude * std::sin(2.0 * std::numbers::pi * static_cast<double>(k % points) / points);
}

double LoopRecord::last_cycle_dissipation() const {
  const std::size_t n = dissipated.size();
  if (points_per_cycle <= 0 || n < static_cast<std::size_t>(points_per_cycle) + 1) return 0.0;
  return dissipated[n - 1] - dissipated[n - 1 - static_cast<std::size_t>(points_per_cycle)];
}

LoopRecord run_loop(SectionLaw& section, const SinusoidalDrive& drive) {
  drive.validate();
  const int samples = drive.cycles * drive.points + 1;
  LoopRecord record;
  record.points_per_cycle = drive.points;
  record.curvature.reserve(samples);
  record.moment.reserve(samples);
  record.dissipated.reserve(samples);
  for (int k = 0; k < samples; ++k) {
    section.set_trial_curvature(drive.curvature(k));
    section.commit();
    record.curvature.push_back(section.curvature());
    record.moment.push_back(section.moment());
    record.dissipated.push_back(section.dissipated_energy());
  }
  return record;
}

}  // namespace stockbridge::section
