#pragma once
// The discretised cable: Gauss-Legendre points s_i with weights w_i along
// [0, l], and the Masing parameters at each point in flat arrays (the model,
// constant; its state lives in CableState).

#include <span>
#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/section/jenkin.hpp"

namespace stockbridge::cable {

/// Per-section columns for the fast path of the cable evaluation (one Jenkin element
/// per section, constant slip moments): each section's numbers side by side, so that
/// the loop over the sections runs on vectors. Arm a_i = l - s_i.
struct OneElementColumns {
  std::vector<double> c, h;                   ///< the element's c (N m^2) and h (N m)
  std::vector<double> ei, stick_stiffness;    ///< ei and ei + c, N m^2
  std::vector<double> slip_compliance, stick_compliance;  ///< 1 / ei, 1 / (ei + c)
  std::vector<double> position;               ///< s_i, m
  /// The quadrature weights times 1, s, a and a s: the tip kinematics and flexibility
  /// are sums of these times the curvature or the compliance (cantilever.hpp).
  std::vector<double> weight, weight_position, weight_arm, weight_arm_position;
};

class Cable {
 public:
  /// Validates the description (InvalidParameter) and discretises it.
  explicit Cable(CableDescription description);

  const CableDescription& description() const { return description_; }
  double length() const { return description_.length; }
  std::size_t sections() const { return positions_.size(); }
  std::size_t elements() const { return description_.jenkin.size(); }

  std::span<const double> positions() const { return positions_; }  ///< s_i, m
  std::span<const double> weights() const { return weights_; }      ///< w_i, m
  double ei(std::size_t i) const { return ei_[i]; }
  /// The Jenkin elements of section i (h is h0 for the modified model).
  std::span<const section::Jenkin> jenkin(std::size_t i) const {
    return std::span<const section::Jenkin>(jenkin_).subspan(i * elements(), elements());
  }
  /// The sections' numbers as columns, for a cable of one element and constant slip
  /// moments (empty otherwise).
  const OneElementColumns& one_element_columns() const { return one_element_columns_; }
  /// k0 of each element (all zero unless the modified Masing model is used).
  std::span<const double> k0() const { return k0_; }
  bool modified_masing() const { return modified_masing_; }

 private:
  void fill_one_element_columns();

  CableDescription description_;
  std::vector<double> positions_;
  std::vector<double> weights_;
  std::vector<double> ei_;
  std::vector<section::Jenkin> jenkin_;  // sections x elements, row-major
  std::vector<double> k0_;
  OneElementColumns one_element_columns_;
  bool modified_masing_ = false;
};

}  // namespace stockbridge::cable
