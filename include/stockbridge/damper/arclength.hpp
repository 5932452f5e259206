#pragma once
// Pseudo-arclength continuation of a harmonic-balance branch in (q, W) at constant
// velocity amplitude: where natural continuation in frequency fails because the
// response curve turns (a fold), the branch is followed by its arclength with the
// exact bordered Jacobian [J, dR/dW; t^T], and every crossing of the target
// frequency is polished there (several crossings: several steady states).

#include <vector>

#include "stockbridge/damper/harmonic_balance.hpp"

namespace stockbridge::damper {

/// Where the branch is known: a converged solution and the solver's memory of it.
struct BranchPoint {
  Eigen::VectorXd unknowns;      ///< q, the Fourier coefficients
  double frequency_hz = 0.0;
  HarmonicBalanceMemory memory;  ///< its periodic cable state (the branch's memory goes on from it)
};

struct BranchCrossings {
  /// The solutions at every crossing of the target frequency, in the order met
  /// along the branch: one on a single-valued branch, several where it folds back
  /// over the target; empty if the branch could not be followed there.
  std::vector<ArmSolution> solutions;
  HarmonicBalanceMemory memory;  ///< the solver's memory at the last of them
};

/// Follows the branch through `from` at velocity amplitude `velocity` (m/s) until
/// the frequency has passed `target_hz` for good, in at most `max_steps` steps.
BranchCrossings continue_along_branch(const HarmonicBalance& model, double velocity, const BranchPoint& from,
                                      double target_hz, HarmonicBalanceWorkspace& workspace, int max_steps = 60);

}  // namespace stockbridge::damper
