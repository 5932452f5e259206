#pragma once
// How an NLopt run that returned (did not throw) ended, as a Termination: the one
// mapping for every NLopt optimiser of the library (the identification's, the
// design polish's). Private to the library.

#include <nlopt.hpp>

#include "stockbridge/numerics/solver_summary.hpp"

namespace stockbridge::numerics {

inline Termination nlopt_termination(nlopt::result result) {
  switch (result) {
    case nlopt::MAXEVAL_REACHED:
    case nlopt::MAXTIME_REACHED: return Termination::max_iterations;
    case nlopt::SUCCESS:
    case nlopt::STOPVAL_REACHED:
    case nlopt::FTOL_REACHED:
    case nlopt::XTOL_REACHED: return Termination::converged;
    default: return Termination::inner_failure;
  }
}

}  // namespace stockbridge::numerics
