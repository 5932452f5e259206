#pragma once
// The polish of the span balance (BalanceOptions::polish): every damper's
// impedance solved directly (harmonic balance) at its own clamp velocity, all
// dampers' clamp velocities solved as one system. Library-internal.
//
// At trial clamp velocities v (u = log v; one unknown per damper of end 1 where end
// 2 mirrors it, else one per damper and end), each damper is solved directly there
// (Z_k = Z(f, v_k)) and the span balanced with these impedances held fixed: the
// smallest stable amplitude Y of P_w - P_s - P_d(1) Y^2 (with fixed impedances the
// ends respond linearly to Y: no fixed point, no table), whose dampers move at
// velocities G(v). The state is self-consistent where
//     h(u) = log G(exp u) - u = 0,
// solved by Powell's hybrid method (numerics::solve_fixed_point) with the Jacobian
//     dh/du = d log G / dZ . diag(dZ_k / du_k) - I:
// d log G / dZ is exact (the balance with fixed impedances differentiated:
// end_response_tangent, and the root's slope dY/dP_d(1) = Y^2 / N'(Y)); dZ_k / du_k,
// the one costly derivative, is a secant through damper k's last two direct solves
// (a damper's Z depends on its own velocity alone), started from the last
// frequency's or the table's slope.
//
// Along the band, each damper is followed by harmonic balance solved from its last
// solution (a DamperTracker; every trial of one frequency from that frequency's
// first solution, so that Z is a function of v even where two steady states of the
// damper coexist, but a trial within 1e-3 in log v of the damper's last solve at
// the frequency, which continues from that one, the same steady state a step away:
// Newton's last steps then cost a damper about one harmonic balance iteration (not
// under a polish tolerance below 1e-7, the damper solve's own scatter); cold where
// the path from the last frequency fails), and each
// frequency starts from the line through the last two frequencies' solutions in
// (log f, log v): the state reached by continuation from the band's low end. Where
// several self-consistent states exist, that is the one reported; the sign of
// det(dh/du) changing from one frequency to the next says the path passed a fold.

#include <complex>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "../numerics/nonlinear_system.hpp"
#include "frequency_balance.hpp"
#include "stockbridge/damper/tracker.hpp"

namespace stockbridge::span {

class Polish {
 public:
  Polish(const Span& span, const BalanceOptions& options);

  /// The balance with directly solved impedances at `balance`'s frequency: from the
  /// clamp velocities of the tables' balance at amplitude `from_tables`, or without
  /// it from the last frequencies' solutions (continues() must be true). On
  /// convergence the balance holds the solution's impedances fixed. summary:
  /// converged; inner_failure (a damper's direct solve, or the tables' velocities:
  /// `where`); max_iterations or no_progress (evaluations, residual = max |h|).
  StableRoot run(FrequencyBalance& balance, std::optional<double> from_tables);
  /// Whether a frequency was polished before (since forget()): run can continue from it.
  bool continues() const { return !history_.empty(); }
  /// Drops what the last frequencies handed on (after a failure: it may mislead).
  void forget();
  /// Whether the last run's solution lies across a fold of the self-consistent
  /// states from the frequency before (the sign of det(dh/du) changed).
  bool passed_fold() const { return passed_fold_; }
  int direct_solves() const;

 private:
  /// One unknown: a damper of the span and the (end, index) slots whose velocity it is.
  struct Unknown {
    std::size_t damper;
    std::vector<std::pair<std::size_t, std::size_t>> slots;
  };
  /// The span at trial velocities: the balance with the directly solved impedances.
  struct Trial {
    Eigen::VectorXd u;                           ///< log v
    std::vector<damper::ImpedancePoint> direct;  ///< per unknown, its damper solved directly
    double absorbed_per_square = 0.0;            ///< P_d(1): the ends' P_d / Y^2, W/m^2
    double amplitude = 0.0;                      ///< Y with these impedances held fixed
    Eigen::VectorXd h;                           ///< log G - u
  };
  /// A frequency's solution, handed on along the band.
  struct Solution {
    double log_f;
    Eigen::VectorXd u;  ///< log v* per unknown
    int jacobian_sign;  ///< of det(dh/du) there
  };

  /// One frequency's solve: the system's result, the trials it made, and why it
  /// stopped where an evaluation failed.
  struct Search {
    numerics::NonlinearSystemResult solved;
    std::vector<Trial> trials;
    std::optional<double> still;  ///< a trial's amplitude <= 0: with its impedances nothing builds up
    SolverSummary failure;        ///< the evaluation that failed (a direct solve, the balance)
    const Trial* trial_at(const Eigen::VectorXd& u) const;
  };

  std::vector<Unknown> unknowns_of(const FrequencyBalance& balance) const;
  /// The clamp velocities that reproduce themselves, from `start` (log v).
  Search search(FrequencyBalance& balance, const Eigen::VectorXd& start);
  /// Where and by how much a search that did not converge failed.
  std::string failure_where(const Search& search) const;
  /// Fixes the trial's directly solved impedances in the balance.
  void hold(FrequencyBalance& balance, const Trial& trial) const;
  /// Fixes the solution's impedances in the balance and hands it on along the band;
  /// its amplitude.
  double accept(FrequencyBalance& balance, const Trial& solution, bool continued);
  /// Where a frequency starts: the tables' clamp velocities at `from_tables`, or the
  /// last frequencies' solutions; none (with the reason) where neither is known.
  std::optional<Eigen::VectorXd> start(FrequencyBalance& balance, std::optional<double> from_tables,
                                       SolverSummary& failure);
  /// Solves every damper directly at exp(u) and balances the span with those impedances.
  std::optional<Trial> evaluate(FrequencyBalance& balance, const Eigen::VectorXd& u, SolverSummary& failure);
  damper::ImpedancePoint solve_directly(const FrequencyBalance& balance, const Unknown& unknown,
                                        const damper::Excitation& excitation);
  /// A measured damper's "direct solve": its sheet's Z, interpolated (the table).
  static damper::ImpedancePoint from_sheet(const FrequencyBalance& balance, const Unknown& unknown,
                                           const damper::Excitation& excitation);
  /// dh/du at a trial.
  Eigen::MatrixXd jacobian(FrequencyBalance& balance, const Trial& trial) const;
  void update_slopes(const Trial& trial);
  void start_slopes(const FrequencyBalance& balance, const Eigen::VectorXd& u);

  const BalanceOptions& options_;
  std::vector<std::optional<damper::DamperTracker>> trackers_;  ///< one per damper of the span; none for a measured sheet
  std::vector<std::optional<damper::DamperTracker::Checkpoint>> anchors_;  ///< per damper: this frequency's first solution
  std::vector<double> last_direct_;  ///< per damper: log v of its last direct solve at this frequency (NaN: none)
  std::vector<Unknown> unknowns_;
  std::vector<std::complex<double>> slopes_;  ///< dZ/du per unknown, the last secant
  std::optional<Trial> last_solved_;          ///< this frequency's last trial, for the secants
  std::vector<Solution> history_;             ///< the last two frequencies polished since forget()
  bool passed_fold_ = false;
};

}  // namespace stockbridge::span
