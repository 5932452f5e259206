#pragma once
// A cable parameter along the arc length s (MODEL.md section 2): constant, or
// tabulated and piecewise linear in s, held constant beyond the table's ends.

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stockbridge::cable {

class Profile {
 public:
  /// The same value everywhere (the default profile is 0).
  static Profile constant(double value);
  /// Values at positions s (m from the clamp), strictly increasing, s[0] >= 0.
  /// Throws InvalidParameter naming `name` for a malformed table.
  static Profile table(std::vector<double> positions, std::vector<double> values, std::string_view name);

  /// The value at s, linear between table points.
  double at(double s) const;
  bool is_constant() const { return positions_.size() == 1; }
  std::span<const double> positions() const { return positions_; }
  std::span<const double> values() const { return values_; }
  /// The smallest value (at a table point, the profile being piecewise linear).
  double min_value() const;

  /// Checks every value with `check(name, value)`, naming "name" or "name.value[i]".
  template <class Check>
  void check_values(std::string_view name, Check check) const;

  bool operator==(const Profile&) const = default;

 private:
  Profile(std::vector<double> positions, std::vector<double> values)
      : positions_(std::move(positions)), values_(std::move(values)) {}
  std::vector<double> positions_;  // one entry 0.0 for a constant
  std::vector<double> values_;
};

template <class Check>
void Profile::check_values(std::string_view name, Check check) const {
  if (is_constant()) {
    check(name, values_[0]);
    return;
  }
  for (std::size_t i = 0; i < values_.size(); ++i) {
    check(std::string(name) + ".value[" + std::to_string(i) + "]", values_[i]);
  }
}
}  // namespace stockbridge::cable
