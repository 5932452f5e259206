#pragma once
// Segalman's four-parameter Iwan model (MODEL.md section 17): a continuous
// distribution of Jenkin elements, slip strengths phi with density
//     rho(phi) = R phi^chi (H(phi) - H(phi - phi_max)) + S delta(phi - phi_max),
// in parallel with the elastic EI: M = EI kappa + M_iwan. Its parameters are the
// slip moment M_S, the tangent stiffness at zero K_T, the exponent chi (-1 < chi <= 0)
// and beta (the weight of the final delta); with c = beta + (chi + 1)/(chi + 2):
//     phi_max = M_S (1 + beta) / (K_T c),  R = M_S (chi + 1) / (phi_max^(chi+2) c),
//     S = M_S beta / (phi_max c).
// Backbone (0 <= u < phi_max; M_S beyond):
//     B(u) = R u^(chi+2)/(chi+2) + R u (phi_max^(chi+1) - u^(chi+1))/(chi+1) + S u,
//     B'(u) = R (phi_max^(chi+1) - u^(chi+1))/(chi+1) + S.
// A Masing law, exact: the virgin curve M_iwan = sign(kappa) B(|kappa|), each branch
// from a reversal (kappa_r, M_r) M_iwan = M_r + d 2 B(|kappa - kappa_r| / 2), and the
// reversal memory of Masing's extended rules: a branch that passes an earlier reversal
// joins the branch before it (the first reversal's branch joins the virgin curve at
// -kappa_1). Energy: the elements that slip on a branch at distance D from its
// reversal are those with 2 phi < D, dissipating G(D/2) = B - u B' per unit of
// curvature, in closed form H(v) = R v^(chi+3)/((chi+2)(chi+3)) (M_S beyond phi_max):
// a steady cycle of amplitude a < phi_max dissipates 4 R a^(chi+3)/((chi+2)(chi+3)).
//
// The memory lives in a span of doubles, [kappa_1, M_1, ..., kappa_K, M_K], the
// reversals held those before the first kappa of 0 (a reversal at exactly 0 is kept
// at 1e-300), so that the mirror, which negates every entry, and the mean of two
// equal memories keep it: the cable keeps it in CableState::hysteretic
// (iwan_cable_law.hpp). A memory that is full forgets its oldest two reversals (the
// outermost loop).

#include <cstddef>
#include <span>
#include <vector>

#include "stockbridge/section/committable.hpp"
#include "stockbridge/section/section_law.hpp"

namespace stockbridge::section {

struct IwanParameters {
  double ei = 0.0;                 ///< the elastic part EI, N m^2, > 0
  double slip_moment = 0.0;        ///< M_S, N m, > 0
  double tangent_stiffness = 0.0;  ///< K_T, the Iwan part's stiffness at zero, N m^2, > 0
  double exponent = 0.0;           ///< chi, -1 < chi <= 0
  double beta = 0.0;               ///< >= 0
};

/// Throws InvalidParameter naming "ei", "slip_moment", "tangent_stiffness", "exponent" or "beta".
void validate(const IwanParameters& parameters);

/// The Iwan part's backbone and energy (MODEL.md 17) from the parameters.
struct IwanBackbone {
  double phi_max = 0.0, r = 0.0, s = 0.0, chi = 0.0, slip_moment = 0.0;
  double phi_power = 0.0;  ///< phi_max^(chi+1)

  IwanBackbone() = default;
  explicit IwanBackbone(const IwanParameters& p);
  double moment(double u) const;      ///< B(u), u >= 0
  double tangent(double u) const;     ///< B'(u), u >= 0
  double dissipation(double v) const; ///< H(v) = int_0^v (B - u B') du, v >= 0
};

/// Reversal points a memory keeps: a memory is 2 kIwanMemory doubles.
inline constexpr std::size_t kIwanMemory = 24;
inline constexpr std::size_t kIwanMemorySize = 2 * kIwanMemory;

/// The reversals a memory holds.
std::size_t iwan_reversals(std::span<const double> memory);

/// Where a step ended: the curvature, the Iwan part's moment and tangent (one-sided,
/// the way it moved), the energy the step dissipated.
struct IwanStep {
  double curvature = 0.0;
  double moment = 0.0;  ///< M_iwan
  double tangent = 0.0; ///< dM_iwan / dkappa
  double dissipated = 0.0;
};

/// The Iwan part's moment at `curvature` on the memory's current branch.
double iwan_moment(const IwanBackbone& backbone, std::span<const double> memory, double curvature);

/// Moves the memory monotonically from `from` to the curvature (`by_moment` false) or
/// to where EI kappa + M_iwan = `target` (`by_moment` true), through reversals and the
/// branches it joins.
IwanStep iwan_step(const IwanBackbone& backbone, double ei, std::span<double> memory, double from, double target,
                   bool by_moment);

/// The section's state: curvature, moment, tangent, dissipated energy and its memory.
struct IwanState {
  double curvature = 0.0;
  double moment = 0.0;
  double tangent = 0.0;
  double dissipated = 0.0;
  std::vector<double> memory = std::vector<double>(kIwanMemorySize, 0.0);
};

class IwanSection final : public CommittedSectionLaw<IwanState> {
 public:
  /// Validates the parameters (InvalidParameter) and starts from the virgin state.
  explicit IwanSection(IwanParameters parameters);

  void set_trial_curvature(double curvature) override;
  const IwanParameters& parameters() const { return parameters_; }
  const IwanBackbone& backbone() const { return backbone_; }

 private:
  IwanParameters parameters_;
  IwanBackbone backbone_;
};

}  // namespace stockbridge::section
