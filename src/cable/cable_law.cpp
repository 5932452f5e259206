#include "stockbridge/cable/cable_law.hpp"

#include "stockbridge/cable/bouc_wen_cable_law.hpp"
#include "stockbridge/cable/masing_cable_law.hpp"

namespace stockbridge::cable {

std::shared_ptr<const CableLaw> make_cable_law(const CableDescription& description, std::span<const double> positions,
                                               std::span<const double> weights) {
  switch (description.law) {
    case SectionLawKind::bouc_wen:
      return std::make_shared<BoucWenCableLaw>(description, positions);
    case SectionLawKind::masing:
      break;
  }
  return std::make_shared<MasingCableLaw>(description, positions, weights);
}

}  // namespace stockbridge::cable
