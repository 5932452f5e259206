#pragma once
// Harmonic balance (Galerkin) and trigonometric collocation for one arm's
// periodic steady state (MODEL.md section 6, dissertation 4.2.5.3-4).
//
// The arm's tip kinematics are a Fourier series of H harmonics,
//     u(t) = u_0 + sum_k a_k cos(k W t) + b_k sin(k W t),  unknowns q = [u_0, a_1, b_1, ...],
// two numbers (x, phi) each. The cable loads f(t) = (F, Q) follow by alternating
// frequency-time: u is sampled at N points per period, the cable is driven
// through a pre-period and the period with the exact law, and f is projected
// back. Harmonic balance sets the Galerkin projection of the equation of motion
// M u'' + f = L x_c'' to zero; collocation sets the equation itself to zero at
// N = 2H + 1 points. Newton's method uses the exact Jacobian (forward
// sensitivities of the piecewise-linear cable map) and a backtracking line search.

#include <Eigen/Core>

#include "stockbridge/damper/periodic_cable.hpp"
#include "stockbridge/damper/periodic_solution.hpp"

namespace stockbridge::damper {

struct HarmonicBalanceOptions {
  int harmonics = 9;          ///< H, >= 1
  int samples = 0;            ///< AFT samples per period (harmonic balance); 0: 8 H rounded up to a power of 2, >= 64
  bool collocation = false;   ///< trigonometric collocation at 2H + 1 points instead
  int max_iterations = 40;    ///< Newton iterations
  double tolerance = 1e-9;    ///< residual relative to the excitation force amplitude m W^2 X
  /// The cable is driven from the virgin state through P periods and the last one is
  /// used; P starts at 2 (or the hint) and doubles until the loads of the last two
  /// periods differ by at most this, relative to their largest value.
  double periodicity_tolerance = 1e-7;
  int max_periods = 32;
  cable::CantileverOptions cantilever;

  void validate() const;
  /// The number of time samples per period actually used.
  int sample_count() const;
};

class HarmonicBalance {
 public:
  HarmonicBalance(const Arm& arm, HarmonicBalanceOptions options);

  const HarmonicBalanceOptions& options() const { return options_; }
  int unknown_count() const { return 2 * (2 * options_.harmonics + 1); }

  /// The all-stick linear steady state (a starting point where no predictor exists).
  Eigen::VectorXd linear_guess(const Excitation& excitation) const;

  /// Newton from `initial` (unknown_count() coefficients, m and rad), starting with
  /// `periods` periods of the cable (at least 2; the previous frequency's count is a good hint).
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& initial, int periods = 2);

  /// The residual (N, relative to nothing) at q, and optionally its exact Jacobian
  /// and its derivative with respect to the angular frequency at constant velocity
  /// amplitude (for arclength continuation). Returns false if the cable failed.
  bool residual(const Excitation& excitation, const Eigen::VectorXd& q, int periods, Eigen::VectorXd& r,
                Eigen::MatrixXd* jacobian, Eigen::VectorXd* d_frequency, PeriodicCableResult* loads);

  /// The excitation force scale m W^2 X used for the tolerance, N.
  double force_scale(const Excitation& excitation) const;

 private:
  ArmPeriod period_of(const Eigen::VectorXd& q, const PeriodicCableResult& loads) const;
  /// Newton at a fixed number of cable periods; updates q and loads.
  bool newton(const Excitation& excitation, int periods, Eigen::VectorXd& q, PeriodicCableResult& loads,
              SolverSummary& summary);

  const Arm& arm_;
  HarmonicBalanceOptions options_;
  int samples_;
  Eigen::MatrixXd basis_;       // N x (2H+1): 1, cos(k W t_j), sin(k W t_j)
  Eigen::MatrixXd projection_;  // (2H+1) x N: Fourier coefficients from samples (harmonic balance)
  PeriodicCable cable_;
  Eigen::MatrixXd sensitivity_;
};

}  // namespace stockbridge::damper
