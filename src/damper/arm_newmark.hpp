#pragma once
// One arm's Newmark step (average acceleration) as both steppers take it: the
// period-at-a-time NewmarkStepper under a harmonic clamp, and DamperInTime under a
// clamp that moves with its support. Internal to the damper layer.

#include <Eigen/Core>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/numerics/solver_summary.hpp"

namespace stockbridge::damper::detail {

/// The arm's Newmark iteration: M a + f(base + q a) = p for a, by Newton on the
/// tangent M + q K_t, started from `a` as passed and left at the answer.
struct ArmStepSystem {
  const Eigen::Matrix2d& mass;  ///< M
  double length;                ///< the cable's, for the moments' scale and the tip's loads
  double q;                     ///< dt^2 / 4: u+ = base + q a+
  int max_newton;
  double tolerance;             ///< on the residual relative to the equation's largest term
};

/// How the iteration ended; on success the cantilever holds the answer's trial
/// state (not committed). On failure it is reverted to its last commit and
/// `cable_failure` is the state determination's summary where that failed.
struct ArmStepOutcome {
  Termination termination = Termination::converged;
  int iterations = 0;
  double residual = 0.0;  ///< relative, on failure
  SolverSummary cable_failure;
};

ArmStepOutcome solve_arm_step(const ArmStepSystem& system, cable::Cantilever& cantilever, const Eigen::Vector2d& base,
                              const Eigen::Vector2d& p, Eigen::Vector2d& a);

}  // namespace stockbridge::damper::detail
