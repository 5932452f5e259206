#include "stockbridge/span/end_fixed_point.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/LU>
#include <fmt/format.h>

#include "../numerics/nonlinear_system.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

void FixedPointOptions::validate() const {
  require_positive("tolerance", tolerance, "");
  require_in_range("max_sweeps", max_sweeps, 1, 100000);
  require_positive("velocity_floor", velocity_floor, "m/s");
}

namespace {

/// The end of one antinode amplitude, its responses counted.
class EndProblem {
 public:
  EndProblem(const EndChain& chain, const ClampImpedance& impedance, const ClampImpedanceSlope& slope, double antinode,
             const FixedPointOptions& options)
      : chain_(chain), wave_(chain.wave()), impedance_(impedance), slope_(slope), antinode_(antinode), options_(options) {}

  /// The impedances at velocities v; none (and `unknown_` says where) if one is not known.
  std::optional<std::vector<std::complex<double>>> impedances(const std::vector<double>& v) {
    std::vector<std::complex<double>> z;
    for (std::size_t j = 0; j < v.size(); ++j) {
      const auto zj = impedance_(j, v[j]);
      if (!zj) {
        unknown_ = fmt::format("damper {}: its impedance is not known near {:.3g} m/s", j + 1, v[j]);
        return std::nullopt;
      }
      z.push_back(*zj);
    }
    return z;
  }
  EndResponse response(const std::vector<std::complex<double>>& z) {
    ++evaluations_;
    return chain_.response(z, antinode_);
  }
  /// log of damper j's velocity in a response (held at the floor at a node).
  double log_velocity(const EndResponse& r, std::size_t j) const {
    return std::log(std::max(wave_.angular_frequency * std::abs(r.damper_displacement[j]), options_.velocity_floor));
  }

  /// Damper j's velocity consistent with the others' (the scalar root in log v); none
  /// if an impedance is not known on the way or no sign change is found.
  std::optional<double> consistent_velocity(std::vector<double> v, std::size_t j);
  /// Every velocity at once (Powell's hybrid method), from v.
  numerics::NonlinearSystemResult solve_system(const std::vector<double>& v);
  /// Every velocity at once by Newton's method from v; into v where max |g| <= the
  /// tolerance (true), else false (the caller goes on from its own start).
  bool solve_newton(std::vector<double>& v, double& residual);

  int evaluations() const { return evaluations_; }
  const std::string& unknown() const { return unknown_; }

 private:
  /// Z and dZ/du of damper j at velocity v: the given slope, or central differences.
  std::optional<TableImpedance> impedance_with_slope(std::size_t j, double v);

  const EndChain& chain_;
  const StringWave& wave_;
  const ClampImpedance& impedance_;
  const ClampImpedanceSlope& slope_;
  double antinode_;
  const FixedPointOptions& options_;
  int evaluations_ = 0;
  std::string unknown_;  ///< where an impedance was not known
};

std::optional<double> EndProblem::consistent_velocity(std::vector<double> v, std::size_t j) {
  const auto g = [&](double u) -> std::optional<double> {
    v[j] = std::exp(u);
    const auto z = impedances(v);
    if (!z) return std::nullopt;
    return log_velocity(response(*z), j) - u;
  };
  double a = std::log(std::max(v[j], options_.velocity_floor));
  auto ga = g(a);
  if (!ga) return std::nullopt;
  if (*ga == 0.0) return std::exp(a);
  // Bracket outward by doubling steps in log v (g falls through zero as v grows).
  double step = *ga > 0.0 ? 0.1 : -0.1, b = a;
  std::optional<double> gb;
  for (int k = 0; k < 80; ++k, step *= 2.0) {
    b = a + step;
    gb = g(b);
    if (!gb) return std::nullopt;
    if ((*gb > 0.0) != (*ga > 0.0)) break;
    a = b;
    ga = gb;
  }
  if ((*gb > 0.0) == (*ga > 0.0)) return std::nullopt;
  // Regula falsi, Illinois variant: halve the weight of an end kept twice.
  int kept = 0;
  for (int k = 0; k < 200 && std::abs(b - a) > 1e-14; ++k) {
    const double c = b - *gb * (b - a) / (*gb - *ga);
    const auto gc = g(c);
    if (!gc) return std::nullopt;
    if (*gc == 0.0) return std::exp(c);
    if ((*gc > 0.0) == (*gb > 0.0)) {
      if (kept == 1) *ga *= 0.5;
      kept = 1;
    } else {
      a = b;
      ga = gb;
      kept = 0;
    }
    b = c;
    gb = gc;
  }
  return std::exp(b);
}

numerics::NonlinearSystemResult EndProblem::solve_system(const std::vector<double>& start) {
  const std::size_t n = start.size();
  const auto velocities = [n](const Eigen::VectorXd& u) {
    std::vector<double> v(n);
    for (std::size_t j = 0; j < n; ++j) v[j] = std::exp(u[static_cast<Eigen::Index>(j)]);
    return v;
  };
  const numerics::Residual residual = [&](const Eigen::VectorXd& u, Eigen::VectorXd& g) {
    const auto z = impedances(velocities(u));
    if (!z) return false;
    const EndResponse r = response(*z);
    g.resize(u.size());
    for (std::size_t j = 0; j < n; ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      g[i] = log_velocity(r, j) - u[i];
    }
    return true;
  };
  // dZ_m/du_m by central differences of the impedance (a table's cubic: exact but
  // for round-off), then the response's exact tangent along each.
  const numerics::ResidualJacobian jacobian = [&](const Eigen::VectorXd& u, Eigen::MatrixXd& jac) {
    constexpr double kStep = 1e-4;
    const std::vector<double> v = velocities(u);
    const auto z = impedances(v);
    if (!z) return false;
    const EndResponse r = response(*z);
    jac = -Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t m = 0; m < n; ++m) {
      const auto hi = impedance_(m, v[m] * std::exp(kStep)), lo = impedance_(m, v[m] * std::exp(-kStep));
      if (!hi || !lo) return false;
      std::vector<std::complex<double>> direction(n, 0.0);
      direction[m] = (*hi - *lo) / (2.0 * kStep);
      const EndResponseTangent t = chain_.tangent(*z, direction, antinode_);
      for (std::size_t j = 0; j < n; ++j) {
        // A damper held at the velocity floor (near a node) does not move with the others.
        const bool floored = wave_.angular_frequency * std::abs(r.damper_displacement[j]) <= options_.velocity_floor;
        if (!floored) jac(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(m)) += t.log_displacement[j];
      }
    }
    return true;
  };
  Eigen::VectorXd u(static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j) u[static_cast<Eigen::Index>(j)] = std::log(std::max(start[j], options_.velocity_floor));
  numerics::NonlinearSystemOptions system;
  system.tolerance = options_.tolerance;
  system.max_evaluations = options_.max_sweeps;
  return numerics::solve_nonlinear_system(residual, jacobian, u, system);
}

std::optional<TableImpedance> EndProblem::impedance_with_slope(std::size_t j, double v) {
  if (slope_) return slope_(j, v);
  constexpr double kStep = 1e-4;
  const auto z = impedance_(j, v), hi = impedance_(j, v * std::exp(kStep)), lo = impedance_(j, v * std::exp(-kStep));
  if (!z || !hi || !lo) return std::nullopt;
  return TableImpedance{*z, (*hi - *lo) / (2.0 * kStep)};
}

bool EndProblem::solve_newton(std::vector<double>& v, double& residual) {
  constexpr int kMaxSize = 8;   // larger ends go to the general solvers
  constexpr double kMaxStep = 2.0;  // in ln v: a factor e^2 a step at most
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSize, 1>;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSize, kMaxSize>;
  const auto n = static_cast<Eigen::Index>(v.size());
  if (n == 0 || n > kMaxSize) return false;
  // A point of the iteration: u = ln v, its impedances, slopes, displacements and g.
  struct Point {
    Vector u, g;
    std::array<std::complex<double>, kMaxSize> z, slope, y;
    double norm = 0.0;
  };
  const auto evaluate = [&](Point& p) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto zj = impedance_with_slope(static_cast<std::size_t>(j), std::exp(p.u[j]));
      if (!zj) return false;
      p.z[static_cast<std::size_t>(j)] = zj->z;
      p.slope[static_cast<std::size_t>(j)] = zj->slope;
    }
    ++evaluations_;
    chain_.displacements(p.z.data(), antinode_, p.y.data());
    p.g.resize(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      p.g[j] = std::log(std::max(wave_.angular_frequency * std::abs(p.y[static_cast<std::size_t>(j)]), options_.velocity_floor)) - p.u[j];
    }
    p.norm = p.g.cwiseAbs().maxCoeff();
    return std::isfinite(p.norm);
  };
  Point at, trial;
  at.u.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) at.u[j] = std::log(std::max(v[static_cast<std::size_t>(j)], options_.velocity_floor));
  if (!evaluate(at)) return false;
  std::array<double, kMaxSize * kMaxSize> jacobian{};
  for (int evaluations = 1; at.norm > options_.tolerance; ) {
    chain_.log_displacement_jacobian(at.z.data(), at.slope.data(), jacobian.data());
    Matrix dg = -Matrix::Identity(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      // A damper held at the velocity floor (near a node) does not move with the others.
      if (wave_.angular_frequency * std::abs(at.y[static_cast<std::size_t>(j)]) <= options_.velocity_floor) continue;
      for (Eigen::Index m = 0; m < n; ++m) dg(j, m) += jacobian[static_cast<std::size_t>(j * n + m)];
    }
    const Eigen::PartialPivLU<Matrix> lu(dg);
    Vector step = lu.solve(-at.g);
    if (!step.allFinite()) return false;
    if (const double longest = step.cwiseAbs().maxCoeff(); longest > kMaxStep) step *= kMaxStep / longest;
    // The full step, or halved until max |g| falls.
    bool accepted = false;
    for (int halving = 0; halving < 8 && !accepted; ++halving, step *= 0.5) {
      if (++evaluations > options_.max_sweeps) return false;
      trial.u = at.u + step;
      accepted = evaluate(trial) && trial.norm < at.norm;
    }
    if (!accepted) return false;
    std::swap(at, trial);
  }
  for (Eigen::Index j = 0; j < n; ++j) v[static_cast<std::size_t>(j)] = std::exp(at.u[j]);
  residual = at.norm;
  return true;
}

}  // namespace

EndSolution solve_end(const StringWave& wave, const std::vector<double>& positions, const ClampImpedance& impedance,
                      double antinode, const FixedPointOptions& options, std::vector<double> start,
                      const EndAttachments& attachments) {
  return solve_end(EndChain(wave, positions, attachments), impedance, {}, antinode, options, std::move(start));
}

EndSolution solve_end(const EndChain& chain, const ClampImpedance& impedance, const ClampImpedanceSlope& slope,
                      double antinode, const FixedPointOptions& options, std::vector<double> start) {
  const StringWave& wave = chain.wave();
  EndProblem problem(chain, impedance, slope, antinode, options);
  EndSolution out;
  std::vector<double>& v = out.velocities;
  // The undamped string's velocities, w Y |sin(k a_j)|, where no start is given.
  if (start.size() != chain.dampers()) {
    start.clear();
    for (const double a : chain.positions()) {
      start.push_back(std::max(wave.angular_frequency * antinode * std::abs(std::sin(wave.wavenumber * a)), options.velocity_floor));
    }
  }
  v = std::move(start);
  SolverSummary& summary = out.summary;
  const auto fail = [&](Termination termination, std::string where) {
    summary.termination = termination;
    summary.where = std::move(where);
    summary.evaluations = problem.evaluations();
    return out;
  };
  // Newton's method, then Powell's (several dampers).
  const auto solve_from = [&](std::vector<double> from) {
    if (problem.solve_newton(from, summary.residual)) return std::optional(std::move(from));
    if (from.size() < 2) return std::optional<std::vector<double>>();
    const numerics::NonlinearSystemResult system = problem.solve_system(from);
    if (!system.summary.converged()) return std::optional<std::vector<double>>();
    for (std::size_t j = 0; j < from.size(); ++j) from[j] = std::exp(system.x[static_cast<Eigen::Index>(j)]);
    summary.residual = system.summary.residual;
    return std::optional(std::move(from));
  };
  std::optional<std::vector<double>> found = solve_from(v);
  bool solved = found.has_value();
  if (found) v = std::move(*found);
  // One damper, or several one at a time (Gauss-Seidel sweeps) where the system solve failed.
  double change = 0.0;
  for (int sweep = 1; !solved && sweep <= options.max_sweeps; ++sweep) {
    change = 0.0;
    for (std::size_t j = 0; j < v.size(); ++j) {
      const auto vj = problem.consistent_velocity(v, j);
      if (!vj) {
        if (!problem.unknown().empty()) return fail(Termination::inner_failure, problem.unknown());
        return fail(Termination::no_root, fmt::format("damper {}: no velocity reproduces itself", j + 1));
      }
      change = std::max(change, std::abs(*vj - v[j]) / std::max(*vj, options.velocity_floor));
      v[j] = *vj;
    }
    solved = change <= options.tolerance || v.size() <= 1;
    summary.residual = change;
  }
  if (!solved) {
    return fail(Termination::max_iterations,
                fmt::format("the dampers' velocities still changed by {:.3g} (relative) after {} sweeps", change,
                            options.max_sweeps));
  }
  const auto z = problem.impedances(v);
  if (!z) return fail(Termination::inner_failure, problem.unknown());
  out.response = problem.response(*z);
  out.impedances = *z;
  summary.termination = Termination::converged;
  summary.evaluations = problem.evaluations();
  return out;
}

}  // namespace stockbridge::span
