#pragma once
// The nonlinear dampers of one span end at a given antinode amplitude Y: each
// damper's impedance depends on its own clamp velocity amplitude v_j = w |Y_j|,
// which depends on every damper's impedance (travelling_wave.hpp). A fixed point
// in v, the root in u = log v of g_j(u) = log(w |Y_j(Z(v))|) - u_j:
// * first Newton's method on all velocities at once with the exact Jacobian
//   dg/du = d log|Y| / dZ . diag(dZ_j / du_j) - I (the chain's tangent, and dZ/du
//   the table interpolant's own slope, or central differences of the impedance
//   where no slope is given), the steps halved until max |g| falls;
// * where that does not converge, Powell's hybrid method on the same system
//   (several dampers), and then one damper at a time (Gauss-Seidel sweeps), each
//   velocity bracketed outward from the last value and closed by regula falsi
//   (Illinois): g > 0 for small v (Z tends to the all-stick value, Y_j stays
//   finite) and g < 0 for large v, so a root exists.

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/span/impedance_table.hpp"
#include "stockbridge/span/travelling_wave.hpp"

namespace stockbridge::span {

/// Z (N s/m) of the end's damper j at clamp velocity amplitude v (m/s); none where
/// it is not known (a table without converged nodes there).
using ClampImpedance = std::function<std::optional<std::complex<double>>(std::size_t damper, double velocity)>;
/// The same with its slope dZ/d(ln v) (a table's interpolant: TableImpedance).
using ClampImpedanceSlope = std::function<std::optional<TableImpedance>(std::size_t damper, double velocity)>;

struct FixedPointOptions {
  /// On every |g_j| (several dampers), or the relative change of every velocity
  /// between Gauss-Seidel sweeps.
  double tolerance = 1e-10;
  int max_sweeps = 200;  ///< Gauss-Seidel sweeps; the system solve evaluates g at most this often
  double velocity_floor = 1e-9;  ///< m/s: below it a damper is taken as still

  void validate() const;
};

struct EndSolution {
  EndResponse response;                      ///< at the fixed point
  std::vector<double> velocities;            ///< v_j, m/s
  std::vector<std::complex<double>> impedances;  ///< Z_j(v_j), N s/m
  /// converged; inner_failure (an impedance not known on the way: `where` says
  /// which damper and velocity); no_root (one damper: no sign change of g found);
  /// max_iterations (the sweeps still moved the velocities: residual says by how
  /// much). evaluations: of the end's response.
  SolverSummary summary;

  bool converged() const { return summary.converged(); }
};

/// The end's dampers at `positions` (m from the end, ascending) at antinode amplitude
/// `antinode` (m), with the end's masses in the chain (`attachments`). `start`:
/// velocities to start from (empty: those of the undamped string, w Y |sin(k a_j)|).
EndSolution solve_end(const StringWave& wave, const std::vector<double>& positions, const ClampImpedance& impedance,
                      double antinode, const FixedPointOptions& options, std::vector<double> start = {},
                      const EndAttachments& attachments = {});
/// The same on a chain made once (the balance's many amplitudes), with the
/// impedances' slopes where known (empty: central differences of `impedance`).
EndSolution solve_end(const EndChain& chain, const ClampImpedance& impedance, const ClampImpedanceSlope& slope,
                      double antinode, const FixedPointOptions& options, std::vector<double> start = {});

}  // namespace stockbridge::span
