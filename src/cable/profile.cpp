#include "stockbridge/cable/profile.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

Profile Profile::constant(double value) { return Profile({0.0}, {value}); }

Profile Profile::table(std::vector<double> positions, std::vector<double> values, std::string_view name) {
  if (positions.empty() || positions.size() != values.size()) {
    throw InvalidParameter(std::string(name),
                           fmt::format(": a table needs as many values as positions, at least one ({} positions, {} values)",
                                       positions.size(), values.size()));
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const std::string key = fmt::format("{}.s[{}]", name, i);
    require_non_negative(key, positions[i], "m");
    if (i > 0 && !(positions[i] > positions[i - 1])) {
      throw_invalid(key, positions[i], fmt::format("positions increasing strictly (previous {} m)", positions[i - 1]));
    }
    require_finite(fmt::format("{}.value[{}]", name, i), values[i], "");
  }
  if (positions.size() == 1) positions[0] = 0.0;  // a one-point table is a constant
  return Profile(std::move(positions), std::move(values));
}

double Profile::at(double s) const {
  if (is_constant() || s <= positions_.front()) return values_.front();
  if (s >= positions_.back()) return values_.back();
  const auto upper = std::upper_bound(positions_.begin(), positions_.end(), s);
  const std::size_t i = static_cast<std::size_t>(upper - positions_.begin());
  const double t = (s - positions_[i - 1]) / (positions_[i] - positions_[i - 1]);
  return values_[i - 1] + t * (values_[i] - values_[i - 1]);
}

double Profile::min_value() const { return *std::min_element(values_.begin(), values_.end()); }

}  // namespace stockbridge::cable
