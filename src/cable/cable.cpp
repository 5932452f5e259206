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
  modified_masing_ = description_.uses_modified_masing();
  if (m == 1 && !modified_masing_) fill_one_element_columns();
}

void Cable::fill_one_element_columns() {
  OneElementColumns& columns = one_element_columns_;
  const double l = length();
  for (std::size_t i = 0; i < sections(); ++i) {
    const section::Jenkin& e = jenkin_[i];
    const double s = positions_[i];
    const double w = weights_[i];
    columns.c.push_back(e.c);
    columns.h.push_back(e.h);
    columns.ei.push_back(ei_[i]);
    columns.stick_stiffness.push_back(ei_[i] + e.c);
    columns.slip_compliance.push_back(1.0 / ei_[i]);
    columns.stick_compliance.push_back(1.0 / (ei_[i] + e.c));
    columns.position.push_back(s);
    columns.weight.push_back(w);
    columns.weight_position.push_back(w * s);
    columns.weight_arm.push_back(w * (l - s));
    columns.weight_arm_position.push_back(w * (l - s) * s);
  }
}

}  // namespace stockbridge::cable
