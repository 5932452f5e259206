#pragma once
// The conductor in time (MODEL.md section 16; docs/time-domain.md): the span as a
// tensioned Euler-Bernoulli beam
//
//     m y_tt + EI y_xxxx - T y_xx = q(x, t),
//
// in cubic Hermite elements (a node's displacement and slope), pinned or clamped at
// both ends, stepped by Newmark's average acceleration rule, which conserves the
// energy of the undamped beam to round-off at any step. The matrices are banded
// (each node couples only with its neighbours): the one matrix a step solves is
// factored once, in the nodes' order, and a step costs a few operations a degree of
// freedom.
//
// With the EBM's own wind (`settle_on_ebm_wind`), the span's amplitude in time
// checks the energy balance's: the wind's input and the self-damping act as a
// distributed force c(x) y_t on the velocity's component at the drive frequency,
// c(x) from the local antinode amplitude, so that over a loop the power per length
// is the EBM's at that amplitude.

#include <complex>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "stockbridge/span/span.hpp"

namespace stockbridge::span {

/// How the conductor is held at the span's two clamps.
enum class BeamEnds {
  pinned,   ///< no displacement, the slope free
  clamped,  ///< no displacement, no slope (the suspension clamps)
};
/// "pinned" or "clamped".
std::string_view beam_ends_name(BeamEnds ends);
/// "pinned" or "clamped"; InvalidParameter naming "ends" otherwise.
BeamEnds parse_beam_ends(std::string_view name);

/// A linear dashpot on the conductor: F = -c y_t at its position (a damper of
/// impedance Z = c, real and constant: the closed-form check of the balance).
struct PointDashpot {
  double position_m = 0.0;        ///< from end 1, in (0, L)
  double coefficient_n_s_m = 0.0; ///< c > 0
};

/// A beam's numbers (SI): length L, mass per length m, tension T, bending stiffness EI.
struct BeamProperties {
  double length = 0.0;
  double mass_per_length = 0.0;
  double tension = 0.0;
  double ei = 0.0;
  BeamEnds ends = BeamEnds::clamped;

  /// The pinned beam-string's n-th natural frequency,
  /// f_n = (n / 2L) sqrt(T / m) sqrt(1 + (n pi / L)^2 EI / T), Hz.
  double pinned_frequency(int n) const;
};

/// The beam in `elements` equal cubic Hermite elements: its consistent mass matrix M
/// and stiffness matrix K (bending and tension) over the free degrees of freedom,
/// node by node (displacement, then slope; those the ends hold removed).
class BeamModel {
 public:
  /// InvalidParameter naming "length", "mass_per_length", "tension", "ei" (>= 0) or
  /// "elements" (2 to 10^6).
  BeamModel(const BeamProperties& properties, int elements);

  const BeamProperties& properties() const { return properties_; }
  int elements() const { return elements_; }
  double element_length() const { return properties_.length / elements_; }
  /// Free degrees of freedom.
  Eigen::Index size() const { return mass_.rows(); }
  const Eigen::SparseMatrix<double>& mass() const { return mass_; }
  const Eigen::SparseMatrix<double>& stiffness() const { return stiffness_; }
  /// The damping matrix of dashpots, sum c N(x) N(x)^T (N the shape functions at
  /// x): InvalidParameter naming "dashpots[i]" where one is off the span or c <= 0.
  Eigen::SparseMatrix<double> damping(const std::vector<PointDashpot>& dashpots) const;

  /// The lowest `count` natural frequencies, Hz (a dense generalised eigenproblem:
  /// for checks, a few thousand degrees of freedom at most).
  std::vector<double> natural_frequencies(int count) const;

  /// The displacement and slope at x (0 <= x <= L) of the free vector `u` (real or
  /// complex amplitudes).
  template <class Scalar>
  std::pair<Scalar, Scalar> at(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& u, double x) const;
  /// Index in the free vector of node i's displacement (0) or slope (1); -1 where held.
  Eigen::Index index(int node, int which) const { return dof_[2 * node + which]; }

 private:
  BeamProperties properties_;
  int elements_;
  std::vector<Eigen::Index> dof_;  ///< per node and (displacement, slope): free index or -1
  Eigen::SparseMatrix<double> mass_, stiffness_;
};

/// Newmark's average acceleration rule (beta = 1/4, gamma = 1/2) on
/// M u'' + C u' + K u = F(t), with M + (dt / 2) C + (dt^2 / 4) K factored once (sparse
/// LDL^T in the nodes' order: banded).
class NewmarkStepper {
 public:
  /// From initial displacement u0 and velocity v0; F0 the load at t = 0; `damping`
  /// C (empty: none).
  NewmarkStepper(const BeamModel& model, double dt, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                 const Eigen::VectorXd& load0, Eigen::SparseMatrix<double> damping = {});

  /// One step to t + dt under the load at t + dt.
  void step(const Eigen::VectorXd& load_next);
  double time() const { return time_; }
  double dt() const { return dt_; }
  const Eigen::VectorXd& displacement() const { return u_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  /// Kinetic plus strain energy, (v^T M v + u^T K u) / 2, J.
  double energy() const;
  /// The energy the damping took so far, J: the rule's own balance, each step
  /// (dt / 4) (v + v+)^T C (v + v+), so that energy() + dissipated() stays at its
  /// start to round-off without load.
  double dissipated() const { return dissipated_; }

 private:
  const BeamModel& model_;
  Eigen::SparseMatrix<double> damping_;
  double dissipated_ = 0.0;
  double dt_;
  double time_ = 0.0;
  Eigen::VectorXd u_, v_, a_;
  Eigen::VectorXd rhs_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> effective_;
};

/// What settle_on_ebm_wind is asked.
struct EbmWindOptions {
  double frequency_hz = 0.0;             ///< the drive: the beam's natural frequency nearest it is taken
  double duration_s = 60.0;              ///< the most time simulated
  int elements_per_wavelength = 10;      ///< at the drive frequency (>= 4)
  int steps_per_period = 40;             ///< >= 8
  double start_amplitude_m = 0.0;        ///< the mode's antinode amplitude at t = 0 (> 0)
  /// Settled: the envelope's distance from the value it approaches (extrapolated
  /// from its changes over the last 20 periods), relative, below it for 20 periods
  /// in a row.
  double settled_change = 1e-3;
};

/// The span's motion under the EBM's wind, in time.
struct EbmWindHistory {
  double frequency_hz = 0.0;         ///< the drive: the beam's natural frequency taken
  int elements = 0;
  double dt_s = 0.0;
  bool settled = false;
  double time_s = 0.0;               ///< simulated
  /// Per period: the local antinode amplitude Y at mid-span, where a symmetric
  /// span's wave carries no energy either way (toward the dampers Y grows: part of
  /// the wave travels there).
  std::vector<double> envelope_m;
  double antinode_amplitude_m = 0.0; ///< the last period's
  std::vector<double> x_m;           ///< the nodes
  std::vector<double> amplitude_m;   ///< |y^| at the nodes, the last period
  /// Per dashpot, the mean power it took over the last period, W.
  std::vector<double> dashpot_power_w;
};

/// The span's conductor under its wind (a) of MODEL.md 16 and self-damping as the
/// span file gives them, with `dashpots` on it (the span's own dampers are not
/// modelled in time yet: they are left out), stepped until the envelope settles or
/// `duration_s` is reached. The drive is the pinned or clamped beam's natural mode
/// nearest `frequency_hz` (without the dashpots), started at `start_amplitude_m`.
/// InvalidParameter naming the option where one is out of range.
EbmWindHistory settle_on_ebm_wind(const Span& span, BeamEnds ends, const EbmWindOptions& options,
                                  const std::vector<PointDashpot>& dashpots = {});

}  // namespace stockbridge::span
