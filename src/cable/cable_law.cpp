#include "stockbridge/cable/cable_law.hpp"

#include "stockbridge/cable/cable_description.hpp"

namespace stockbridge::cable {

std::shared_ptr<const CableLaw> make_cable_law(const CableDescription& description, std::span<const double> positions,
                                               std::span<const double> weights) {
  return description.law->make(description, positions, weights);
}

}  // namespace stockbridge::cable
