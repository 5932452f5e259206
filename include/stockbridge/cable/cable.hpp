#pragma once
// The discretised cable: Gauss-Legendre points s_i with weights w_i along
// [0, l], and the Masing parameters at each point in flat arrays (the model,
// constant; its state lives in CableState).

#include <span>
#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/section/jenkin.hpp"

namespace stockbridge::cable {

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
  /// 1 / ei and 1 / (ei + sum c) at section i: the slipping and sticking compliances
  /// of a one-element section (the fast path of the cable evaluation).
  double slip_compliance(std::size_t i) const { return slip_compliance_[i]; }
  double stick_compliance(std::size_t i) const { return stick_compliance_[i]; }
  /// k0 of each element (all zero unless the modified Masing model is used).
  std::span<const double> k0() const { return k0_; }
  bool modified_masing() const { return modified_masing_; }

 private:
  CableDescription description_;
  std::vector<double> positions_;
  std::vector<double> weights_;
  std::vector<double> ei_;
  std::vector<section::Jenkin> jenkin_;  // sections x elements, row-major
  std::vector<double> k0_;
  std::vector<double> slip_compliance_;
  std::vector<double> stick_compliance_;
  bool modified_masing_ = false;
};

}  // namespace stockbridge::cable
