#pragma once
// The Bouc-Wen section law of RTE's slenderpy (MODEL.md section 13): a smooth
// hysteretic moment instead of Jenkin elements,
//     M = EI_min chi + (EI_max - EI_min) chi0 eta,   chi0 d eta = d chi - |d chi| eta,
// eta in [-1, 1]. Along a monotone stretch of curvature from (chi_s, eta_s) it is
// exact in closed form (increasing: 1 - eta = (1 - eta_s) exp(-(chi - chi_s) / chi0);
// decreasing: 1 + eta = (1 + eta_s) exp(-(chi_s - chi) / chi0)), so a trial is exact
// through its turning points, as the Masing law's is. The dissipated energy splits
// the hysteretic curvature into a recoverable part chi0 eta (the stiffness EI_max -
// EI_min) and the rest: dD = (EI_max - EI_min) chi0 eta^2 |d chi| >= 0, integrated in
// closed form too. Over a steady cycle of amplitude chi_a it is the loop's area,
// 4 (EI_max - EI_min) chi0 (chi_a - chi0 tanh(chi_a / chi0)).

#include "stockbridge/section/committable.hpp"
#include "stockbridge/section/section_law.hpp"

namespace stockbridge::section {

struct BoucWenParameters {
  double ei_min = 0.0;  ///< EI_min, the free wires' (asymptotic) stiffness, N m^2, > 0
  double ei_max = 0.0;  ///< EI_max, the no-slip (initial) stiffness, N m^2, >= ei_min
  double chi0 = 0.0;    ///< the curvature scale of the transition, 1/m, > 0
};

/// Throws InvalidParameter naming "ei_min", "ei_max" or "chi0".
void validate(const BoucWenParameters& parameters);

/// A state of the section: the curvature, eta, the moment, the tangent, the energy
/// dissipated since the virgin state, and which way the curvature last moved (the
/// tangent at a turning point is the one of the way it moved).
struct BoucWenState {
  double curvature = 0.0;
  double eta = 0.0;
  double moment = 0.0;
  double tangent = 0.0;
  double dissipated = 0.0;
  int direction = 1;  ///< +1 increasing, -1 decreasing

  static BoucWenState virgin(const BoucWenParameters& parameters);
};

/// The exact state at `curvature` reached monotonically from `from`.
BoucWenState bouc_wen_update(const BoucWenParameters& parameters, const BoucWenState& from, double curvature);

class BoucWenSection final : public CommittedSectionLaw<BoucWenState> {
 public:
  /// Validates the parameters (InvalidParameter) and starts from the virgin state.
  explicit BoucWenSection(BoucWenParameters parameters);

  void set_trial_curvature(double curvature) override;
  const BoucWenParameters& parameters() const { return parameters_; }
  double eta() const { return state_.trial().eta; }

 private:
  BoucWenParameters parameters_;
};

}  // namespace stockbridge::section
