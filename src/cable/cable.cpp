#include "stockbridge/cable/cable.hpp"

#include <utility>

#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/gauss_legendre.hpp"

namespace stockbridge::cable {

Cable::Cable(CableDescription description) : description_(validated(std::move(description))) {
  const numerics::QuadratureRule rule = numerics::gauss_legendre(description_.sections, 0.0, description_.length);
  positions_ = rule.nodes;
  weights_ = rule.weights;
  const std::size_t n = positions_.size();
  const std::size_t m = description_.jenkin.size();
  ei_.resize(n);
  jenkin_.resize(n * m);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = description_.profile_position(positions_[i]);
    ei_[i] = description_.ei.at(s);
    for (std::size_t j = 0; j < m; ++j) {
      jenkin_[i * m + j] = {description_.jenkin[j].c.at(s), description_.jenkin[j].h.at(s)};
    }
  }
  for (const JenkinProfile& e : description_.jenkin) k0_.push_back(e.k0);
  slip_compliance_.resize(n);
  stick_compliance_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    double stiffness = ei_[i];
    for (std::size_t j = 0; j < m; ++j) stiffness += jenkin_[i * m + j].c;
    slip_compliance_[i] = 1.0 / ei_[i];
    stick_compliance_[i] = 1.0 / stiffness;
  }
  modified_masing_ = description_.uses_modified_masing();
}

}  // namespace stockbridge::cable
