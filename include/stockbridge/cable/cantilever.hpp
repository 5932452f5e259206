#pragma once
// The damper cable as a quasi-static, massless cantilever (MODEL.md section 3):
// clamped at s = 0, loaded at the tip s = l by a force F and a moment Q, so that
//     M(s) = T - F s,  T = Q + F l   (T: moment at the clamp)
//     phi = int_0^l kappa ds,  x = int_0^l (l - s) kappa ds.
// Given loads (T, F) the state follows exactly (moment-driven section updates);
// given tip kinematics it follows from Newton's method on (T, F) with the exact
// flexibility d(phi, x)/d(T, F) and a backtracking line search (with the
// flexibility's change too where the law's tangents vary smoothly: Chebyshev's
// method). This replaces the dissertation's fixed-point iteration (4.45)-(4.49).

#include <span>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/cable/cable.hpp"
#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/section/committable.hpp"
#include "stockbridge/section/jenkin.hpp"

namespace stockbridge::cable {

/// Everything that changes as the cable is loaded. Starts virgin (all zero).
struct CableState {
  double clamp_moment = 0.0;  ///< T, N m
  double tip_force = 0.0;     ///< F, N
  double rotation = 0.0;      ///< phi = w'(l), rad
  double deflection = 0.0;    ///< x = w(l), m
  /// d(phi, x)/d(T, F) for continued loading: [[rad/(N m), rad/N], [m/(N m), m/N]].
  Eigen::Matrix2d flexibility = Eigen::Matrix2d::Zero();
  /// How the flexibility changes with the loads, for a law whose tangents vary
  /// smoothly along a monotone stretch (CableLaw::has_flexibility_change; zero
  /// otherwise): with c_i = d^2 kappa / dM^2 at section i in the direction it last
  /// moved, row 0 holds sum w_i c_i s_i^p and row 1 sum w_i (l - s_i) c_i s_i^p for
  /// p = 0, 1, 2, so that a change (dT, dF) of the loads moves (phi, x) by the
  /// flexibility's term plus half of sum w c (dT - dF s)^2 [1; l - s].
  Eigen::Matrix<double, 2, 3> flexibility_change = Eigen::Matrix<double, 2, 3>::Zero();
  double dissipated = 0.0;            ///< energy dissipated by all sliders since virgin, J
  std::vector<double> curvature;      ///< kappa at each section, 1/m
  std::vector<double> tangent;        ///< section tangent stiffness, N m^2
  /// The law's internal variables (sections x CableLaw::internal_variables()): the
  /// Jenkin elements' moments H (N m) of the Masing law, eta of the Bouc-Wen law.
  std::vector<double> hysteretic;

  static CableState virgin(const Cable& cable);
  /// The state under the opposite loads: the law is odd (a Jenkin element's moment
  /// changes sign with its path, the modified Masing slip moments depend on |M| / |F|,
  /// Bouc-Wen's eta changes sign with its path), so loads, tip kinematics, curvatures
  /// and internal variables change sign, and so does the flexibility's change (each
  /// section's direction turns); tangents, flexibility and the energy dissipated stay.
  void mirror();
  /// Halfway to `other` (a state of the same cable): loads, tip kinematics,
  /// curvatures and internal variables become the means (a state again: every law's
  /// moment is linear in them); tangents, flexibility (and its change) and the
  /// energy dissipated stay this state's.
  void move_halfway_to(const CableState& other);
  /// Q = T - F l, N m.
  double tip_moment(double length) const { return clamp_moment - tip_force * length; }
  /// d(F, Q)/(x, phi): the tip stiffness for the damper, from the flexibility.
  Eigen::Matrix2d tip_stiffness(double length) const;
};

/// Scratch space of apply_loads, sized on first use: the modified Masing model's
/// elements; the Bouc-Wen law's last travels, each section's u and e^-u - 1 (where the
/// next evaluation's solves start).
struct CableWorkspace {
  std::vector<section::Jenkin> jenkin;
  std::vector<double> hysteretic;
  std::vector<double> travel;
};

/// Loads in, state out: every section moves exactly, moment-driven, from `from`
/// to the moment T - F s_i, by the cable's law (CableLaw::apply_loads). Fills every
/// field of `to` (sized like `from`).
///
/// Modified Masing model (3.7): the slip moments are h0 + k0 min(|M|/|F|, cap),
/// the cap standing in for |M|/|F| where F = 0; an element whose stored moment
/// exceeds its new slip moment is set back to it (without dissipation), and the
/// flexibility ignores dh/dM, so Newton converges linearly rather than finitely.
void apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force,
                 CableState& to, CableWorkspace& workspace);

/// d(phi, x)/d(T, F) for given section tangent stiffnesses.
Eigen::Matrix2d tip_flexibility(const Cable& cable, std::span<const double> tangent);
/// d(F, Q)/d(x, phi) from the flexibility d(phi, x)/d(T, F) of a cable of this
/// length (Q = T - F l): the tip stiffness for the damper.
Eigen::Matrix2d tip_stiffness(const Eigen::Matrix2d& flexibility, double length);

struct CantileverOptions {
  int max_iterations = 50;    ///< Newton iterations per state determination
  double tolerance = 1e-11;   ///< on the kinematic residual, relative to the step's scale
  int max_halvings = 40;      ///< line search
  /// Throws InvalidParameter naming the bad field.
  void validate() const;
};

/// How a state determination ended: never a number without this. Fills
/// termination, newton_iterations (each one evaluation of the cable, plus line
/// search), evaluations (cable evaluations in all) and residual (the final kinematic
/// residual, rad: deflections divided by l).
using StateDetermination = SolverSummary;

/// The cable with the trial/commit protocol.
class Cantilever {
 public:
  explicit Cantilever(Cable cable, CantileverOptions options = {});

  const Cable& cable() const { return cable_; }
  const CantileverOptions& options() const { return options_; }

  /// Tip deflection x and rotation phi prescribed: find T and F.
  StateDetermination set_trial_tip(double deflection, double rotation);
  /// Experiment (a): tip deflection prescribed, no tip moment (Q = 0, T = F l).
  StateDetermination set_trial_deflection(double deflection);
  /// Experiment (b): tip rotation prescribed with the tip guided (x = 0).
  StateDetermination set_trial_rotation(double rotation) { return set_trial_tip(0.0, rotation); }
  /// Loads prescribed: exact, no iteration.
  void set_trial_loads(double clamp_moment, double tip_force);

  const CableState& trial() const { return state_.trial(); }
  const CableState& committed() const { return state_.committed(); }
  void commit();
  void revert_to_last_commit() { state_.revert_to_last_commit(); }
  /// Back to the virgin state.
  void reset();
  /// Commits a given state (one of this cable's, e.g. saved from committed()).
  void restore(const CableState& state);
  /// Commits the mirror image of the committed state (CableState::mirror): driving
  /// the mirrored cable along a path gives the negative of driving the cable along
  /// the negative path. The predictor's last increment changes sign with it.
  void mirror();
  /// Commits the committed state moved halfway to `other` (CableState::move_halfway_to).
  void commit_halfway_to(const CableState& other);

 private:
  struct BothTipCoordinates;  // what a state determination prescribes (cantilever.cpp)
  struct DeflectionOnly;
  template <class Prescribed>
  StateDetermination solve(const typename Prescribed::Vector& target);

  Cable cable_;
  CantileverOptions options_;
  SwappingCommittable<CableState> state_;
  double inverse_length_;                // 1 / l
  bool second_order_;                    // the law fills CableState::flexibility_change
  Eigen::Matrix2d elastic_flexibility_;  // every element sticking: the predictor after a reversal
  Eigen::Vector2d last_increment_ = Eigen::Vector2d::Zero();  // of (phi, x / l) in the last committed step
  CableWorkspace workspace_;
  CableState candidate_;  // line-search trial
};

}  // namespace stockbridge::cable
