#pragma once
// Segalman's four-parameter Iwan model in the cable (MODEL.md section 17,
// section/iwan_section.hpp): each section an elastic EI in parallel with the Iwan
// part, moved exactly and moment-driven along its branches (Newton on the concave
// branch, from the side that converges monotonically) with the reversal memory of
// Masing's extended rules. Its internal variables are each section's memory,
// [count, kappa_1, M_1, ...] (section::kIwanMemorySize entries): the mirror negates
// them (the count's sign is ignored), the law being odd.
//
// Its LoadSensitivity is exact: on the branch from a reversal (kappa_r, M_r) the
// section carries M = EI kappa + M_r + d 2 B(|kappa - kappa_r| / 2), so
//     (EI + B') d kappa = dM - dM_r + B' d kappa_r,   B' at the end of the step,
// with each reversal's (d kappa_r, dM_r) kept from the step in which it was made
// (the virgin curve: no reversal terms). The tip kinematics close it, as for the
// other laws: d(T, F) = J^-1 (du - sum_i w_i [1; l - s_i] a_i).

#include <span>
#include <vector>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/cable/cable_law.hpp"
#include "stockbridge/section/iwan_section.hpp"

namespace stockbridge::cable {

class IwanCableLaw final : public CableLaw {
 public:
  IwanCableLaw(const CableDescription& description, std::span<const double> positions);

  double ei(std::size_t i) const { return ei_[i]; }
  const section::IwanBackbone& backbone(std::size_t i) const { return backbone_[i]; }

  std::size_t internal_variables() const override { return section::kIwanMemorySize; }
  double stick_stiffness(std::size_t section) const override { return ei_[section] + tangent_stiffness_[section]; }
  double slip_stiffness(std::size_t section) const override { return ei_[section]; }
  void apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force, CableState& to,
                   CableWorkspace& workspace) const override;
  double internal_change(const CableState& start, const CableState& end) const override;
  std::unique_ptr<LoadSensitivity> load_sensitivity(const Cable& cable) const override;

 private:
  std::vector<double> ei_, tangent_stiffness_;
  std::vector<section::IwanBackbone> backbone_;
};

}  // namespace stockbridge::cable
