#pragma once
// Solving a damper along a path of excitations chosen as one goes: each solve
// starts from the last converged one, as a sweep continues along its frequencies,
// with the sweep's fallbacks where a step fails: smaller steps from the last
// converged excitation, arclength continuation along the branch (constant
// velocity), and for a first point that fails from a cold start, a lead-in from a
// decade below. The sweep is built on it; the span balance follows each damper's
// clamp velocity with it. A tracker owns its solvers' scratch space: one serves
// one thread.

#include <memory>
#include <vector>

#include "stockbridge/damper/impedance.hpp"

namespace stockbridge::damper {

/// The amplitude a path holds, or moves along geometrically with the frequency.
enum class HeldAmplitude { velocity, displacement };

/// One arm along a path of excitations.
class ArmTracker {
 public:
  ArmTracker(const Arm& arm, const SolverOptions& options, HeldAmplitude held);

  /// The arm at `target`, from the last converged solution (cold the first time).
  /// Never throws for non-convergence: the solution's summary says so.
  ArmSolution solve(const Excitation& target);
  /// Where the next solve starts from (the last converged solution).
  const Continuation& path() const { return path_; }
  void set_path(Continuation path) { path_ = std::move(path); }

 private:
  ArmSolution advance_to(const Excitation& target);
  ArmSolution lead_in(const Excitation& target);
  /// The excitation a fraction t of the way from `from` to `to`, geometric in the
  /// frequency and the held amplitude.
  Excitation between(const Excitation& from, const Excitation& to, double t) const;

  std::unique_ptr<ArmSolver> solver_;
  bool continues_;  ///< the method starts from the path (harmonic balance, collocation)
  HeldAmplitude held_;
  Continuation path_;
};

/// A whole damper along a path of excitations: its distinct arms each tracked,
/// combined into the clamp's impedance as a sweep's point.
class DamperTracker {
 public:
  /// The tracker keeps its own copy of the damper.
  DamperTracker(Damper damper, const SolverOptions& options, HeldAmplitude held = HeldAmplitude::velocity);

  /// The damper at `excitation`; converged() false (with the failure) where an arm did not converge.
  ImpedancePoint solve(const Excitation& excitation);
  /// Solves made so far (one per call).
  int solves() const { return solves_; }

  /// Where the next solve starts from: take one and go back to it to solve several
  /// excitations from one start (near a fold, where two steady states coexist, the
  /// state reached depends on the path: from one start it is a function of the
  /// excitation).
  using Checkpoint = std::vector<Continuation>;
  Checkpoint checkpoint() const;
  void restore(const Checkpoint& checkpoint);
  /// The next solve starts cold (with the lead-in where a cold start fails).
  void forget();

 private:
  Damper damper_;
  double energy_tolerance_;
  std::vector<ArmTracker> arms_;  ///< one per distinct arm
  int solves_ = 0;
};

}  // namespace stockbridge::damper
