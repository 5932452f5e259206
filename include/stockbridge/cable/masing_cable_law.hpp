#pragma once
// The Masing law of the cable (MODEL.md sections 1-3): at each section an elastic
// beam ei in parallel with Jenkin elements (c, h), optionally with the modified
// model's load-dependent slip moments h0 + k0 min(|M| / |F|, cap). Its internal
// variables are the elements' moments H (sections x elements, row-major).

#include <span>
#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/cable/cable_law.hpp"
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

class MasingCableLaw final : public CableLaw {
 public:
  MasingCableLaw(const CableDescription& description, std::span<const double> positions,
                 std::span<const double> weights);

  std::size_t elements() const { return k0_.size(); }
  double ei(std::size_t i) const { return ei_[i]; }
  /// The Jenkin elements of section i (h is h0 for the modified model).
  std::span<const section::Jenkin> jenkin(std::size_t i) const {
    return std::span<const section::Jenkin>(jenkin_).subspan(i * elements(), elements());
  }
  /// k0 of each element (all zero unless the modified Masing model is used).
  std::span<const double> k0() const { return k0_; }
  bool modified_masing() const { return modified_masing_; }
  /// The sections' numbers as columns, for a cable of one element and constant slip
  /// moments (empty otherwise).
  const OneElementColumns& one_element_columns() const { return one_element_columns_; }

  std::size_t internal_variables() const override { return elements(); }
  double stick_stiffness(std::size_t section) const override;
  double slip_stiffness(std::size_t section) const override { return ei_[section]; }
  void apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force, CableState& to,
                   CableWorkspace& workspace) const override;
  double internal_change(const CableState& start, const CableState& end) const override;
  std::unique_ptr<LoadSensitivity> load_sensitivity(const Cable& cable) const override;

 private:
  void fill_one_element_columns(double length, std::span<const double> positions, std::span<const double> weights);

  std::vector<double> ei_;
  std::vector<section::Jenkin> jenkin_;  // sections x elements, row-major
  std::vector<double> k0_;
  double lever_arm_limit_ = 0.0;
  bool modified_masing_ = false;
  OneElementColumns one_element_columns_;
};

}  // namespace stockbridge::cable
