#pragma once
// How a solver ended, for every iterative solver of the library: the cantilever's
// state determination, the periodic cable, harmonic balance, collocation, time
// integration and shooting, the span balance's root search and its systems, the
// fits and optimisers (Ceres's Summary / TerminationType). Callers branch
// and tests match on `termination`; messages are made from it and the figures by
// brief_report(), never parsed.

#include <limits>
#include <string>
#include <string_view>
#include <utility>

namespace stockbridge {

enum class Termination {
  not_run,             ///< the solver has produced nothing yet
  converged,           ///< every criterion met: the result may be used
  max_iterations,      ///< the Newton iteration limit was reached
  line_search_failed,  ///< no step along the Newton direction reduced the residual
  singular_jacobian,   ///< the Newton matrix is numerically singular: no solution is determined here
  non_finite,          ///< NaN or inf in the unknowns or the residual
  not_periodic,        ///< the state did not repeat within the periods allowed
  energy_mismatch,     ///< the equations hold but the energy balance is off beyond its tolerance
  inner_failure,       ///< a nested solve failed (e.g. a cable state determination); `where` says which
  no_progress,         ///< the iteration stopped making progress (the residual stopped falling, the step shrank to round-off)
  no_root,             ///< the function keeps its sign over the whole range searched: no root there
  interrupted,         ///< a stop was asked for (Ctrl-C, a caller's stop flag): ended early, nothing wrong
};

/// snake_case name, as in JSON output and Python ("line_search_failed").
std::string_view termination_name(Termination termination);

struct SolverSummary {
  Termination termination = Termination::not_run;
  /// Newton steps taken (state determination, harmonic balance, collocation, shooting);
  /// time integration takes none.
  int newton_iterations = 0;
  /// Periods integrated in all (periodic cable, harmonic balance and collocation
  /// including the settling periods, time integration, shooting).
  int periods = 0;
  int evaluations = 0;  ///< evaluations of the solver's residual (or of the cable)
  int jacobians = 0;    ///< of which with an exact Jacobian
  /// Final residual, relative to the solver's scale (each solver's header says which).
  double residual = std::numeric_limits<double>::quiet_NaN();
  /// How much the state still changes over one period, relative (periodic solvers).
  double periodicity_defect = std::numeric_limits<double>::quiet_NaN();
  /// |P - D/T| relative to the apparent power (periodic solvers of the damper).
  double energy_error = std::numeric_limits<double>::quiet_NaN();
  /// Estimated reciprocal condition number of the Newton matrix (singular_jacobian).
  double reciprocal_condition = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;  ///< wall time
  /// Where the solver stopped, for the message ("at sample 12 of period 2"); the
  /// nested failure's report for inner_failure. Empty when converged.
  std::string where;

  bool converged() const { return termination == Termination::converged; }
};

/// A summary of only its termination and where it ended (a step's outcome, a
/// failure before any figure was computed).
inline SolverSummary summary_of(Termination termination, std::string where = {}) {
  SolverSummary summary;
  summary.termination = termination;
  summary.where = std::move(where);
  return summary;
}

/// One line: what happened, with the figures that say by how much and where
/// ("no convergence in 100 Newton iterations (residual 3.2e-05) at ...").
std::string brief_report(const SolverSummary& summary);

}  // namespace stockbridge
