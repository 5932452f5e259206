#include "stockbridge/damper/impedance.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>
#include <utility>

#include <Eigen/LU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/arclength.hpp"

namespace stockbridge::damper {

Method parse_method(std::string_view name) {
  if (name == "hb") return Method::harmonic_balance;
  if (name == "collocation") return Method::collocation;
  if (name == "time") return Method::time_integration;
  if (name == "shooting") return Method::shooting;
  throw InvalidParameter("method", fmt::format(" = '{}': expected hb, collocation, time or shooting", name));
}

std::string_view method_name(Method method) {
  switch (method) {
    case Method::harmonic_balance: return "hb";
    case Method::collocation: return "collocation";
    case Method::time_integration: return "time";
    case Method::shooting: return "shooting";
  }
  return "?";
}

HarmonicBalanceOptions SolverOptions::collocation_defaults() {
  HarmonicBalanceOptions options;
  options.collocation = true;
  options.harmonics = 40;  // its 2H + 1 points are its sampling: at H = 9 it is 2 % off
  return options;
}

void SolverOptions::validate() const {
  within_field("harmonic_balance", [&] { harmonic_balance.validate(); });
  within_field("collocation", [&] { collocation.validate(); });
  if (!collocation.collocation) throw InvalidParameter("collocation.collocation", " = false: expected true");
  within_field("time_integration", [&] { time_integration.validate(); });
  within_field("shooting", [&] { shooting.validate(); });
  require_positive("energy_tolerance", energy_tolerance, "");
}

bool same_amplitude(double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); }

bool Continuation::secant_applies(const Excitation& target) const {
  if (previous_unknowns.size() != unknowns.size()) return false;
  const double last_step = std::log(excitation.frequency_hz / previous_excitation.frequency_hz);
  const double step = std::log(target.frequency_hz / excitation.frequency_hz);
  const double v = excitation.velocity_amplitude();
  const bool one_velocity =
      same_amplitude(previous_excitation.velocity_amplitude(), v) && same_amplitude(target.velocity_amplitude(), v);
  return last_step > 0.0 && step > 0.0 && step <= 2.0 * last_step && one_velocity;
}

Eigen::VectorXd Continuation::predictor(const Excitation& target) const {
  Eigen::VectorXd scaled = unknowns * (target.displacement_amplitude / excitation.displacement_amplitude);
  if (!secant_applies(target)) return scaled;
  const Eigen::VectorXd previous_scaled =
      previous_unknowns * (target.displacement_amplitude / previous_excitation.displacement_amplitude);
  const double last_step = std::log(excitation.frequency_hz / previous_excitation.frequency_hz);
  const double step = std::log(target.frequency_hz / excitation.frequency_hz);
  return scaled + (step / last_step) * (scaled - previous_scaled);
}

void Continuation::advance(const Eigen::VectorXd& solution, const Excitation& at) {
  std::swap(previous_unknowns, unknowns);
  previous_excitation = excitation;
  unknowns = solution;
  excitation = at;
}

namespace {

/// Moves the path on to a converged solution.
void advance(Continuation& path, const ArmSolution& solution, const Excitation& excitation) {
  path.advance(solution.unknowns, excitation);
}

class HarmonicBalanceArmSolver final : public ArmSolver {
 public:
  HarmonicBalanceArmSolver(const Arm& arm, const HarmonicBalanceOptions& options)
      : model_(arm, options), workspace_(model_.make_workspace()) {}

  // A failed solve clears the path's memory (its cable state and Jacobian): the
  // smaller steps and arclength that follow start from the virgin cable at the last
  // converged unknowns. (Keeping the last converged state there was tried: one point
  // of SweepRobustness.TinyAmplitudeNearTheStickResonance then fails at 39.6 Hz.)
  ArmSolution solve(const Excitation& excitation, Continuation& path) override {
    ArmSolution solution = path.empty() ? model_.solve(excitation, model_.linear_guess(excitation), path.memory, workspace_)
                                        : model_.solve(excitation, predictor(excitation, path), path.memory, workspace_);
    if (!solution.summary.converged() && !path.empty()) {
      // The predictor may lie on another piece: retry from the virgin state and the linear guess.
      HarmonicBalanceMemory cold;
      ArmSolution retry = model_.solve(excitation, model_.linear_guess(excitation), cold, workspace_);
      if (retry.summary.converged()) {
        solution = std::move(retry);
        path.memory = std::move(cold);
      }
    }
    if (!solution.summary.converged() && model_.options().uses_half_wave()) {
      // No symmetric steady state found: look for one over whole periods, which need
      // not be symmetric. The path stays at its last symmetric solution.
      ArmSolution whole = solve_over_whole_periods(excitation, solution.unknowns, path);
      if (whole.summary.converged()) return whole;
    }
    if (solution.summary.converged()) advance(path, solution, excitation);
    return solution;
  }

  std::vector<ArmSolution> continue_to(const Excitation& target, Continuation& path) override {
    if (path.empty()) return {};
    BranchCrossings crossings =
        continue_along_branch(model_, target.velocity_amplitude(),
                              BranchPoint{path.unknowns, path.excitation.frequency_hz, path.memory},
                              target.frequency_hz, workspace_);
    if (!crossings.solutions.empty()) {
      advance(path, crossings.solutions.back(), target);
      path.memory = std::move(crossings.memory);
    }
    return std::move(crossings.solutions);
  }

 private:
  /// Where the path's secant does not apply (another amplitude: the span's polish),
  /// a Newton step from the last solution on the equations at `target` with the
  /// stored Jacobian: exact in the cable's loads, which depend on q alone.
  Eigen::VectorXd predictor(const Excitation& target, const Continuation& path) const {
    if (path.memory.force_jacobian.size() == 0 || path.secant_applies(target)) return path.predictor(target);
    const Eigen::MatrixXd j = model_.jacobian(target, path.memory.force_jacobian);
    const Eigen::VectorXd q = path.unknowns - Eigen::PartialPivLU<Eigen::MatrixXd>(j).solve(
                                                   model_.residual_change(path.excitation, target, path.unknowns));
    return q.allFinite() ? q : path.predictor(target);
  }

  /// The harmonic balance over whole periods (every harmonic and the mean) from the
  /// virgin cable: from `failed`, where the symmetric solve ended (often close, its
  /// line search stalled at a kink), else from the path's predictor. Its Jacobian's
  /// sign belongs to another system than the path's: no fold is read off it.
  ArmSolution solve_over_whole_periods(const Excitation& excitation, const Eigen::VectorXd& failed,
                                       const Continuation& path) {
    if (!whole_periods_) {
      HarmonicBalanceOptions options = model_.options();
      options.half_wave = false;
      whole_periods_.emplace(model_.arm(), options);
    }
    HarmonicBalance& model = whole_periods_->model;
    ArmSolution solution;
    for (const Eigen::VectorXd& start : {failed, path.empty() ? Eigen::VectorXd() : path.predictor(excitation)}) {
      if (start.size() != model_.unknown_count() || !start.allFinite()) continue;
      HarmonicBalanceMemory virgin;
      solution = model.solve(excitation, model_.whole_period_unknowns(start), virgin, whole_periods_->workspace);
      if (solution.summary.converged()) break;
    }
    solution.jacobian_sign = 0;
    return solution;
  }

  HarmonicBalance model_;
  HarmonicBalanceWorkspace workspace_;
  struct WholePeriods {
    WholePeriods(const Arm& arm, const HarmonicBalanceOptions& options)
        : model(arm, options), workspace(model.make_workspace()) {}
    HarmonicBalance model;
    HarmonicBalanceWorkspace workspace;
  };
  std::optional<WholePeriods> whole_periods_;  ///< built at the first fallback
};

/// Time integration and shooting always start from the all-stick linear steady state
/// of the excitation: where nothing slips it is already periodic, whereas a neighbour's
/// state would set off a free vibration that dry friction alone never damps (MODEL.md
/// section 6). The path's predictor is therefore not used.
template <class Solver, class Options>
class TimeDomainArmSolver final : public ArmSolver {
 public:
  TimeDomainArmSolver(const Arm& arm, const Options& options) : solver_(arm, options), stepper_(solver_.stepper()) {}
  ArmSolution solve(const Excitation& excitation, Continuation& path) override {
    ArmSolution solution = solver_.solve(excitation, nullptr, stepper_);
    if (solution.summary.converged()) advance(path, solution, excitation);
    return solution;
  }

 private:
  const Solver solver_;      // the model
  NewmarkStepper stepper_;   // this task's run state and workspace, reused from point to point
};

}  // namespace

std::unique_ptr<ArmSolver> make_arm_solver(const Arm& arm, const SolverOptions& options) {
  switch (options.method) {
    case Method::harmonic_balance: return std::make_unique<HarmonicBalanceArmSolver>(arm, options.harmonic_balance);
    case Method::collocation: return std::make_unique<HarmonicBalanceArmSolver>(arm, options.collocation);
    case Method::time_integration:
      return std::make_unique<TimeDomainArmSolver<TimeIntegration, TimeIntegrationOptions>>(arm, options.time_integration);
    case Method::shooting:
      return std::make_unique<TimeDomainArmSolver<Shooting, ShootingOptions>>(arm, options.shooting);
  }
  throw InvalidParameter("method", fmt::format(" = {}: unknown", static_cast<int>(options.method)));
}

namespace {

/// Why an arm's solution is not trusted, or nothing if it is.
std::optional<std::pair<Termination, std::string>> distrust(const ArmSolution& s, double energy_tolerance) {
  if (!s.summary.converged()) return std::pair{s.summary.termination, brief_report(s.summary)};
  if (!(s.summary.energy_error <= energy_tolerance)) {
    return std::pair{Termination::energy_mismatch,
                     fmt::format("energy balance off by {:.3g} of the apparent power (tolerance {:.3g})",
                                 s.summary.energy_error, energy_tolerance)};
  }
  return std::nullopt;
}

}  // namespace

ImpedancePoint combine(const Damper& damper, const Excitation& excitation,
                       const std::vector<const ArmSolution*>& arm_solutions, double energy_tolerance) {
  assert(arm_solutions.size() == damper.arms().size());
  ImpedancePoint point;
  point.frequency_hz = excitation.frequency_hz;
  point.velocity_amplitude = excitation.velocity_amplitude();
  point.displacement_amplitude = excitation.displacement_amplitude;
  point.termination = Termination::converged;
  point.arms.resize(arm_solutions.size());
  const double v = point.velocity_amplitude;
  std::complex<double> z(0.0, excitation.angular_frequency() * damper.clamp_mass());
  double dissipated = 0.0, residual = 0.0, energy = 0.0, curvature = 0.0;
  std::vector<ArmFigures> figures(arm_solutions.size());
  for (std::size_t k = 0; k < arm_solutions.size(); ++k) {
    const ArmSolution& s = *arm_solutions[k];
    point.newton_iterations = std::max(point.newton_iterations, s.summary.newton_iterations);
    point.periods = std::max(point.periods, s.summary.periods);
    point.seconds += s.summary.seconds;
    if (const auto why = distrust(s, energy_tolerance)) {
      if (point.converged()) {  // the first failure says why
        point.termination = why->first;
        point.failure = fmt::format("{}: {}", damper.arm_label(k), why->second);
      }
      continue;
    }
    residual = std::max(residual, s.summary.residual);
    energy = std::max(energy, s.summary.energy_error);
    std::string note;
    if (s.branches > 1) {
      point.non_unique = true;
      note = fmt::format("{}: {} steady states at this frequency (the response curve folds back)", damper.arm_label(k),
                         s.branches);
    } else if (!s.note.empty()) {
      note = fmt::format("{}: {}", damper.arm_label(k), s.note);
    }
    if (!note.empty()) point.note += (point.note.empty() ? "" : "; ") + note;
    figures[k] = arm_figures(s.period, damper.arms()[k], excitation);
    z += figures[k].impedance;
    curvature = std::max(curvature, figures[k].clamp_curvature_amplitude);
    dissipated += s.period.dissipated;
  }
  if (!point.converged()) {  // notes speak of solutions, and there is none
    point.note.clear();
    point.non_unique = false;
  } else {
    point.impedance = z;
    point.arms = std::move(figures);
    point.messenger_curvature_max = curvature;
    point.power = 0.5 * v * v * z.real();
    point.dissipated_power = dissipated / excitation.period();
    point.residual = residual;
    point.energy_error = energy;
  }
  return point;
}

Eigen::RowVectorXd shaker_force(const Damper& damper, const Excitation& excitation,
                                const std::vector<const ArmSolution*>& arm_solutions) {
  const Eigen::Index n = arm_solutions.front()->period.loads.cols();
  for (const ArmSolution* s : arm_solutions) {
    if (s->period.loads.cols() != n) return Eigen::RowVectorXd();
  }
  const double w = excitation.angular_frequency();
  Eigen::RowVectorXd force(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double t = excitation.period() * static_cast<double>(j) / static_cast<double>(n);
    force(j) = -damper.clamp_mass() * w * w * excitation.displacement_amplitude * std::sin(w * t);
  }
  for (const ArmSolution* s : arm_solutions) force -= s->period.loads.row(0);
  return force;
}

}  // namespace stockbridge::damper
