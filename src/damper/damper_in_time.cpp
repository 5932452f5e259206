#include "stockbridge/damper/damper_in_time.hpp"

#include <utility>

#include <fmt/format.h>

#include "arm_newmark.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::damper {

DamperInTime::DamperInTime(const Damper& damper, double dt, const TimeDomainOptions& options)
    : dt_(dt),
      max_newton_(options.max_newton),
      newton_tolerance_(options.newton_tolerance),
      clamp_mass_(damper.clamp_mass()) {
  require_positive("dt", dt, "s");
  require_in_range("max_newton", options.max_newton, 1, 10000);
  require_positive("newton_tolerance", options.newton_tolerance, "");
  within_field("cantilever", [&] { options.cantilever.validate(); });
  for (const std::size_t k : damper.distinct()) {
    const Arm& arm = damper.arms()[k];
    int count = 0;
    for (const std::size_t r : damper.representative()) count += r == k ? 1 : 0;
    arms_.push_back({arm.mass_matrix(), arm.load_vector(), arm.cable().length(), count,
                     cable::Cantilever(arm.cable(), options.cantilever), {}, {}, {}, {}, damper.arm_label(k)});
  }
}

ClampResponse DamperInTime::start(double clamp_acceleration) {
  for (ArmState& arm : arms_) {
    arm.cantilever.reset();
    arm.u.setZero();
    arm.v.setZero();
    arm.a = arm.mass.inverse() * (arm.load * clamp_acceleration);  // f(0) = 0
    arm.trial_a = arm.a;
  }
  time_ = 0.0;
  force_ = trial_force_ = -clamp_mass_ * clamp_acceleration;
  return {force_, -clamp_mass_};
}

ClampResponse DamperInTime::trial(double clamp_acceleration) {
  const double q = 0.25 * dt_ * dt_;
  ClampResponse response{-clamp_mass_ * clamp_acceleration, -clamp_mass_};
  for (ArmState& arm : arms_) {
    const Eigen::Vector2d base = arm.u + dt_ * arm.v + q * arm.a;
    const Eigen::Vector2d p = arm.load * clamp_acceleration;
    const detail::ArmStepOutcome outcome = detail::solve_arm_step({arm.mass, arm.length, q, max_newton_, newton_tolerance_},
                                                                  arm.cantilever, base, p, arm.trial_a);
    if (outcome.termination != Termination::converged) {
      const std::string where = fmt::format("the damper's {} in the time step to t = {:.9g} s, clamp acceleration {:.6g} m/s^2",
                                            arm.label, time_ + dt_, clamp_acceleration);
      if (outcome.termination == Termination::inner_failure) {
        throw NumericalError(fmt::format("cable state determination of {}: {}", where, brief_report(outcome.cable_failure)));
      }
      throw NumericalError(fmt::format("{}: {} after {} Newton iterations (residual {:.3g} relative to the largest term)",
                                       where, termination_name(outcome.termination), outcome.iterations, outcome.residual));
    }
    const cable::CableState& state = arm.cantilever.trial();
    const Eigen::Matrix2d stiffness = state.tip_stiffness(arm.length);
    const Eigen::Vector2d du = q * (arm.mass + q * stiffness).inverse() * arm.load;  // d u / d x_c''
    response.force_n += arm.count * state.tip_force;
    response.force_per_acceleration_kg += arm.count * stiffness.row(0).dot(du);
  }
  trial_force_ = response.force_n;
  return response;
}

void DamperInTime::commit() {
  const double q = 0.25 * dt_ * dt_;
  for (ArmState& arm : arms_) {
    arm.cantilever.commit();
    const Eigen::Vector2d base = arm.u + dt_ * arm.v + q * arm.a;
    arm.v += 0.5 * dt_ * (arm.a + arm.trial_a);
    arm.u = base + q * arm.trial_a;
    arm.a = arm.trial_a;
  }
  force_ = trial_force_;
  time_ += dt_;
}

double DamperInTime::dissipated() const {
  double sum = 0.0;
  for (const ArmState& arm : arms_) sum += arm.count * arm.cantilever.committed().dissipated;
  return sum;
}

}  // namespace stockbridge::damper
