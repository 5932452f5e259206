#include "stockbridge/numerics/solver_summary.hpp"

#include <cmath>

#include <fmt/format.h>

namespace stockbridge {

std::string_view termination_name(Termination termination) {
  switch (termination) {
    case Termination::not_run: return "not_run";
    case Termination::converged: return "converged";
    case Termination::max_iterations: return "max_iterations";
    case Termination::line_search_failed: return "line_search_failed";
    case Termination::singular_jacobian: return "singular_jacobian";
    case Termination::non_finite: return "non_finite";
    case Termination::not_periodic: return "not_periodic";
    case Termination::energy_mismatch: return "energy_mismatch";
    case Termination::inner_failure: return "inner_failure";
    case Termination::no_progress: return "no_progress";
    case Termination::no_root: return "no_root";
    case Termination::interrupted: return "interrupted";
  }
  return "unknown";
}

namespace {

std::string what_happened(const SolverSummary& s) {
  switch (s.termination) {
    case Termination::not_run: return "not solved";
    case Termination::converged:
      return fmt::format("converged in {} Newton iterations and {} periods (residual {:.3g})", s.newton_iterations,
                         s.periods, s.residual);
    case Termination::max_iterations:
      if (s.newton_iterations == 0 && s.evaluations > 0) {
        return fmt::format("no convergence in {} evaluations{}", s.evaluations,
                           std::isnan(s.residual) ? "" : fmt::format(" (residual {:.3g})", s.residual));
      }
      return fmt::format("no convergence in {} Newton iterations (residual {:.3g})", s.newton_iterations, s.residual);
    case Termination::line_search_failed:
      return fmt::format("line search failed at Newton iteration {} (residual {:.3g})", s.newton_iterations + 1,
                         s.residual);
    case Termination::singular_jacobian:
      return fmt::format("singular Jacobian at Newton iteration {} (reciprocal condition number {:.3g}, residual {:.3g}): "
                         "no periodic solution is determined here",
                         s.newton_iterations + 1, s.reciprocal_condition, s.residual);
    case Termination::non_finite: return "non-finite values (NaN or inf)";
    case Termination::not_periodic:
      return fmt::format("not periodic after {} periods (the state still changes by {:.3g} per period)", s.periods,
                         s.periodicity_defect);
    case Termination::energy_mismatch:
      return fmt::format("energy balance off by {:.3g} of the apparent power", s.energy_error);
    case Termination::inner_failure: return "a nested solve failed";
    case Termination::no_progress:
      return fmt::format("no progress after {} evaluations{}", s.evaluations,
                         std::isnan(s.residual) ? "" : fmt::format(" (residual {:.3g})", s.residual));
    case Termination::no_root: return "no root in the range searched";
    case Termination::interrupted: return "interrupted (a stop was asked for)";
  }
  return "unknown termination";
}

}  // namespace

std::string brief_report(const SolverSummary& summary) {
  const std::string what = what_happened(summary);
  if (summary.where.empty()) return what;
  if (summary.termination == Termination::inner_failure) return summary.where;
  return fmt::format("{} {}", what, summary.where);
}

}  // namespace stockbridge
