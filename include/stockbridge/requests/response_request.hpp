#pragma once
// The request layer for one steady period of a damper (`stockbridge response`,
// Python's response): what a user asks for (a frequency, a velocity or a
// displacement amplitude, solver settings), the damper solved there, its period
// as the rows of the response table and its point as one summary row.

#include <optional>
#include <vector>

#include "stockbridge/core/warning.hpp"
#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/requests/solver_settings.hpp"

namespace stockbridge::requests {

struct ResponseRequest {
  double frequency = 0.0;               ///< Hz
  std::optional<double> velocity;       ///< V, m/s ...
  std::optional<double> displacement;   ///< ... or X, m: exactly one
  SolverSettings solver;
};

/// What a response request computed. The period is written even where the point
/// did not converge (the last iterate, marked), so that it can be inspected.
struct ResponseResult {
  damper::Excitation excitation;
  damper::DamperSteadyState state;
  std::vector<double> time;           ///< s, the samples of the longest arm period
  std::vector<double> shaker_force;   ///< N, NaN unless every arm has a period of those samples
  std::vector<Warning> warnings;      ///< the frequency and amplitude outside their typical ranges
};

/// InvalidParameter naming "frequency", "velocity", "displacement" or a solver
/// setting, before any file is read.
void validate(const ResponseRequest& request);

/// Validates the request and solves the damper there (damper::solve_steady_state).
ResponseResult run_response(const damper::Damper& damper, const ResponseRequest& request);

/// One sample of the period.
struct ResponseSample {
  const ResponseResult* result = nullptr;
  std::size_t j = 0;
};
std::vector<ResponseSample> response_samples(const ResponseResult& result);

/// The response CSV's quantities (Python's response arrays, the per-arm ones stacked
/// arms x samples): time_s, clamp_displacement_m, clamp_velocity_m_s,
/// shaker_force_n, per arm <arm>_x_m, <arm>_phi_rad, <arm>_force_n,
/// <arm>_clamp_moment_n_m, <arm>_tip_moment_n_m, <arm>_clamp_curvature_per_m,
/// <arm>_clamp_section_moment_n_m (NaN for an arm without a period of that many
/// samples), then converged.
Table<ResponseSample> response_table(const damper::Damper& damper);

/// The --json summary: the point (point_summary_table) and the warnings.
io::JsonObject response_summary(const damper::Damper& damper, const ResponseResult& result);

}  // namespace stockbridge::requests
