#pragma once
// The seam between a section law and the cable: what the cantilever, the periodic
// drive of harmonic balance and the modes need of a law, and nothing else. A law
// keeps its numbers per section (it is built from the CableDescription at the
// cable's Gauss points) and its internal variables in CableState::hysteretic
// (internal_variables() a section): the Jenkin moments H of the Masing law, eta of
// the Bouc-Wen law.
//
// What a law must give (docs/architecture.md, "A third section law"):
//   * its tangents in the two linear limits (stick: virgin and just after a
//     reversal; slip: fully developed), for the modes and the predictor;
//   * apply_loads: every section moved exactly, moment-driven, from one state to
//     the moment T - F s_i, with the tip kinematics, the flexibility and the energy
//     dissipated (the law is odd: CableState::mirror negates the internal variables;
//     and its moment is linear in the curvature and the internal variables, so that
//     the mean of two states is a state, CableState::move_halfway_to);
//   * how far two states' internal variables are apart (the periodicity defect);
//   * a LoadSensitivity: the exact derivative of the loads along a path;
//   * optionally, the flexibility's change (a smooth law) and the coordinates of
//     a periodic state, for harmonic balance's Newton on it.

#include <cstddef>
#include <memory>
#include <span>

#include <Eigen/Core>

namespace stockbridge::cable {

class Cable;
struct CableDescription;
struct CableState;
struct CableWorkspace;

/// Exact forward sensitivities of the loads (T, F) along a path of tip kinematics
/// whose samples depend on parameters q (PeriodicCable): one object a path, fed each
/// monotone step in order.
class LoadSensitivity {
 public:
  virtual ~LoadSensitivity() = default;
  /// Before the path: `parameters` columns, the starting state held fixed (its
  /// derivatives zero).
  virtual void start(Eigen::Index parameters) = 0;
  /// At the start of each pass over the path (a law may refresh running sums).
  virtual void begin_pass() {}
  /// The step `from` -> `to` (to reached from `from` monotonically, to's tip
  /// kinematics prescribed) whose target kinematics have the derivatives
  /// d_rotation = d phi/dq and d_deflection = dx/dq: d_clamp_moment = dT/dq and
  /// d_tip_force = dF/dq of `to`. d_rotation and d_deflection may be overwritten.
  virtual void step(const CableState& from, const CableState& to, Eigen::VectorXd& d_rotation,
                    Eigen::VectorXd& d_deflection, Eigen::VectorXd& d_clamp_moment, Eigen::VectorXd& d_tip_force) = 0;
  /// The cable's state was mirrored (CableState::mirror): so are the derivatives.
  virtual void mirror() = 0;
  /// For Newton on the periodic state (CableLaw::periodic_coordinates > 0), after
  /// start(): the columns from `first` on are the derivatives with respect to the
  /// starting state's coordinates z0 (CableLaw::coordinates), seeded here.
  virtual void seed_coordinates(Eigen::Index /*first*/) {}
  /// The internal variables' derivatives at the current state, sections x
  /// internal variables rows (section-major) by the parameters.
  virtual void internal_derivatives(Eigen::MatrixXd& /*out*/) const {}
};

class CableLaw {
 public:
  virtual ~CableLaw() = default;

  /// Entries of CableState::hysteretic per section.
  virtual std::size_t internal_variables() const = 0;
  /// Section i's tangent stiffness in the virgin state and just after a reversal, N m^2.
  virtual double stick_stiffness(std::size_t section) const = 0;
  /// Section i's tangent stiffness when its friction has fully developed, N m^2.
  virtual double slip_stiffness(std::size_t section) const = 0;
  /// Whether apply_loads fills CableState::flexibility_change (a law whose tangents
  /// vary smoothly with the moment); the cantilever's predictor and Newton steps then
  /// take the second order. Else it is zero, and they are the first-order ones.
  virtual bool has_flexibility_change() const { return false; }
  /// Loads in, state out (cable::apply_loads): fills every field of `to`.
  virtual void apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force,
                           CableState& to, CableWorkspace& workspace) const = 0;
  /// The largest change of an internal variable from `start` to `end`, relative to
  /// its scale (a slip moment, eta's range): 0 when equal.
  virtual double internal_change(const CableState& start, const CableState& end) const = 0;
  /// Newton on the periodic state (optional; HarmonicBalance uses it where offered):
  /// how many coordinates z fix a state of `cable` with its loads, 0 where the law
  /// offers none (Masing: its sticking sets make the state's map piecewise
  /// constant, and the halfway step settles it). Bouc-Wen: z = (T, F, eta_i), the
  /// curvatures following from the moment's linearity.
  virtual std::size_t periodic_coordinates(const Cable& /*cable*/) const { return 0; }
  /// z of `state` (periodic_coordinates entries).
  virtual void coordinates(const CableState& /*state*/, Eigen::VectorXd& /*z*/) const {}
  /// Moves `state` by dz in its coordinates, its curvatures and tip kinematics along
  /// (tangents, flexibility and dissipation stay), an internal variable stopped at
  /// its bound (Bouc-Wen: eta saturates at -1 or 1); false, `state` unchanged, where
  /// it cannot move (a non-finite dz).
  virtual bool shift(const Cable& /*cable*/, CableState& /*state*/, const Eigen::VectorXd& /*dz*/) const {
    return false;
  }
  /// A new propagator of the loads' sensitivities for this law on `cable`.
  virtual std::unique_ptr<LoadSensitivity> load_sensitivity(const Cable& cable) const = 0;
};

/// The law the description names, at the cable's Gauss points `positions`.
std::shared_ptr<const CableLaw> make_cable_law(const CableDescription& description, std::span<const double> positions,
                                               std::span<const double> weights);

}  // namespace stockbridge::cable
