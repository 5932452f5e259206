#include "stockbridge/damper/impedance.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/shooting.hpp"
#include "stockbridge/damper/time_integration.hpp"

namespace stockbridge::damper {

Method parse_method(std::string_view name) {
  if (name == "hb") return Method::harmonic_balance;
  if (name == "collocation") return Method::collocation;
  if (name == "time") return Method::time_integration;
  if (name == "shooting") return Method::shooting;
  throw InvalidParameter(fmt::format("method = '{}': expected hb, collocation, time or shooting", name));
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

void SolverOptions::validate() const {
  harmonic_balance.validate();
  require_in_range("steps_per_period", steps_per_period, 16, 1 << 20);
  require_positive("energy_tolerance", energy_tolerance, "");
}

namespace {

class HarmonicBalanceArmSolver final : public ArmSolver {
 public:
  HarmonicBalanceArmSolver(const Arm& arm, HarmonicBalanceOptions options) : solver_(arm, options) {}
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& predictor) override {
    const Eigen::VectorXd start = predictor.size() == solver_.unknown_count() ? predictor : solver_.linear_guess(excitation);
    const bool continuing = predictor.size() == solver_.unknown_count();
    ArmSolution solution = solver_.solve(excitation, start, continuing);
    if (!solution.summary.converged && continuing) {
      // The predictor may lie on another piece: retry from the virgin state and the linear guess.
      ArmSolution retry = solver_.solve(excitation, solver_.linear_guess(excitation));
      if (retry.summary.converged) solution = std::move(retry);
    }
    return solution;
  }

  std::vector<ArmSolution> continue_to(const Excitation& target, const Eigen::VectorXd& from,
                                       double from_frequency_hz) override {
    if (from.size() != solver_.unknown_count()) return {};
    std::vector<ArmSolution> crossings =
        solver_.continue_along_branch(target.velocity_amplitude(), from, from_frequency_hz, target.frequency_hz);
    for (ArmSolution& s : crossings) s.summary.branches = static_cast<int>(crossings.size());
    return crossings;
  }

 private:
  HarmonicBalance solver_;
};

/// Time integration and shooting always start from the all-stick linear steady state
/// of the excitation: where nothing slips it is already periodic, whereas a neighbour's
/// state would set off a free vibration that dry friction alone never damps (MODEL.md
/// section 6). The predictor is therefore not used.
template <class Solver, class Options>
class TimeDomainArmSolver final : public ArmSolver {
 public:
  TimeDomainArmSolver(const Arm& arm, Options options) : solver_(arm, options) {}
  ArmSolution solve(const Excitation& excitation, const Eigen::VectorXd& /*predictor*/) override {
    return solver_.solve(excitation, nullptr);
  }

 private:
  Solver solver_;
};

}  // namespace

std::unique_ptr<ArmSolver> make_arm_solver(const Arm& arm, const SolverOptions& options) {
  options.validate();
  switch (options.method) {
    case Method::harmonic_balance:
      return std::make_unique<HarmonicBalanceArmSolver>(arm, options.harmonic_balance);
    case Method::collocation: {
      HarmonicBalanceOptions collocation = options.harmonic_balance;
      collocation.collocation = true;
      return std::make_unique<HarmonicBalanceArmSolver>(arm, collocation);
    }
    case Method::time_integration: {
      TimeIntegrationOptions time;
      time.steps_per_period = options.steps_per_period;
      return std::make_unique<TimeDomainArmSolver<TimeIntegration, TimeIntegrationOptions>>(arm, time);
    }
    case Method::shooting: {
      ShootingOptions shooting;
      shooting.steps_per_period = options.steps_per_period;
      return std::make_unique<TimeDomainArmSolver<Shooting, ShootingOptions>>(arm, shooting);
    }
  }
  throw InvalidParameter(fmt::format("method = {}: unknown", static_cast<int>(options.method)));
}

std::vector<std::size_t> distinct_arms(const DamperDescription& damper) {
  std::vector<std::size_t> representative(damper.arms.size());
  for (std::size_t k = 0; k < damper.arms.size(); ++k) {
    representative[k] = k;
    for (std::size_t j = 0; j < k; ++j) {
      if (damper.arms[k].same_mechanics(damper.arms[j])) {
        representative[k] = representative[j];
        break;
      }
    }
  }
  return representative;
}

ImpedancePoint combine(const DamperDescription& damper, const Excitation& excitation,
                       const std::vector<const ArmSolution*>& arm_solutions, double energy_tolerance) {
  ImpedancePoint point;
  point.frequency_hz = excitation.frequency_hz;
  point.velocity_amplitude = excitation.velocity_amplitude();
  point.displacement_amplitude = excitation.displacement_amplitude;
  point.converged = true;
  const double v = point.velocity_amplitude;
  std::complex<double> z(0.0, excitation.angular_frequency() * damper.clamp_mass);
  double dissipated = 0.0;
  for (std::size_t k = 0; k < arm_solutions.size(); ++k) {
    const ArmSolution& s = *arm_solutions[k];
    point.iterations = std::max(point.iterations, s.summary.iterations);
    point.seconds += s.summary.seconds;
    if (!s.summary.converged) {
      point.converged = false;
      if (point.message.empty()) {
        point.message = fmt::format("arm {} ({}): {}", k, damper.arms[k].name, s.summary.message);
      }
      continue;
    }
    if (!(s.summary.energy_error <= energy_tolerance)) {
      point.converged = false;
      if (point.message.empty()) {
        point.message = fmt::format("arm {} ({}): energy balance off by {:.3g} of the apparent power (tolerance {:.3g})", k,
                                    damper.arms[k].name, s.summary.energy_error, energy_tolerance);
      }
      continue;
    }
    point.residual = std::max(point.residual, s.summary.residual);
    if (s.summary.branches > 1) {
      point.non_unique = true;
      point.message = fmt::format("arm {} ({}): {} steady states at this frequency (the response curve folds back)", k,
                                  damper.arms[k].name, s.summary.branches);
    }
    point.energy_error = std::max(point.energy_error, s.summary.energy_error);
    z += arm_force_first_harmonic(s.period) / v;
    dissipated += s.period.dissipated;
  }
  if (point.converged) {
    point.impedance = z;
    point.power = 0.5 * v * v * z.real();
    point.dissipated_power = dissipated / excitation.period();
  }
  return point;
}

Eigen::RowVectorXd shaker_force(const DamperDescription& damper, const Excitation& excitation,
                                const std::vector<const ArmSolution*>& arm_solutions) {
  const Eigen::Index n = arm_solutions.front()->period.loads.cols();
  const double w = excitation.angular_frequency();
  Eigen::RowVectorXd force(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double t = excitation.period() * static_cast<double>(j) / static_cast<double>(n);
    force(j) = -damper.clamp_mass * w * w * excitation.displacement_amplitude * std::sin(w * t);
  }
  for (const ArmSolution* s : arm_solutions) force -= s->period.loads.row(0);
  return force;
}

}  // namespace stockbridge::damper
