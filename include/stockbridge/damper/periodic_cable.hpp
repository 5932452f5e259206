#pragma once
// Drives an arm's cable through a sampled periodic path of tip kinematics
// u_j = (x_j, phi_j), j = 0..N-1 (one period, t_j = j T / N), starting from the
// virgin state (or a given state), for a fixed number of periods, and returns the
// loads of the last one with its periodicity defect (how much the state changed
// over it).
// A single Jenkin element is periodic after one pre-period (MODEL.md section 6);
// the cable under two prescribed tip coordinates is not: its sections' memories
// settle geometrically over several periods (defects of 1e-6 .. 1e-10 after six
// periods are typical in the slipping regime). The number of periods is fixed per
// call so that the loads are a deterministic, piecewise-linear function of the
// path; the solvers raise it until the defect is small enough.
// Each step is a monotone increment of the exact cable law.
//
// Optionally propagates exact forward sensitivities of the loads with respect to
// parameters p of the path, du_j/dp = (basis row j) per degree of freedom, step by
// step through the cable law's LoadSensitivity (cable_law.hpp): for the Masing law
// the map from the path to the loads is piecewise linear and its derivative follows
// from the sticking sets of every section; for a smooth law from each section's
// state derivatives; the tip kinematics close both through the exact flexibility.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/damper/periodic_solution.hpp"

namespace stockbridge::damper {

/// What the path's second half is.
enum class PathSymmetry {
  none,       ///< the samples are a whole period
  /// The samples are the first half of a period whose second half is their negative,
  /// u(t + T/2) = -u(t) (odd harmonics only). The cable law is odd, so the second half
  /// from state S is the mirror image of the first half from the mirror image of S:
  /// each pass drives the half and mirrors the state (Cantilever::mirror), and a
  /// steady state is one whose mirror image the half leads back to. Half the samples
  /// per pass, and the mirrored memory settles in half-period steps.
  half_wave,
};

struct PeriodicCableResult {
  /// termination: converged when every state determination converged, else
  /// inner_failure with `where` naming the sample, the period and the failed state
  /// determination's report; newton_iterations: the most any state determination
  /// took; periods: periods run in all; periodicity_defect: how far the cable's state
  /// at the end of the last period is from its state at that period's start,
  /// max |kappa_end - kappa_start| / max |kappa| over the sections, and the law's
  /// internal_change (Masing: max |H_end - H_start| / h over the elements; Bouc-Wen:
  /// max |eta_end - eta_start|); zero: every further period repeats the last one exactly.
  SolverSummary summary;
  /// The final period: the tip loads (F, Q), the clamp moment and the clamp
  /// section's curvature and moment per sample, the sliders' dissipation.
  ArmPeriod period;
  /// Under PeriodicStart::newton with sensitivities: d z_end / d(q, z0), the end
  /// state's coordinates (CableLaw::coordinates) by the path's parameters q and the
  /// start state's coordinates z0 (m x (2C + m)).
  Eigen::MatrixXd state_jacobian;
};

/// How the passes treat the state they start from.
enum class PeriodicStart {
  /// The passes run from it and, under half-wave symmetry, the final state is
  /// centred between the last pass's start and its mirrored end (the moments
  /// friction locks in); the start's own derivatives are zero.
  chained,
  /// The passes run from it as they are (no centring): the caller solves for the
  /// periodic start itself (Newton on the periodic state). With sensitivities the
  /// law's periodic coordinates of the start are parameters too (state_jacobian),
  /// after the path's, and `sensitivity` has their columns.
  newton,
};

class PeriodicCable {
 public:
  PeriodicCable(const cable::Cable& cable, cable::CantileverOptions options);

  /// Loads along the periodic path `kinematics` (2 x N) in the last of `passes`
  /// passes of it (periods; half periods, each followed by the mirror, under
  /// PathSymmetry::half_wave), starting from `start` (nullptr: the virgin state).
  /// With `basis` (N x C) the path is u_j = sum_c basis(j, c) q(2c + d) for DOF d,
  /// and `sensitivity` (2N x 2C, rows 2j + d for F (d = 0) and Q (d = 1)) receives
  /// the exact derivative of the final pass's loads with respect to q. The period
  /// returned is whole (2N samples under half_wave, the second half the negative of
  /// the first); the final state is the one the next pass would start from.
  PeriodicCableResult evaluate(const Eigen::Matrix2Xd& kinematics, int passes, const cable::CableState* start = nullptr,
                               const Eigen::MatrixXd* basis = nullptr, Eigen::MatrixXd* sensitivity = nullptr,
                               PathSymmetry symmetry = PathSymmetry::none,
                               PeriodicStart mode = PeriodicStart::chained);
  /// The cable's state at the end of the last evaluation.
  const cable::CableState& final_state() const { return cantilever_.committed(); }
  const cable::Cable& cable() const { return cantilever_.cable(); }

 private:
  /// A point between two samples where the smooth path through them (the cubic
  /// through four samples with central-difference slopes, one C1 curve for the whole
  /// period) turns in x or phi: driven, not recorded, so that the cable reaches the
  /// path's extreme rather than the nearest sample (the loop's tips).
  struct TurningPoint {
    double time = 0.0;             ///< in samples from the pass's start (-1 < time < N - 1)
    Eigen::Vector2d kinematics;    ///< (x, phi)
    Eigen::VectorXd d_x, d_phi;    ///< their derivatives with respect to q (with a basis)
  };
  void find_turning_points(const Eigen::Matrix2Xd& kinematics, bool half_wave, const Eigen::MatrixXd* basis);
  /// One step of the cable to `tip` (sample < 0: a turning point, committed here;
  /// a sample is committed by the caller after recording it), with its sensitivities
  /// from rhs_x_, rhs_phi_; false (summary filled) if the state determination failed.
  bool drive_to(const Eigen::Vector2d& tip, int sample, bool with_sensitivity, Eigen::MatrixXd* sensitivity,
                SolverSummary& summary, int pass, bool half_wave);
  void set_sample_derivative(const Eigen::MatrixXd& basis, int sample);
  void propagate_sensitivity(const cable::CableState& from, const cable::CableState& to, int sample,
                             Eigen::MatrixXd* sensitivity);
  /// d z / d(q, z0) of the current state, its loads' derivatives the last step's.
  void state_derivatives(Eigen::MatrixXd& out);

  double state_change(const cable::CableState& start, const cable::CableState& end) const;
  /// Mirrors the cable and, with it, the sensitivities carried to the next pass.
  void mirror(bool with_sensitivity);
  /// Under half-wave symmetry: the final state halfway between the last pass's start
  /// and its mirrored end (centres the moments friction locks in).
  void settle_locked_moments();

  cable::Cantilever cantilever_;
  cable::CableState period_start_;
  std::vector<TurningPoint> turning_points_;
  std::unique_ptr<cable::LoadSensitivity> sensitivity_;
  Eigen::VectorXd rhs_phi_, rhs_x_, d_clamp_moment_, d_tip_force_;  // du/dq of the step's target, d(T, F)/dq
  Eigen::Index columns_ = 0;  // sensitivity columns: the path's, then the start's coordinates
  Eigen::MatrixXd internal_derivatives_;
};

}  // namespace stockbridge::damper
