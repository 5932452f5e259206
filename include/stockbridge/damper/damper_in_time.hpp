#pragma once
// The damper on a moving support, one time step at a time (MODEL.md section 16,
// docs/time-domain.md): its clamp moves as the conductor under it does, so the
// clamp's acceleration is not known in advance but found with the conductor's at
// each step. Each arm is stepped by Newmark's average acceleration rule with the
// exact cable law, as NewmarkStepper does under a harmonic clamp; for a trial clamp
// acceleration x_c'' at the end of the step the damper answers with the force it
// puts on its support,
//
//     F = -m_c x_c'' + sum_k F_k,
//
// (F_k the arm's cable's tip force: the shaker force of section 4, negated) and its
// exact derivative with respect to x_c'': with K_t the arm's tip stiffness and
// q = dt^2 / 4, du_k / dx_c'' = q (M_k + q K_t)^-1 L_k, so that the coupled step's
// Newton iteration has the damper's own tangent. Arms of the same mechanics move
// alike from rest and are stepped once.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/damper/damper.hpp"
#include "stockbridge/damper/time_integration.hpp"

namespace stockbridge::damper {

/// The damper's answer to a trial clamp acceleration at the end of a step.
struct ClampResponse {
  /// On the support (the conductor), upward positive, N: -m_c x_c'' + sum F_k.
  double force_n = 0.0;
  /// d force_n / d x_c'', kg: minus the mass the support feels in this step (the
  /// clamp's and what of the arms' the cables carry).
  double force_per_acceleration_kg = 0.0;
};

class DamperInTime {
 public:
  /// The damper at rest, its cables virgin, stepped by `dt` (s). Of `options`, the
  /// Newton iteration's limits and the cantilever's are used (steps_per_period is the
  /// stepper's business). InvalidParameter naming "dt" or the option.
  DamperInTime(const Damper& damper, double dt, const TimeDomainOptions& options);

  /// Starts the arms at rest, undeflected, with the clamp's acceleration x_c''(0):
  /// the arms' accelerations follow from their equations; the force is -m_c x_c''.
  ClampResponse start(double clamp_acceleration);
  /// The step from t to t + dt with the clamp's acceleration `clamp_acceleration` at
  /// t + dt (the clamp's displacement and velocity follow from Newmark's rule on it).
  /// Nothing is committed. NumericalError naming the arm, the time and by how much
  /// where an arm's iteration fails.
  ClampResponse trial(double clamp_acceleration);
  /// Makes the last trial the state at t + dt.
  void commit();

  double time() const { return time_; }
  double dt() const { return dt_; }
  /// The force on the support at the last commit, N.
  double force() const { return force_; }
  /// The energy the cables' sliders dissipated since the start, J (each arm counted
  /// as often as the damper has it).
  double dissipated() const;

 private:
  struct ArmState {
    Eigen::Matrix2d mass;
    Eigen::Vector2d load;
    double length = 0.0;
    int count = 1;  ///< arms of the damper moving alike
    cable::Cantilever cantilever;
    Eigen::Vector2d u = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero(), a = Eigen::Vector2d::Zero();
    Eigen::Vector2d trial_a = Eigen::Vector2d::Zero();
    std::string label;  ///< how messages name it ("arm long")
  };

  double dt_;
  int max_newton_;
  double newton_tolerance_;
  double clamp_mass_;
  std::vector<ArmState> arms_;
  double time_ = 0.0;
  double force_ = 0.0, trial_force_ = 0.0;
};

}  // namespace stockbridge::damper
