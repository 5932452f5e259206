#include "stockbridge/damper/tracker.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stockbridge::damper {

namespace {

double held_value(const Excitation& e, HeldAmplitude held) {
  return held == HeldAmplitude::velocity ? e.velocity_amplitude() : e.displacement_amplitude;
}

}  // namespace

ArmTracker::ArmTracker(const Arm& arm, const SolverOptions& options, HeldAmplitude held)
    : solver_(make_arm_solver(arm, options)),
      continues_(options.method == Method::harmonic_balance || options.method == Method::collocation),
      held_(held) {}

Excitation ArmTracker::between(const Excitation& from, const Excitation& to, double t) const {
  const double f = from.frequency_hz * std::pow(to.frequency_hz / from.frequency_hz, t);
  const double a0 = held_value(from, held_), a1 = held_value(to, held_);
  const double a = same_amplitude(a0, a1) ? a1 : a0 * std::pow(a1 / a0, t);
  return held_ == HeldAmplitude::velocity ? Excitation::from_velocity(f, a) : Excitation{f, a};
}

ArmSolution ArmTracker::solve(const Excitation& target) {
  ArmSolution solution = advance_to(target);
  if (!solution.summary.converged() && path_.empty() && continues_) {
    ArmSolution led = lead_in(target);
    if (led.summary.converged()) solution = std::move(led);
  }
  return solution;
}

/// From the path; a step that fails is taken again from the last converged
/// excitation in smaller steps, then (constant velocity) by arclength continuation.
ArmSolution ArmTracker::advance_to(const Excitation& target) {
  ArmSolution solution = solver_->solve(target, path_);
  if (!solution.summary.converged() && !path_.empty()) {
    constexpr int kSubsteps = 8;
    const Excitation from = path_.excitation;
    bool reached = true;
    for (int k = 1; k < kSubsteps && reached; ++k) {
      reached = solver_->solve(between(from, target, static_cast<double>(k) / kSubsteps), path_).summary.converged();
    }
    if (reached) {
      ArmSolution retry = solver_->solve(target, path_);
      if (retry.summary.converged()) solution = std::move(retry);
    }
  }
  if (!solution.summary.converged() && !path_.empty() && held_ == HeldAmplitude::velocity &&
      same_amplitude(path_.excitation.velocity_amplitude(), target.velocity_amplitude())) {
    // Natural continuation fails where the branch turns: follow it by arclength.
    std::vector<ArmSolution> crossings = solver_->continue_to(target, path_);
    if (!crossings.empty()) solution = std::move(crossings.back());
  }
  return solution;
}

/// A first point that fails from a cold start (near a resonance, where the linear
/// guess lies far from the slipping solution) is approached as a sweep would reach
/// it: from a decade below in frequency, where the cable slips all along (constant
/// velocity) or moves quasi-statically (constant displacement) and a cold start
/// converges, up in log steps along the branch.
ArmSolution ArmTracker::lead_in(const Excitation& target) {
  constexpr int kLeadInSteps = 20;
  constexpr double kLeadInDecades = 1.0;
  Excitation start = target;
  start.frequency_hz = target.frequency_hz * std::pow(10.0, -kLeadInDecades);
  if (held_ == HeldAmplitude::velocity) start = Excitation::from_velocity(start.frequency_hz, target.velocity_amplitude());
  for (int k = 0; k < kLeadInSteps; ++k) advance_to(between(start, target, static_cast<double>(k) / kLeadInSteps));
  return advance_to(target);
}

DamperTracker::DamperTracker(Damper damper, const SolverOptions& options, HeldAmplitude held)
    : damper_(std::move(damper)), energy_tolerance_(options.energy_tolerance) {
  options.validate();
  for (const std::size_t k : damper_.distinct()) arms_.emplace_back(damper_.arms()[k], options, held);
}

DamperTracker::Checkpoint DamperTracker::checkpoint() const {
  Checkpoint c;
  for (const ArmTracker& arm : arms_) c.push_back(arm.path());
  return c;
}

void DamperTracker::restore(const Checkpoint& checkpoint) {
  if (checkpoint.size() != arms_.size()) throw std::invalid_argument("DamperTracker::restore: a checkpoint of another damper");
  for (std::size_t k = 0; k < arms_.size(); ++k) arms_[k].set_path(checkpoint[k]);
}

void DamperTracker::forget() {
  for (ArmTracker& arm : arms_) arm.set_path(Continuation{});
}

ImpedancePoint DamperTracker::solve(const Excitation& excitation) {
  excitation.validate();
  ++solves_;
  const std::vector<std::size_t>& distinct = damper_.distinct();
  std::vector<ArmSolution> solved;
  solved.reserve(arms_.size());
  for (ArmTracker& arm : arms_) solved.push_back(arm.solve(excitation));
  std::vector<const ArmSolution*> per_arm(damper_.arms().size());
  for (std::size_t k = 0; k < per_arm.size(); ++k) {
    const auto d = std::find(distinct.begin(), distinct.end(), damper_.representative()[k]) - distinct.begin();
    per_arm[k] = &solved[static_cast<std::size_t>(d)];
  }
  return combine(damper_, excitation, per_arm, energy_tolerance_);
}

}  // namespace stockbridge::damper
