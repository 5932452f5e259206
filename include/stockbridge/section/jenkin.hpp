#pragma once
// Jenkin elements: a linear spring c in series with a Coulomb slider of strength h
// (MODEL.md section 1, dissertation 3.4). For a cable cross-section the
// "displacement" is the curvature kappa (1/m) and the force is a moment (N m):
// c is a bending stiffness (N m^2), h a slip moment (N m), H the element's moment.
//
// The exact law is piecewise linear: for a monotone curvature increment dk,
//     H_new = clamp(H + c dk, -h, h)
// These kernels work on spans so that one section (MasingSection) and the many
// sections of a cable (flat arrays) share the same code.

#include <algorithm>
#include <cstddef>
#include <span>
#include <string_view>

namespace stockbridge::section {

/// Parameters of one Jenkin element.
struct Jenkin {
  double c = 0.0;  ///< spring stiffness, N m^2, > 0
  double h = 0.0;  ///< slip moment, N m, > 0
};

/// Throws InvalidParameter naming `name` (e.g. "jenkin[0]") unless c > 0 and h > 0, finite.
void validate(const Jenkin& element, std::string_view name);

/// Outcome of one exact monotone step of a set of parallel Jenkin elements.
struct JenkinStep {
  double moment = 0.0;           ///< sum of the elements' moments H after the step, N m
  double stick_stiffness = 0.0;  ///< sum of c over the elements that stick after the step, N m^2
  double dissipated = 0.0;       ///< energy the sliders dissipate in the step, J/m (per unit length)
};

/// Whether an element slips in the monotone step dkappa from the moment h_from (the
/// classification jenkin_step uses; exposed for derivative propagation).
inline bool jenkin_slips(const Jenkin& element, double h_from, double dkappa) {
  const double elastic = h_from + element.c * dkappa;
  return (dkappa > 0.0 && elastic >= element.h) || (dkappa < 0.0 && elastic <= -element.h);
}

/// Exact return mapping for the monotone curvature increment `dkappa`:
/// h_to[j] = clamp(h_from[j] + c_j dkappa, -h_j, h_j).
///
/// An element that reaches its slip moment while loading counts as slipping (its
/// tangent for continued loading is 0); with dkappa == 0 every element counts as
/// sticking (the unloading tangent). Each slider dissipates h * |slip|.
/// Preconditions: |h_from[j]| <= h_j; the spans have equal sizes; h_to may alias h_from.
inline JenkinStep jenkin_step(std::span<const Jenkin> jenkin, std::span<const double> h_from,
                              double dkappa, std::span<double> h_to) {
  JenkinStep step;
  for (std::size_t j = 0; j < jenkin.size(); ++j) {
    const double c = jenkin[j].c;
    const double h = jenkin[j].h;
    const double elastic = h_from[j] + c * dkappa;
    double value = elastic;
    if (dkappa > 0.0 && elastic >= h) {
      value = h;
      step.dissipated += h * (elastic - h) / c;
    } else if (dkappa < 0.0 && elastic <= -h) {
      value = -h;
      step.dissipated += h * (-h - elastic) / c;
    } else {
      step.stick_stiffness += c;
    }
    h_to[j] = value;
    step.moment += value;
  }
  return step;
}

/// Moment-driven use: the curvature increment dk at which the section's moment
/// grows by `excess`:
///     ei * dk + sum_j [clamp(h_from[j] + c_j dk, -h_j, h_j) - h_from[j]] = excess.
/// The left side is monotone and piecewise linear in dk, so the solution is exact:
/// an active-set pass that only ever removes elements from the sticking set, at most
/// m + 1 passes of O(m) each, no sorting, no allocation.
/// Returns false (and leaves dk unset) only when no solution exists, which requires
/// ei == 0 and |excess| beyond what the elements can still take.
inline bool solve_curvature_increment(double ei, std::span<const Jenkin> jenkin,
                                      std::span<const double> h_from, double excess, double& dk) {
  if (excess == 0.0) {
    dk = 0.0;
    return true;
  }
  // Work in the loading direction, s = sign * dk >= 0. Element j saturates at its
  // breakpoint b_j = (h_j - sign H_j) / c_j. With the sticking set S = {j : b_j > s}
  // the equation reads (ei + sum_S c_j) s + sum_{not S} c_j b_j = sign * excess.
  // Each pass solves it for the current S; the estimate never overshoots the root
  // and only grows, so S only shrinks: at most m + 1 passes, exact on exit.
  const double sign = excess > 0.0 ? 1.0 : -1.0;
  const double target = sign * excess;
  double step = 0.0;
  std::size_t stuck_before = jenkin.size() + 1;
  for (;;) {
    double stiffness = ei;
    double capped = 0.0;
    std::size_t stuck = 0;
    for (std::size_t j = 0; j < jenkin.size(); ++j) {
      const double reserve = jenkin[j].h - sign * h_from[j];  // c_j b_j
      if (reserve > step * jenkin[j].c) {
        stiffness += jenkin[j].c;
        ++stuck;
      } else {
        capped += reserve;
      }
    }
    if (stuck == stuck_before) break;
    if (stiffness <= 0.0) return false;
    step = std::max(step, (target - capped) / stiffness);
    stuck_before = stuck;
  }
  dk = sign * step;
  return true;
}

}  // namespace stockbridge::section
