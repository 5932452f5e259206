#include "stockbridge/cable/cable.hpp"

#include <utility>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/gauss_legendre.hpp"

namespace stockbridge::cable {

Cable::Cable(CableDescription description) : description_(validated(std::move(description))) {
  const numerics::QuadratureRule rule = numerics::gauss_legendre(description_.sections, 0.0, description_.length);
  positions_ = rule.nodes;
  weights_ = rule.weights;
  law_ = make_cable_law(description_, positions_, weights_);
}

}  // namespace stockbridge::cable
