#pragma once
// The dissertation's regularised rate law (3.15), kept for comparison with the
// exact law (MODEL.md section 1):
//     dH_j = c_j dkappa [1 - 1/2 (1 + sign(dkappa H_j)) |H_j / h_j|^n],   n > 1.
// It tends to the exact law as n grows. A trial step integrates the law over the
// (monotone) curvature increment with Boost.Odeint's adaptive Dormand-Prince
// stepper, together with the dissipated energy dW = sum_j H_j (dkappa - dH_j / c_j).

#include "stockbridge/section/committable.hpp"
#include "stockbridge/section/masing_law.hpp"
#include "stockbridge/section/section_law.hpp"

namespace stockbridge::section {

struct RegularisedOptions {
  double exponent = 10.0;            ///< n in (3.15), > 1
  double absolute_tolerance = 1e-12;  ///< odeint error control, N m
  double relative_tolerance = 1e-10;

  /// Throws InvalidParameter for an exponent <= 1 or tolerances <= 0.
  void validate() const;
};

class RegularisedSection final : public CommittedSectionLaw<SectionState> {
 public:
  RegularisedSection(MasingParameters parameters, RegularisedOptions options);

  void set_trial_curvature(double curvature) override;
  const MasingParameters& parameters() const { return parameters_; }
  const RegularisedOptions& options() const { return options_; }

 private:
  MasingParameters parameters_;
  RegularisedOptions options_;
};

}  // namespace stockbridge::section
