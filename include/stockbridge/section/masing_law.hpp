#pragma once
// The Masing model of one cable cross-section (MODEL.md section 1, dissertation
// (3.11)): an elastic bending stiffness `ei` in parallel with any number of Jenkin
// elements,
//     M = ei * kappa + sum_j H_j.
// Parameters (MasingParameters) are kept apart from state (SectionState); the
// updates are pure functions from a committed state to a trial state.

#include <vector>

#include "stockbridge/section/jenkin.hpp"

namespace stockbridge::section {

/// Constant description of a section.
struct MasingParameters {
  double ei = 0.0;             ///< elastic (minimum) bending stiffness, N m^2, >= 0
  std::vector<Jenkin> jenkin;  ///< any number of Jenkin elements, possibly none

  /// ei + sum c_j: the stiffness while every element sticks, N m^2.
  double max_stiffness() const;
  /// sum h_j: the moment the elements carry while all of them slip, N m.
  double total_slip_moment() const;
};

/// Throws InvalidParameter naming the bad quantity ("ei", "jenkin[1].h", ...).
void validate(const MasingParameters& parameters);

/// Everything that changes as a section is loaded. Starts virgin (all zero).
struct SectionState {
  double curvature = 0.0;           ///< kappa, 1/m
  double moment = 0.0;              ///< M, N m
  double tangent = 0.0;             ///< dM/dkappa for continued loading, N m^2
  double dissipated = 0.0;          ///< energy dissipated by the sliders since virgin, J/m
  std::vector<double> hysteretic;   ///< H_j, N m, one per Jenkin element

  /// The virgin state of a section with these parameters.
  static SectionState virgin(const MasingParameters& parameters);
};

/// Curvature-driven exact update: the state reached from `from` by a monotone
/// curvature change to `curvature`. Writes `to` (which must be sized like `from`).
void curvature_update(const MasingParameters& parameters, const SectionState& from,
                      double curvature, SectionState& to);

/// Moment-driven exact update: the state on the monotone path from `from` whose
/// moment equals `moment`. Throws NumericalError if no curvature reaches it
/// (only possible with ei == 0).
void moment_update(const MasingParameters& parameters, const SectionState& from, double moment,
                   SectionState& to);

}  // namespace stockbridge::section
