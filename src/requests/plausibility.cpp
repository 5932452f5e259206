#include "stockbridge/requests/plausibility.hpp"

namespace stockbridge::requests {

std::vector<UnusualValue> unusual_values(const SweepRequest& request) {
  std::vector<UnusualValue> found;
  for (const double v : request.velocities) check_typical(found, "velocity", v, typical::velocity);
  for (const double x : request.displacements) check_typical(found, "displacement", x, typical::displacement);
  if (request.frequencies.empty()) {
    check_typical(found, "fmin", request.grid.fmin, typical::frequency);
    check_typical(found, "fmax", request.grid.fmax, typical::frequency);
  }
  for (const double f : request.frequencies) check_typical(found, "frequencies", f, typical::frequency);
  return found;
}

std::vector<UnusualValue> unusual_excitation(double frequency_hz, std::optional<double> velocity,
                                             std::optional<double> displacement) {
  std::vector<UnusualValue> found;
  check_typical(found, "frequency", frequency_hz, typical::frequency);
  if (velocity) check_typical(found, "velocity", *velocity, typical::velocity);
  if (displacement) check_typical(found, "displacement", *displacement, typical::displacement);
  return found;
}

}  // namespace stockbridge::requests
