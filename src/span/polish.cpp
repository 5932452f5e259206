#include "polish.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/LU>
#include <fmt/format.h>


namespace stockbridge::span {

namespace {

/// How far (in polish tolerances) the directly solved impedances' own scatter can
/// move the balance's velocity: a jump of h that small is round-off, not a jump.
constexpr double kPolishScatter = 10.0;
/// The step in log v of the tables' slope dZ/du where a frequency starts from them.
constexpr double kTableSlopeStep = 0.05;
/// Newton steps on dh/du before the hybrid method: the Jacobian is exact but for the
/// secant dZ/du, and each frequency starts close to its solution.
constexpr int kPolishNewtonSteps = 6;
/// A trial this close (in log v) to a damper's last direct solve at the frequency
/// continues from that solve rather than from the frequency's first ...
constexpr double kNearTrial = 1e-3;
/// ... where the polish's tolerance is at least this: two starts of one damper's
/// harmonic balance agree to its own tolerance (Z within about 1e-8 at the default
/// 1e-7), so a tighter polish needs the one start that makes Z a function of v to
/// the last bit.
constexpr double kNearTrialTolerance = 1e-7;

}  // namespace

Polish::Polish(const Span& span, const BalanceOptions& options) : options_(options) {
  for (const SpanDamper& d : span.dampers()) {
    if (d.damper) {
      trackers_.emplace_back(std::in_place, *d.damper, options.table.solver);
    } else {
      trackers_.emplace_back();  // a measured sheet: its table is all there is
    }
  }
}

void Polish::forget() {
  slopes_.clear();
  history_.clear();
}

int Polish::direct_solves() const {
  int n = 0;
  for (const std::optional<damper::DamperTracker>& t : trackers_) n += t ? t->solves() : 0;
  return n;
}

std::vector<Polish::Unknown> Polish::unknowns_of(const FrequencyBalance& balance) const {
  const std::vector<EndLayout>& ends = balance.layouts();
  std::vector<Unknown> unknowns;
  const bool mirrored = ends.size() == 2 && ends[1].mirrors(ends[0]);
  for (std::size_t e = 0; e < ends.size(); ++e) {
    for (std::size_t j = 0; j < ends[e].damper.size(); ++j) {
      if (mirrored && e == 1) {
        unknowns[j].slots.emplace_back(e, j);
      } else {
        unknowns.push_back({ends[e].damper[j], {{e, j}}});
      }
    }
  }
  return unknowns;
}

std::optional<Eigen::VectorXd> Polish::start(FrequencyBalance& balance, std::optional<double> from_tables,
                                             SolverSummary& failure) {
  const auto n = static_cast<Eigen::Index>(unknowns_.size());
  Eigen::VectorXd u(n);
  if (!from_tables) {
    const Solution& b = history_.back();
    if (history_.size() < 2) return b.u;
    const Solution& a = history_[history_.size() - 2];
    const double t = (std::log(balance.wave().angular_frequency) - b.log_f) / (b.log_f - a.log_f);
    return Eigen::VectorXd(b.u + t * (b.u - a.u));
  }
  const EndsAtAmplitude first = balance.dampers(*from_tables);
  if (!first.summary.converged()) {
    failure = first.summary;
    return std::nullopt;
  }
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    const auto [e, j] = unknowns_[k].slots[0];
    u[static_cast<Eigen::Index>(k)] = std::log(first.ends[e].velocities[j]);
  }
  return u;
}

void Polish::start_slopes(const FrequencyBalance& balance, const Eigen::VectorXd& u) {
  if (slopes_.size() == unknowns_.size()) return;  // the last frequency's
  slopes_.assign(unknowns_.size(), 0.0);
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    const double v = std::exp(u[static_cast<Eigen::Index>(k)]);
    const auto hi = balance.table_impedance(unknowns_[k].damper, v * std::exp(kTableSlopeStep));
    const auto lo = balance.table_impedance(unknowns_[k].damper, v * std::exp(-kTableSlopeStep));
    if (hi && lo) slopes_[k] = (*hi - *lo) / (2.0 * kTableSlopeStep);
  }
}

damper::ImpedancePoint Polish::solve_directly(const FrequencyBalance& balance, const Unknown& unknown,
                                              const damper::Excitation& excitation) {
  if (!trackers_[unknown.damper]) return from_sheet(balance, unknown, excitation);
  damper::DamperTracker& tracker = *trackers_[unknown.damper];
  std::optional<damper::DamperTracker::Checkpoint>& anchor = anchors_[unknown.damper];
  const double log_v = std::log(excitation.velocity_amplitude());
  double& last = last_direct_[unknown.damper];
  const bool near = options_.polish_tolerance >= kNearTrialTolerance && std::abs(log_v - last) <= kNearTrial;
  if (anchor && !near) tracker.restore(*anchor);
  damper::ImpedancePoint direct = tracker.solve(excitation);
  last = direct.converged() ? log_v : std::numeric_limits<double>::quiet_NaN();
  if (!direct.converged() && !anchor) {
    // Where the path from the last frequency fails (the arm's stick resonance passed
    // between them, say), from a cold start.
    tracker.forget();
    direct = tracker.solve(excitation);
  }
  if (direct.converged() && !anchor) anchor = tracker.checkpoint();
  return direct;
}

damper::ImpedancePoint Polish::from_sheet(const FrequencyBalance& balance, const Unknown& unknown,
                                           const damper::Excitation& excitation) {
  damper::ImpedancePoint p;
  p.frequency_hz = excitation.frequency_hz;
  p.velocity_amplitude = excitation.velocity_amplitude();
  p.displacement_amplitude = excitation.displacement_amplitude;
  const std::optional<std::complex<double>> z = balance.table_impedance(unknown.damper, p.velocity_amplitude);
  if (!z) {
    p.termination = Termination::inner_failure;
    p.failure = "its measured sheet does not give Z at this frequency";
    return p;
  }
  p.termination = Termination::converged;
  p.impedance = *z;
  p.power = 0.5 * p.velocity_amplitude * p.velocity_amplitude * z->real();
  return p;
}

std::optional<Polish::Trial> Polish::evaluate(FrequencyBalance& balance, const Eigen::VectorXd& u,
                                              SolverSummary& failure) {
  Trial t;
  t.u = u;
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    const Unknown& unknown = unknowns_[k];
    const double v = std::exp(u[static_cast<Eigen::Index>(k)]);
    if (!(v > 0.0 && std::isfinite(v))) {  // a trial the solver stepped out to: no damper moves so
      failure.termination = Termination::inner_failure;
      failure.where = fmt::format("end {}, damper {}: the trial clamp velocity {:.4g} m/s is not a finite velocity",
                                  unknown.slots[0].first + 1, unknown.slots[0].second + 1, v);
      return std::nullopt;
    }
    damper::ImpedancePoint direct =
        solve_directly(balance, unknown, damper::Excitation::from_velocity(balance.frequency(), v));
    if (!direct.converged()) {
      failure.termination = Termination::inner_failure;
      failure.where = fmt::format("end {}, damper {} solved directly at {:.4g} m/s: {}", unknown.slots[0].first + 1,
                                  unknown.slots[0].second + 1, v, direct.failure);
      return std::nullopt;
    }
    for (const auto& [e, j] : unknown.slots) balance.fix(e, j, direct);
    t.direct.push_back(std::move(direct));
  }
  t.absorbed_per_square = *balance.absorbed_per_square();
  const StableRoot y = balance.balanced_amplitude();
  if (!y.converged()) {
    failure = y.summary;
    return std::nullopt;
  }
  t.amplitude = y.amplitude;
  t.h = Eigen::VectorXd::Zero(u.size());
  if (y.amplitude <= 0.0) return t;  // with these impedances nothing builds up
  const EndsAtAmplitude at = balance.dampers(y.amplitude);
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    const auto [e, j] = unknowns_[k].slots[0];
    const auto i = static_cast<Eigen::Index>(k);
    t.h[i] = std::log(at.ends[e].velocities[j]) - u[i];
  }
  return t;
}

Eigen::MatrixXd Polish::jacobian(FrequencyBalance& balance, const Trial& trial) const {
  const auto n = static_cast<Eigen::Index>(unknowns_.size());
  const std::vector<EndLayout>& ends = balance.layouts();
  const double y = trial.amplitude;
  // The root of N(Y) = P_w - P_s - P_d(1) Y^2 moves by dY = Y^2 dP_d(1) / N'(Y).
  const double slope = balance.net_power_slope(y) - 2.0 * trial.absorbed_per_square * y;
  std::vector<std::vector<std::complex<double>>> z(ends.size());
  for (std::size_t e = 0; e < ends.size(); ++e) z[e].resize(ends[e].positions.size());
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    for (const auto& [e, j] : unknowns_[k].slots) z[e][j] = trial.direct[k].impedance;
  }
  Eigen::MatrixXd jac = -Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index m = 0; m < n; ++m) {
    std::vector<EndResponseTangent> tangents;
    double d_absorbed = 0.0;
    for (std::size_t e = 0; e < ends.size(); ++e) {
      std::vector<std::complex<double>> direction(ends[e].positions.size(), 0.0);
      for (const auto& [se, sj] : unknowns_[static_cast<std::size_t>(m)].slots) {
        if (se == e) direction[sj] = slopes_[static_cast<std::size_t>(m)];
      }
      tangents.push_back(balance.end_tangent(e, z[e], direction));
      d_absorbed += tangents.back().absorbed_power;
    }
    const double d_log_y = y * d_absorbed / slope;
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto [e, j] = unknowns_[static_cast<std::size_t>(k)].slots[0];
      jac(k, m) += d_log_y + tangents[e].log_displacement[j];
    }
  }
  return jac;
}

void Polish::update_slopes(const Trial& trial) {
  if (last_solved_) {
    for (std::size_t k = 0; k < unknowns_.size(); ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      const double du = trial.u[i] - last_solved_->u[i];
      if (std::abs(du) > 1e-9) slopes_[k] = (trial.direct[k].impedance - last_solved_->direct[k].impedance) / du;
    }
  }
  last_solved_ = trial;
}

Polish::Search Polish::search(FrequencyBalance& balance, const Eigen::VectorXd& start) {
  anchors_.assign(trackers_.size(), std::nullopt);
  last_direct_.assign(trackers_.size(), std::numeric_limits<double>::quiet_NaN());
  last_solved_.reset();
  Search out;
  const numerics::Residual residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& h) {
    std::optional<Trial> trial = evaluate(balance, x, out.failure);
    if (!trial) return false;
    if (trial->amplitude <= 0.0) {
      out.still = trial->amplitude;
      h = Eigen::VectorXd::Zero(x.size());  // stops the solve: converged
      return true;
    }
    update_slopes(*trial);
    h = trial->h;
    out.trials.push_back(std::move(*trial));
    return true;
  };
  const numerics::ResidualJacobian jacobian_at = [&](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    const Trial* trial = out.trial_at(x);
    if (!trial) return false;
    hold(balance, *trial);  // the balance's slope with this trial's impedances, not the last trial's
    jac = jacobian(balance, *trial);
    return true;
  };
  numerics::NonlinearSystemOptions system;
  system.tolerance = options_.polish_tolerance;
  system.max_evaluations = options_.max_polish_evaluations;
  system.newton_steps = kPolishNewtonSteps;
  out.solved = numerics::solve_fixed_point(residual, jacobian_at, start, system, kPolishScatter * options_.polish_tolerance);
  return out;
}

const Polish::Trial* Polish::Search::trial_at(const Eigen::VectorXd& x) const {
  const auto found = std::find_if(trials.rbegin(), trials.rend(), [&](const Trial& t) { return t.u == x; });
  return found == trials.rend() ? nullptr : &*found;
}

std::string Polish::failure_where(const Search& search) const {
  if (search.solved.summary.termination == Termination::inner_failure) {
    return search.failure.termination == Termination::inner_failure ? search.failure.where : brief_report(search.failure);
  }
  std::string where = fmt::format("in the dampers' clamp velocities with directly solved impedances (tolerance {:.3g})",
                                  options_.polish_tolerance);
  if (search.solved.jump_at.size() > 0) {
    Eigen::Index worst = 0;
    const double jump = search.solved.jump_residual.cwiseAbs().maxCoeff(&worst);
    const Unknown& k = unknowns_[static_cast<std::size_t>(worst)];
    where += fmt::format(": as end {}, damper {}'s trial passes {:.4g} m/s its balance velocity jumps by {:.3g} % (no "
                         "self-consistent state there)",
                         k.slots[0].first + 1, k.slots[0].second + 1, std::exp(search.solved.jump_at[worst]),
                         100.0 * std::expm1(jump));
  }
  return where;
}

void Polish::hold(FrequencyBalance& balance, const Trial& trial) const {
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    for (const auto& [e, j] : unknowns_[k].slots) balance.fix(e, j, trial.direct[k]);
  }
}

double Polish::accept(FrequencyBalance& balance, const Trial& solution, bool continued) {
  hold(balance, solution);
  const double det = jacobian(balance, solution).partialPivLu().determinant();
  const int sign = det > 0.0 ? 1 : det < 0.0 ? -1 : 0;
  passed_fold_ = continued && sign != 0 && history_.back().jacobian_sign != 0 && sign != history_.back().jacobian_sign;
  history_.push_back({std::log(balance.wave().angular_frequency), solution.u, sign});
  if (history_.size() > 2) history_.erase(history_.begin());  // the next frequency needs the last two
  return solution.amplitude;
}

StableRoot Polish::run(FrequencyBalance& balance, std::optional<double> from_tables) {
  StableRoot out;
  if (from_tables && *from_tables <= 0.0) {  // nothing builds up: the dampers stand still
    out.summary.termination = Termination::converged;
    return out;
  }
  unknowns_ = unknowns_of(balance);
  if (!from_tables && (history_.empty() || history_.back().u.size() != static_cast<Eigen::Index>(unknowns_.size()))) {
    out.summary.termination = Termination::inner_failure;
    out.summary.where = "no earlier frequency to continue from";
    return out;
  }
  if (from_tables) slopes_.clear();
  const std::optional<Eigen::VectorXd> u = start(balance, from_tables, out.summary);
  if (!u) return out;
  start_slopes(balance, *u);
  const Search found = search(balance, *u);
  out.summary = found.solved.summary;
  out.summary.where.clear();
  if (found.still) {
    out.summary.termination = Termination::converged;  // with the direct impedances nothing builds up
  } else if (!found.solved.summary.converged()) {
    out.summary.where = failure_where(found);
  } else {
    out.amplitude = accept(balance, *found.trial_at(found.solved.x), !from_tables);
  }
  return out;
}

}  // namespace stockbridge::span
