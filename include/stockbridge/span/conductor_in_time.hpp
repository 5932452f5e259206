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
// checks the energy balance's: the wind's input acts as a distributed force
// c_w(x) y_t on the velocity's component at the drive frequency and the
// self-damping as a distributed damper c_s(x) on the whole velocity, both from the
// local antinode amplitude, so that over a loop the net power per length is the
// EBM's at that amplitude. The span's dampers are stepped by their own models in
// time and solved with the conductor each step.

#include <array>
#include <atomic>
#include <complex>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "stockbridge/damper/damper_in_time.hpp"
#include "stockbridge/span/span.hpp"
#include "stockbridge/span/time_settings.hpp"

namespace stockbridge::span {

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

/// The beam in cubic Hermite elements: its consistent mass matrix M and stiffness
/// matrix K (bending and tension) over the free degrees of freedom, node by node
/// (displacement, then slope; those the ends hold removed). The elements are equal,
/// or between given nodes (a node at each attachment: a point force's kink falls on
/// a node, where the Hermite interpolation allows it).
class BeamModel {
 public:
  /// InvalidParameter naming "length", "mass_per_length", "tension", "ei" (>= 0) or
  /// "elements" (2 to 10^6).
  BeamModel(const BeamProperties& properties, int elements);
  /// Between `nodes` (m from end 1: 0 first, L last, increasing): InvalidParameter
  /// naming "nodes" otherwise.
  BeamModel(const BeamProperties& properties, std::vector<double> nodes);

  const BeamProperties& properties() const { return properties_; }
  int elements() const { return static_cast<int>(nodes_.size()) - 1; }
  const std::vector<double>& nodes() const { return nodes_; }
  double element_length(int e) const { return nodes_[e + 1] - nodes_[e]; }
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
  std::vector<double> nodes_;
  std::vector<Eigen::Index> dof_;  ///< per node and (displacement, slope): free index or -1
  Eigen::SparseMatrix<double> mass_, stiffness_;
};

/// A damper in time on the beam (damper/damper_in_time.hpp), its clamp at x from
/// end 1: the clamp moves as the beam there does.
struct BeamDamper {
  double position_m = 0.0;
  damper::DamperInTime damper;
};

/// Newmark's average acceleration rule (beta = 1/4, gamma = 1/2) on
/// M u'' + C u' + K u = F(t) + sum_d N_d F_d, with M + (dt / 2) C + (dt^2 / 4) K
/// factored once (sparse LDL^T in the nodes' order: banded). N_d are the shape
/// functions at damper d's clamp and F_d its force, which depends on the clamp's
/// acceleration: each step solves the beam and the dampers together, by Newton's
/// method on the clamps' accelerations a_c = N^T u'' (a few unknowns): the beam's
/// part is a0 + S F with a0 the step without the dampers and S = (M + ...)^-1 N,
/// made once, so the iteration costs no solve of the beam and has the dampers' exact
/// tangents.
class NewmarkStepper {
 public:
  /// From initial displacement u0 and velocity v0 (the dampers at rest, undeflected);
  /// F0 the load at t = 0; `damping` C (empty: none); `dampers` stepped by `dt`
  /// (InvalidParameter naming "dampers[i]" where one is off the span or steps by
  /// another dt).
  NewmarkStepper(const BeamModel& model, double dt, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                 const Eigen::VectorXd& load0, Eigen::SparseMatrix<double> damping = {},
                 std::vector<BeamDamper> dampers = {});

  /// Another damping matrix C from the next step on (the same pattern: the matrix is
  /// factored again, numerically only). The energy balances below hold step by step
  /// for each step's C; across a change the start's acceleration was the old C's.
  void set_damping(Eigen::SparseMatrix<double> damping);
  /// One step to t + dt under the load at t + dt. With dampers, NumericalError
  /// naming the time and by how much where the coupled iteration does not converge
  /// (or a damper's own iteration fails).
  void step(const Eigen::VectorXd& load_next);
  double time() const { return time_; }
  double dt() const { return dt_; }
  const BeamModel& model() const { return model_; }
  const Eigen::VectorXd& displacement() const { return u_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  const Eigen::VectorXd& acceleration() const { return a_; }
  /// Kinetic plus strain energy of the beam, (v^T M v + u^T K u) / 2, J.
  double energy() const;
  /// The energy the damping took so far, J: the rule's own balance, each step
  /// (dt / 4) (v + v+)^T C (v + v+), so that energy() + dissipated() stays at its
  /// start to round-off without load.
  double dissipated() const { return dissipated_; }
  const std::vector<BeamDamper>& dampers() const { return dampers_; }
  /// Damper d's clamp: the beam's displacement and velocity at its position.
  double clamp_displacement(std::size_t d) const { return attachment_.col(static_cast<Eigen::Index>(d)).dot(u_); }
  double clamp_velocity(std::size_t d) const { return attachment_.col(static_cast<Eigen::Index>(d)).dot(v_); }
  /// The work the dampers' forces did on the beam so far, J, the rule's own
  /// (each step (y_d+ - y_d) (F_d + F_d+) / 2): energy() + dissipated() -
  /// dampers_work() stays at its start without load.
  double dampers_work() const { return damper_work_.sum(); }
  /// Damper d's part of it, J.
  double dampers_work_of(std::size_t d) const { return damper_work_(static_cast<Eigen::Index>(d)); }

 private:
  void start_dampers(const Eigen::VectorXd& load0);
  /// The step's acceleration from the one without the dampers (overwritten).
  const Eigen::VectorXd& coupled_acceleration(Eigen::VectorXd& uncoupled);

  const BeamModel& model_;
  Eigen::SparseMatrix<double> damping_;
  double dissipated_ = 0.0;
  double dt_;
  double time_ = 0.0;
  Eigen::VectorXd u_, v_, a_;
  Eigen::VectorXd rhs_, predicted_u_, predicted_v_, uncoupled_, velocity_sum_, damped_;  ///< a step's workspace
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> effective_;
  std::vector<BeamDamper> dampers_;
  Eigen::MatrixXd attachment_;  ///< N: a column per damper
  Eigen::MatrixXd influence_;   ///< S = (M + dt C / 2 + dt^2 K / 4)^-1 N
  Eigen::MatrixXd coupling_;    ///< G = N^T S
  Eigen::VectorXd forces_;      ///< F_d at the last step
  Eigen::VectorXd damper_work_;  ///< per damper
};

/// The wake oscillators of a beam's elements (one at each element's middle), stepped
/// by Newmark's average acceleration rule (the van der Pol damping at the step's end,
/// as the rule takes every force: a scalar Newton iteration each), the conductor's
/// acceleration at the step's start driving it (the beam's step that follows takes the lift at its
/// end: a staggered coupling, one step behind, at 160 steps a period).
class WakeOscillators {
 public:
  /// `count` oscillators at rest but for q = q0, shedding at w_s (rad/s), for a
  /// conductor of diameter D, stepped by dt.
  WakeOscillators(Eigen::Index count, const WakeParameters& parameters, double shedding_w, double diameter, double dt,
                  double q0 = 0.0);
  /// One step to t + dt, the conductor's acceleration at each oscillator given (at t).
  void step(const Eigen::VectorXd& acceleration);
  const Eigen::VectorXd& q() const { return q_; }
  const Eigen::VectorXd& q_velocity() const { return p_; }

 private:
  WakeParameters parameters_;
  double w_, diameter_, dt_;
  Eigen::VectorXd q_, p_, qa_;
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
  /// Settled in the mean: where the envelope keeps fluctuating (nonlinear dampers
  /// exchange energy between the drive mode and its neighbours, a beat of the modes'
  /// spacing), its means over consecutive windows of two round trips of a wave along
  /// the span: the distance of the last window's mean from the value the means
  /// approach (extrapolated as above from three windows), relative, below this.
  double settled_mean_change = 2e-3;
  /// The dampers' own Newton iteration (its steps_per_period is not used: the
  /// dampers step with the beam).
  damper::TimeDomainOptions damper;
  /// The wind: the EBM's (a) or the wake oscillator (b), whose shedding frequency is
  /// frequency_hz (the wind speed U = f D / St) and which starts at rest (q = 0), driven
  /// by the conductor's motion from start_amplitude_m; the self-damping is the same.
  WindInTime wind = WindInTime::ebm;
  WakeParameters wake;
  /// Called after every step (a history's row), where given.
  std::function<void(const NewmarkStepper&)> observer;
  /// Set (from any thread or a signal handler): the run ends after the step under
  /// way, `interrupted`, with the figures of the periods done.
  const std::atomic<bool>* stop = nullptr;
};

/// A damper's figures, means over the periods the history's figures are taken over.
struct DamperInTimeFigures {
  std::string name;
  double position_m = 0.0;           ///< from end 1
  /// The mean power the conductor gave it (the step's own work), W.
  double power_w = 0.0;
  /// Its cables' sliders' dissipation per second, W (equal to power_w once the
  /// motion repeats, to the time step's accuracy).
  double dissipated_w = 0.0;
  /// The clamp velocity's component at the drive frequency, amplitude, m/s.
  double velocity_amplitude_m_s = 0.0;
  /// The clamp force's harmonics of the drive frequency, 1, 2, ..., amplitudes, N.
  std::vector<double> force_harmonics_n;
};

/// How a simulation was judged settled.
enum class SettledBy {
  not_settled,  ///< neither rule held by the end
  envelope,     ///< the envelope itself, period by period (settled_change)
  mean,         ///< the envelope's means over windows (settled_mean_change)
};
/// "not_settled", "envelope" or "mean".
std::string_view settled_by_name(SettledBy rule);

/// The span's motion under the EBM's wind, in time.
struct EbmWindHistory {
  double frequency_hz = 0.0;         ///< the drive: the beam's natural frequency taken
  int elements = 0;
  double dt_s = 0.0;
  bool settled = false;
  SettledBy settled_by = SettledBy::not_settled;
  /// The periods the steady figures are means over: the last 20 (settled by the
  /// envelope), the last window (by the mean), or the last period (not settled).
  int figure_periods = 0;
  /// The envelope's standard deviation over those periods, relative to its mean.
  double envelope_fluctuation = 0.0;
  bool interrupted = false;          ///< stopped by `stop` before settling or the duration
  double time_s = 0.0;               ///< simulated
  /// Per period: the local antinode amplitude Y at mid-span, where a symmetric
  /// span's wave carries no energy either way (toward the dampers Y grows: part of
  /// the wave travels there).
  std::vector<double> envelope_m;
  double antinode_amplitude_m = 0.0; ///< the envelope's mean over figure_periods
  /// The local antinode amplitude in the stretch next to each span clamp (up to the
  /// first attachment or node), m, its mean over figure_periods: the loop amplitude
  /// S the clamp's bending follows (fatigue.hpp).
  std::array<double, 2> end_loop_amplitude_m{};
  std::vector<double> x_m;           ///< the nodes
  std::vector<double> amplitude_m;   ///< |y^| at the nodes, the last period's
  /// The local antinode amplitude sqrt(|y^|^2 + |y^'/k|^2) at the nodes, the last
  /// period's: the standing wave's envelope along the span (|y^| samples it).
  std::vector<double> antinode_along_m;
  /// Means over figure_periods (the rule's own work, each step (u+ - u) (F + F+) / 2):
  /// the power the wind put in, W, and the power the self-damping and the dashpots
  /// took, W (with the dampers' powers, they balance once the motion repeats).
  double wind_power_w = 0.0;
  double damping_power_w = 0.0;
  /// With the wake oscillator: the wind speed whose shedding frequency is the one asked, m/s.
  double wind_speed_m_s = 0.0;
  /// Per dashpot, the mean power it took over the last period, W.
  std::vector<double> dashpot_power_w;
  /// The span's dampers, each position of each (end 1's first), in the span file's order.
  std::vector<DamperInTimeFigures> dampers;
};

/// The span's conductor under its wind (a) of MODEL.md 16 (or the wake oscillator,
/// options.wind) and self-damping as the span file gives them, with the span's dampers on it, each by its own model in
/// time (damper/damper_in_time.hpp), and `dashpots`, stepped until the envelope
/// settles or `duration_s` is reached. The mesh has a node at every damper and
/// dashpot. The drive is the pinned or clamped beam's natural mode nearest
/// `frequency_hz` (without the dampers), started at `start_amplitude_m`.
/// InvalidParameter naming the option where one is out of range, "damper[i]" where
/// a damper is known only by its measured sheet (a sheet has no form in time) and
/// "mass[i]" for the masses (not modelled in time yet).
EbmWindHistory settle_on_ebm_wind(const Span& span, BeamEnds ends, const EbmWindOptions& options,
                                  const std::vector<PointDashpot>& dashpots = {});
/// Whether the span can be stepped in time: InvalidParameter as settle_on_ebm_wind
/// for a damper known only by its sheet ("damper[i]") or masses ("mass[0]").
void check_in_time(const Span& span);

}  // namespace stockbridge::span
