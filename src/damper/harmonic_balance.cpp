#include "stockbridge/damper/harmonic_balance.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/LU>
#include <fmt/format.h>

#include "../numerics/updated_factors.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/numerics/linear_solve.hpp"

namespace stockbridge::damper {

void HarmonicBalanceOptions::validate() const {
  require_in_range("harmonics", harmonics, 1, 100);
  if (samples != 0) require_in_range("samples", samples, 2 * harmonics + 1, 1 << 16);
  require_in_range("max_iterations", max_iterations, 1, 10000);
  require_positive("tolerance", tolerance, "");
  require_positive("periodicity_tolerance", periodicity_tolerance, "");
  require_in_range("periods", periods, 1, 1000);
  require_in_range("max_settling_periods", max_settling_periods, 0, 1000000);
  if (!(jacobian_refresh_ratio > 0.0 && jacobian_refresh_ratio <= 1.0)) {
    throw_invalid("jacobian_refresh_ratio", jacobian_refresh_ratio, "a value in (0, 1]");
  }
  if (!(settle_ratio >= 0.0 && std::isfinite(settle_ratio))) throw_invalid("settle_ratio", settle_ratio, "a value >= 0");
  require_in_range("stored_jacobian_points", stored_jacobian_points, 0, 1000000);
  cantilever.validate();
}

bool HarmonicBalanceOptions::uses_half_wave() const { return half_wave && !collocation && sample_count() % 2 == 0; }

int HarmonicBalanceOptions::sample_count() const {
  if (collocation) return 2 * harmonics + 1;
  if (samples > 0) return samples;
  // No FFT: any even count serves (half-wave symmetry halves it); multiples of 16 keep
  // the half period's samples a multiple of 8.
  return std::max(64, (8 * harmonics + 15) / 16 * 16);
}

namespace {
using Strided = Eigen::Map<Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>;
using ConstStrided = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, 2>>;

}  // namespace

HarmonicBalance::HarmonicBalance(Arm arm, HarmonicBalanceOptions options)
    : arm_(std::move(arm)),
      options_(validated(options)),
      samples_(options_.sample_count()),
      symmetry_(options_.uses_half_wave() ? PathSymmetry::half_wave : PathSymmetry::none),
      driven_samples_(symmetry_ == PathSymmetry::half_wave ? samples_ / 2 : samples_) {
  const bool odd_only = symmetry_ == PathSymmetry::half_wave;
  if (!odd_only) harmonic_.push_back(0);
  for (int k = 1; k <= options_.harmonics; k += odd_only ? 2 : 1) harmonic_.insert(harmonic_.end(), {k, k});
  excitation_column_ = odd_only ? 1 : 2;
  periodic_newton_ = options_.periodic_newton && arm_.cable().law().periodic_coordinates(arm_.cable()) > 0;
  const auto c_count = static_cast<Eigen::Index>(harmonic_.size());
  basis_.resize(driven_samples_, c_count);
  projection_.resize(c_count, driven_samples_);
  // Over half a period the odd harmonics' sums are half the whole period's.
  const double weight = (odd_only ? 2.0 : 1.0) / samples_;
  const int first_cosine = odd_only ? 0 : 1;  // then sine, cosine, sine, ...
  for (int j = 0; j < driven_samples_; ++j) {
    const double theta = 2.0 * std::numbers::pi * j / samples_;
    for (Eigen::Index c = 0; c < c_count; ++c) {
      const int k = harmonic_[static_cast<std::size_t>(c)];
      const bool sine = k > 0 && (c - first_cosine) % 2 == 1;
      basis_(j, c) = k == 0 ? 1.0 : sine ? std::sin(k * theta) : std::cos(k * theta);
      projection_(c, j) = (k == 0 ? 1.0 : 2.0) * weight * basis_(j, c);
    }
  }
}

HarmonicBalanceWorkspace HarmonicBalance::make_workspace() const {
  return HarmonicBalanceWorkspace{PeriodicCable(arm_.cable(), options_.cantilever), Eigen::MatrixXd()};
}

double HarmonicBalance::force_scale(const Excitation& excitation) const {
  const double w = excitation.angular_frequency();
  return arm_.description().mass * w * w * excitation.displacement_amplitude;
}

Eigen::VectorXd HarmonicBalance::linear_guess(const Excitation& excitation) const {
  const double w = excitation.angular_frequency();
  const Eigen::Matrix2d dynamic = arm_.stick_stiffness() - w * w * arm_.mass_matrix();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(unknown_count());
  // p(t) = L x_c'' = -W^2 X L sin(W t).
  q.segment<2>(2 * excitation_column_) = dynamic.inverse() * (-w * w * excitation.displacement_amplitude * arm_.load_vector());
  return q;
}

Eigen::VectorXd HarmonicBalance::whole_period_unknowns(const Eigen::VectorXd& q) const {
  if (symmetry_ != PathSymmetry::half_wave) return q;
  Eigen::VectorXd whole = Eigen::VectorXd::Zero(2 * (1 + 2 * static_cast<Eigen::Index>(options_.harmonics)));
  for (std::size_t c = 0; c < harmonic_.size(); ++c) {
    // Whole periods' columns: the mean, then cos k, sin k for k = 1, 2, ...; here cos k, sin k for odd k.
    const Eigen::Index column = 2 * harmonic_[c] - 1 + static_cast<Eigen::Index>(c % 2);
    whole.segment<2>(2 * column) = q.segment<2>(2 * static_cast<Eigen::Index>(c));
  }
  return whole;
}

Eigen::VectorXd HarmonicBalance::residual_change(const Excitation& from, const Excitation& to,
                                                 const Eigen::VectorXd& q) const {
  const int c_count = static_cast<int>(harmonic_.size());
  const double w0 = from.angular_frequency(), w1 = to.angular_frequency();
  const Eigen::Map<const Eigen::Matrix2Xd> coefficients(q.data(), 2, c_count);
  Eigen::Matrix2Xd d_inertia(2, c_count);  // of M u'': -k^2 W^2 M per harmonic
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_[static_cast<std::size_t>(c)];
    d_inertia.col(c) = -k * k * (w1 * w1 - w0 * w0) * (arm_.mass_matrix() * coefficients.col(c));
  }
  // R holds +W^2 X L sin(W t).
  const Eigen::Vector2d d_excitation =
      (w1 * w1 * to.displacement_amplitude - w0 * w0 * from.displacement_amplitude) * arm_.load_vector();
  Eigen::VectorXd d(unknown_count());
  if (!options_.collocation) {
    Eigen::Map<Eigen::Matrix2Xd> change(d.data(), 2, c_count);
    change = d_inertia;
    change.col(excitation_column_) += d_excitation;
  } else {
    Eigen::Map<Eigen::Matrix2Xd> change(d.data(), 2, samples_);
    change = d_inertia * basis_.transpose() + d_excitation * basis_.col(excitation_column_).transpose();
  }
  return d;
}

HarmonicBalanceEvaluation HarmonicBalance::evaluate(const Excitation& excitation, const Eigen::VectorXd& q,
                                                    const cable::CableState* start, int periods, unsigned derivatives,
                                                    HarmonicBalanceWorkspace& workspace, PeriodicStart mode) const {
  assert(q.size() == unknown_count());
  const int c_count = static_cast<int>(harmonic_.size());
  const int p_count = 2 * c_count;
  const bool with_jacobian = (derivatives & kJacobian) != 0;
  const double w = excitation.angular_frequency();
  const double x_amp = excitation.displacement_amplitude;
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  const Eigen::Vector2d& load = arm_.load_vector();
  const Eigen::Map<const Eigen::Matrix2Xd> coefficients(q.data(), 2, c_count);
  HarmonicBalanceEvaluation out;
  const Eigen::Matrix2Xd kinematics = coefficients * basis_.transpose();
  if (!kinematics.allFinite()) {
    out.cable.termination = Termination::non_finite;
    out.cable.where = "in the tip motion (the Fourier coefficients hold NaN or inf)";
    return out;
  }
  PeriodicCableResult loads =
      workspace.cable.evaluate(kinematics, periods, start, with_jacobian ? &basis_ : nullptr,
                               with_jacobian ? &workspace.sensitivity : nullptr, symmetry_, mode);
  out.cable = std::move(loads.summary);
  out.period = std::move(loads.period);
  if (!out.ok()) return out;
  out.end_state = workspace.cable.final_state();
  if (mode == PeriodicStart::newton) {
    const cable::CableLaw& law = arm_.cable().law();
    Eigen::VectorXd z_start;
    law.coordinates(start ? *start : cable::CableState::virgin(arm_.cable()), z_start);
    law.coordinates(out.end_state, out.state_gap);
    out.state_gap -= z_start;
    out.state_jacobian = std::move(loads.state_jacobian);
  }
  const Eigen::Index columns = with_jacobian ? workspace.sensitivity.cols() : 0;  // q's, then z0's
  // Accelerations' coefficients: -k^2 W^2 per harmonic.
  Eigen::Matrix2Xd acceleration(2, c_count);
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_[static_cast<std::size_t>(c)];
    acceleration.col(c) = -k * k * w * w * coefficients.col(c);
  }
  out.residual.resize(p_count);
  if (!options_.collocation) {
    Eigen::Map<Eigen::Matrix2Xd> residual(out.residual.data(), 2, c_count);
    residual = mass * acceleration + out.period.loads.leftCols(driven_samples_) * projection_.transpose();
    residual.col(excitation_column_) -= -w * w * x_amp * load;  // excitation, sin(W t)
    if (with_jacobian) {
      out.force_jacobian.resize(p_count, columns);
      for (int d = 0; d < 2; ++d) {
        const ConstStrided s(workspace.sensitivity.data() + d, driven_samples_, columns,
                             Eigen::Stride<Eigen::Dynamic, 2>(2 * driven_samples_, 2));
        Strided(out.force_jacobian.data() + d, c_count, columns, Eigen::Stride<Eigen::Dynamic, 2>(2 * c_count, 2)) =
            projection_ * s;
      }
    }
  } else {
    Eigen::Map<Eigen::Matrix2Xd> residual(out.residual.data(), 2, samples_);
    residual = mass * (acceleration * basis_.transpose()) + out.period.loads;
    residual -= (-w * w * x_amp * load) * basis_.col(excitation_column_).transpose();
    if (with_jacobian) out.force_jacobian = workspace.sensitivity;
  }
  if ((derivatives & kFrequency) != 0) {
    // At constant velocity amplitude V = W X: excitation -W V L sin(W t).
    const double v = w * x_amp;
    Eigen::Matrix2Xd d_acceleration(2, c_count);
    for (int c = 0; c < c_count; ++c) {
      const double k = harmonic_[static_cast<std::size_t>(c)];
      d_acceleration.col(c) = -2.0 * k * k * w * coefficients.col(c);
    }
    out.d_frequency.resize(p_count);
    if (!options_.collocation) {
      Eigen::Map<Eigen::Matrix2Xd> d(out.d_frequency.data(), 2, c_count);
      d = mass * d_acceleration;
      d.col(excitation_column_) += v * load;
    } else {
      Eigen::Map<Eigen::Matrix2Xd> d(out.d_frequency.data(), 2, samples_);
      d = mass * (d_acceleration * basis_.transpose());
      d += (v * load) * basis_.col(excitation_column_).transpose();
    }
  }
  return out;
}

Eigen::MatrixXd HarmonicBalance::jacobian(const Excitation& excitation, const Eigen::MatrixXd& force_jacobian) const {
  Eigen::MatrixXd jacobian;
  assemble_jacobian(excitation, force_jacobian, jacobian);
  return jacobian;
}

void HarmonicBalance::assemble_jacobian(const Excitation& excitation, const Eigen::MatrixXd& force_jacobian,
                                        Eigen::MatrixXd& jacobian) const {
  const int c_count = static_cast<int>(harmonic_.size());
  const double w = excitation.angular_frequency();
  const Eigen::Matrix2d& mass = arm_.mass_matrix();
  jacobian = force_jacobian;
  for (int c = 0; c < c_count; ++c) {
    const double k = harmonic_[static_cast<std::size_t>(c)];
    if (!options_.collocation) {
      jacobian.block<2, 2>(2 * c, 2 * c) += -k * k * w * w * mass;
    } else {
      for (int j = 0; j < samples_; ++j) jacobian.block<2, 2>(2 * j, 2 * c) += -k * k * w * w * basis_(j, c) * mass;
    }
  }
}

namespace {

/// Newton's method for one excitation, in named steps. The cable's start state,
/// the current evaluation and the Newton matrix are its own; the stored force
/// Jacobian lives in the caller's memory.
class NewtonSolve {
 public:
  NewtonSolve(const HarmonicBalance& model, const Excitation& excitation, HarmonicBalanceMemory& memory,
              HarmonicBalanceWorkspace& workspace, SolverSummary& summary)
      : model_(model),
        options_(model.options()),
        excitation_(excitation),
        scale_(model.force_scale(excitation)),
        memory_(memory),
        workspace_(workspace),
        summary_(summary),
        periodic_newton_(model.uses_periodic_newton()),
        start_(memory.cable_state) {}

  /// Runs Newton from q (updated in place); true when converged. `current()` is the
  /// last successful evaluation.
  bool run(Eigen::VectorXd& q);
  HarmonicBalanceEvaluation& current() { return current_; }
  const std::optional<cable::CableState>& cable_state() const { return start_; }

 private:
  /// Evaluates at q from the chained start state; on success adopts it as the
  /// current evaluation (the next start is its end state) and sets the Newton
  /// matrix, exact when `exact` or else from the stored force Jacobian.
  bool adopt_evaluation(const Eigen::VectorXd& q, bool exact, std::string_view stage);
  bool fail(Termination termination, std::string where = {});
  /// The residual and the periodicity defect of the current evaluation both within tolerance.
  bool criteria_met() const {
    return norm_ <= options_.tolerance && current_.cable.periodicity_defect <= options_.periodicity_tolerance;
  }
  enum class Finish { converged, not_yet, failed };
  /// Both criteria met: records the determinant sign and ends; where the sign
  /// changed since the last solution it is confirmed with an exact evaluation,
  /// whose criteria must hold too (not_yet: Newton goes on).
  Finish finish(const Eigen::VectorXd& q);
  /// The equations hold but the memory has not settled: more periods, no step.
  bool settle(const Eigen::VectorXd& q);
  enum class StepOutcome { accepted, retry_with_exact_jacobian, failed };
  /// One Newton step with a backtracking line search.
  StepOutcome step(Eigen::VectorXd& q);
  /// Broyden's rank-one update of the stored force Jacobian after an accepted step
  /// with a stored one: the secant condition J dq = dr along the step.
  void broyden_update(const Eigen::VectorXd& q);
  double norm_of(const HarmonicBalanceEvaluation& e) const { return e.residual.lpNorm<Eigen::Infinity>() / scale_; }
  /// Newton on the periodic state: from an exact evaluation, the stored terms and
  /// the force Jacobian with the state eliminated (false, nothing stored: G_z - I
  /// singular, its reciprocal condition below 1e-12).
  bool store_periodic_state_terms(const HarmonicBalanceEvaluation& e);
  /// The residual Newton steps on: R, less R_z D^-1 G under Newton on the periodic state.
  Eigen::VectorXd effective_residual(const HarmonicBalanceEvaluation& e) const;
  /// Where the next evaluation after `e` starts for a step dq (empty: none): its end
  /// state, or under Newton on the periodic state that moved to z + dz, dz = -D^-1 (G
  /// + G_q dq) (the end state where the law refuses the move).
  cable::CableState next_start(const HarmonicBalanceEvaluation& e, const Eigen::VectorXd* dq) const;
  /// Under Newton on the periodic state, with the state terms and the q of the last
  /// solution stored: moves the start (the periodic state there) to the state the
  /// terms predict periodic at q, z - D^-1 G_q (q - q_last) in the law's coordinates
  /// (kept where the law refuses the move). Along a sweep the first pass then starts
  /// nearer its periodic state: on slenderpy's damper the first pass's defect falls
  /// from a median of 2.6e-2 to 3.3e-3, and a point takes 4.9 passes instead of 5.4.
  void predict_periodic_start(const Eigen::VectorXd& q);
  /// Sign of det of the Newton matrix, from its factors (factored here where none are ready).
  int newton_matrix_sign() {
    if (!factors_.ready()) factors_.factor(jacobian_);
    return factors_.determinant_sign();
  }

  const HarmonicBalance& model_;
  const HarmonicBalanceOptions& options_;
  const Excitation& excitation_;
  const double scale_;
  HarmonicBalanceMemory& memory_;
  HarmonicBalanceWorkspace& workspace_;
  SolverSummary& summary_;
  /// From here on, chained periods (and the half-wave's centring) instead of Newton
  /// on the periodic state; the stored state terms are dropped with it.
  void chain_periods();

  PeriodicStart mode() const { return periodic_newton_ ? PeriodicStart::newton : PeriodicStart::chained; }
  /// Passes an evaluation drives: one under Newton on the periodic state, else options' periods.
  int passes() const { return periodic_newton_ ? 1 : options_.periods; }

  bool periodic_newton_;
  std::optional<cable::CableState> start_;  // where the cable's next evaluation starts (empty: virgin)
  Eigen::VectorXd effective_;                 // the current evaluation's effective_residual
  HarmonicBalanceEvaluation current_;
  Eigen::MatrixXd jacobian_;
  numerics::UpdatedFactors factors_;  // of jacobian_ where ready (its Broyden updates as rank-one changes)
  bool exact_ = false;  // the Newton matrix is exact at the current point
  double norm_ = 0.0;   // of the current residual, relative to the force scale
  int settling_periods_ = 0;
  double last_settling_defect_ = std::numeric_limits<double>::infinity();  // before the last settling pass
  Eigen::VectorXd step_start_, step_start_residual_;  // where the last step started
};

bool NewtonSolve::fail(Termination termination, std::string where) {
  summary_.termination = termination;
  summary_.where = std::move(where);
  return false;
}

bool NewtonSolve::adopt_evaluation(const Eigen::VectorXd& q, bool exact, std::string_view stage) {
  const unsigned derivatives = exact ? HarmonicBalance::kJacobian : HarmonicBalance::kNone;
  HarmonicBalanceEvaluation e =
      model_.evaluate(excitation_, q, start_ ? &*start_ : nullptr, passes(), derivatives, workspace_, mode());
  ++summary_.evaluations;
  summary_.jacobians += exact;
  summary_.periods += passes();
  if (e.cable.termination == Termination::non_finite) {
    return fail(Termination::non_finite, fmt::format("{} {}", stage, e.cable.where));
  }
  if (!e.ok()) return fail(Termination::inner_failure, fmt::format("{}: {}", stage, brief_report(e.cable)));
  bool chain = false;
  if (exact) {
    if (!periodic_newton_) {
      memory_.force_jacobian = std::move(e.force_jacobian);
    } else if (!store_periodic_state_terms(e)) {
      // G_z - I singular: a memory the pass barely forgets (whole periods near
      // stick), which no Newton step on the state resolves; chained periods settle it.
      memory_.force_jacobian = e.force_jacobian.leftCols(model_.unknown_count());
      chain = true;
    }
  }
  start_ = next_start(e, nullptr);
  current_ = std::move(e);
  norm_ = norm_of(current_);
  effective_ = effective_residual(current_);
  if (chain) chain_periods();
  model_.assemble_jacobian(excitation_, memory_.force_jacobian, jacobian_);
  factors_.clear();
  exact_ = exact;
  if (!current_.residual.allFinite()) return fail(Termination::non_finite, fmt::format("{} in the residual", stage));
  return true;
}

NewtonSolve::Finish NewtonSolve::finish(const Eigen::VectorXd& q) {
  int sign = newton_matrix_sign();
  if (!exact_ && sign != memory_.jacobian_sign) {
    // A fold is suspected: confirm the sign with the exact Jacobian.
    if (!adopt_evaluation(q, true, "confirming the Jacobian's sign")) return Finish::failed;
    if (!criteria_met()) return Finish::not_yet;
    sign = newton_matrix_sign();
  }
  memory_.jacobian_sign = sign;
  summary_.residual = norm_;
  summary_.periodicity_defect = current_.cable.periodicity_defect;
  summary_.termination = Termination::converged;
  return Finish::converged;
}

bool NewtonSolve::settle(const Eigen::VectorXd& q) {
  if (settling_periods_ >= options_.max_settling_periods) {
    const std::string where =
        norm_ <= options_.tolerance
            ? std::string("the equations hold")
            : fmt::format("the residual {:.3g} below {} times the periodicity defect {:.3g}", norm_,
                          options_.settle_ratio, current_.cable.periodicity_defect);
    return fail(Termination::not_periodic,
                fmt::format("({}; {} more periods at the same coefficients did not settle the cable's memory)", where,
                            settling_periods_));
  }
  settling_periods_ += options_.periods;
  // Newton's move of the start stalls where the pass's map has a kink (a section
  // whose moment reverses right at the period's start): there the rest of the solve
  // chains periods from the last end state, as without Newton on the state.
  if (periodic_newton_ && current_.cable.periodicity_defect > 0.5 * last_settling_defect_) chain_periods();
  last_settling_defect_ = current_.cable.periodicity_defect;
  return adopt_evaluation(q, false, "while settling");
}

NewtonSolve::StepOutcome NewtonSolve::step(Eigen::VectorXd& q) {
  if (!factors_.ready()) factors_.factor(jacobian_);
  const Eigen::VectorXd direction = factors_.solve(-effective_);
  if (exact_) {
    // Exact: adopted since the last factorisation, so no Broyden change on the factors.
    const double reciprocal_condition = factors_.reciprocal_condition();
    if (numerics::is_singular(reciprocal_condition, direction)) {
      summary_.reciprocal_condition = reciprocal_condition;
      fail(Termination::singular_jacobian);
      return StepOutcome::failed;
    }
  } else {
    // A stored Jacobian's step is tried once and an exact Jacobian decides if it
    // fails, so its conditioning is not estimated (that cost half a factorisation);
    // a singular one gives a non-finite step.
    if (!direction.allFinite()) return StepOutcome::retry_with_exact_jacobian;
  }
  const double norm2 = effective_.norm();
  // With a stored Jacobian only the full step is tried: if it fails, an exact one is cheaper than halving.
  // Under Newton on the periodic state chained periods take over sooner (run()).
  const int halvings = !exact_ ? 1 : periodic_newton_ ? 6 : 30;
  double alpha = 1.0;
  for (int halving = 0; halving < halvings; ++halving, alpha *= 0.5) {
    const Eigen::VectorXd dq = alpha * direction;
    const Eigen::VectorXd q_try = q + dq;
    const cable::CableState trial_start = next_start(current_, &dq);
    HarmonicBalanceEvaluation trial =
        model_.evaluate(excitation_, q_try, &trial_start, passes(), HarmonicBalance::kNone, workspace_, mode());
    ++summary_.evaluations;
    summary_.periods += passes();
    if (!trial.ok()) continue;
    // Accept a decrease, or a step that meets the tolerance.
    Eigen::VectorXd trial_effective = effective_residual(trial);
    if (trial_effective.norm() <= (1.0 - 1e-4 * alpha) * norm2 || norm_of(trial) <= options_.tolerance) {
      q = q_try;
      start_ = next_start(trial, nullptr);
      current_ = std::move(trial);
      effective_ = std::move(trial_effective);
      return StepOutcome::accepted;
    }
  }
  if (!exact_) return StepOutcome::retry_with_exact_jacobian;
  fail(Termination::line_search_failed);
  return StepOutcome::failed;
}

void NewtonSolve::predict_periodic_start(const Eigen::VectorXd& q) {
  if (!periodic_newton_ || !start_ || memory_.periodic_state.empty() || memory_.unknowns.size() != q.size()) return;
  // The stored state is periodic at the stored q. Staying periodic, z_end = z, to first
  // order: G_z dz + G_q dq = dz, so dz = -D^-1 G_q dq (D = G_z - I).
  const Eigen::VectorXd move = -(memory_.periodic_state.start_by_coefficients * (q - memory_.unknowns));
  cable::CableState moved = *start_;
  if (model_.arm().cable().law().shift(model_.arm().cable(), moved, move)) start_ = std::move(moved);
}

bool NewtonSolve::run(Eigen::VectorXd& q) {
  predict_periodic_start(q);
  const bool stored = memory_.force_jacobian.size() > 0 && (!periodic_newton_ || !memory_.periodic_state.empty());
  // Under Newton on the periodic state the stored Jacobian drifts from point to point.
  const bool aged = periodic_newton_ && options_.stored_jacobian_points > 0 &&
                    memory_.jacobian_points >= options_.stored_jacobian_points;
  if (!adopt_evaluation(q, !stored || aged, "at the starting point")) return false;
  while (true) {
    summary_.residual = norm_;
    summary_.periodicity_defect = current_.cable.periodicity_defect;
    if (criteria_met()) {
      const Finish outcome = finish(q);
      if (outcome == Finish::not_yet) continue;
      return outcome == Finish::converged;
    }
    // The equations hold, or the residual is mostly the memory's drift (a step cannot
    // remove it: a stored Jacobian's step was then mostly rejected, and an exact one
    // re-evaluated): let the memory settle at these coefficients first.
    if (norm_ <= options_.tolerance ||
        (!periodic_newton_ && norm_ < options_.settle_ratio * current_.cable.periodicity_defect)) {
      if (!settle(q)) return false;
      continue;
    }
    if (summary_.newton_iterations == options_.max_iterations) return fail(Termination::max_iterations);
    ++summary_.newton_iterations;
    const double previous_norm = norm_;
    step_start_ = q;
    step_start_residual_ = effective_;
    const StepOutcome outcome = step(q);
    if (outcome == StepOutcome::failed) {
      if (!periodic_newton_ || summary_.termination != Termination::line_search_failed) return false;
      // Newton's move of the start can leave the piece on which the pass's map is
      // smooth (a section reversing at the period's start): chain periods instead.
      --summary_.newton_iterations;
      summary_.termination = Termination::not_run;
      summary_.where.clear();
      chain_periods();
      if (!adopt_evaluation(q, true, "chaining periods")) return false;
      continue;
    }
    if (outcome == StepOutcome::retry_with_exact_jacobian) {
      --summary_.newton_iterations;
      if (!adopt_evaluation(q, true, "refreshing the Jacobian")) return false;
      continue;
    }
    norm_ = norm_of(current_);
    // Slow progress means the Jacobian belongs to another piece: refresh it.
    const bool refresh = norm_ > options_.jacobian_refresh_ratio * previous_norm && norm_ > options_.tolerance;
    if (refresh) {
      if (!adopt_evaluation(q, true, "refreshing the Jacobian")) return false;
    } else {
      broyden_update(q);
      model_.assemble_jacobian(excitation_, memory_.force_jacobian, jacobian_);
      exact_ = false;
    }
  }
}

void NewtonSolve::chain_periods() {
  periodic_newton_ = false;
  memory_.periodic_state = {};
  start_ = current_.end_state;
  effective_ = current_.residual;
}

bool NewtonSolve::store_periodic_state_terms(const HarmonicBalanceEvaluation& e) {
  const Eigen::Index n = model_.unknown_count(), m = e.state_gap.size();
  Eigen::MatrixXd d = e.state_jacobian.rightCols(m);
  d.diagonal().array() -= 1.0;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(d);
  if (!(lu.rcond() > 1e-12)) return false;
  PeriodicStateTerms& terms = memory_.periodic_state;
  terms.start_by_gap = lu.inverse();
  if (!terms.start_by_gap.allFinite()) return false;
  terms.start_by_coefficients.noalias() = terms.start_by_gap * e.state_jacobian.leftCols(n);
  terms.residual_by_start = e.force_jacobian.rightCols(m);
  memory_.force_jacobian = e.force_jacobian.leftCols(n);
  memory_.force_jacobian.noalias() -= terms.residual_by_start * terms.start_by_coefficients;
  return true;
}

Eigen::VectorXd NewtonSolve::effective_residual(const HarmonicBalanceEvaluation& e) const {
  if (!periodic_newton_ || memory_.periodic_state.empty()) return e.residual;
  const PeriodicStateTerms& terms = memory_.periodic_state;
  const Eigen::VectorXd start_move = terms.start_by_gap * e.state_gap;
  return e.residual - terms.residual_by_start * start_move;
}

cable::CableState NewtonSolve::next_start(const HarmonicBalanceEvaluation& e, const Eigen::VectorXd* dq) const {
  if (!periodic_newton_ || memory_.periodic_state.empty()) return e.end_state;
  const PeriodicStateTerms& terms = memory_.periodic_state;
  // From the end state (z + G) to z + dz.
  Eigen::VectorXd move = -(terms.start_by_gap * e.state_gap) - e.state_gap;
  if (dq) move.noalias() -= terms.start_by_coefficients * *dq;
  cable::CableState start = e.end_state;
  if (!model_.arm().cable().law().shift(model_.arm().cable(), start, move)) return e.end_state;
  return start;
}

void NewtonSolve::broyden_update(const Eigen::VectorXd& q) {
  if (!options_.broyden) return;
  const Eigen::VectorXd dq = q - step_start_;
  const double dq2 = dq.squaredNorm();
  if (!(dq2 > 0.0)) return;
  // The inertia terms are linear: the whole Newton matrix's secant error is the force Jacobian's.
  const Eigen::VectorXd change = ((effective_ - step_start_residual_) - jacobian_ * dq) / dq2;
  memory_.force_jacobian.noalias() += change * dq.transpose();
  if (factors_.ready()) factors_.update(change, dq);
}

}  // namespace

ArmSolution HarmonicBalance::solve(const Excitation& excitation, const Eigen::VectorXd& initial,
                                   HarmonicBalanceMemory& memory, HarmonicBalanceWorkspace& workspace) const {
  excitation.validate();
  if (initial.size() != unknown_count()) {
    throw InvalidParameter("initial_guess", fmt::format(" has {} values: expected {}", initial.size(), unknown_count()));
  }
  const auto started = std::chrono::steady_clock::now();
  ArmSolution solution;
  solution.unknowns = initial;
  NewtonSolve newton(*this, excitation, memory, workspace, solution.summary);
  const bool converged = newton.run(solution.unknowns);
  if (converged) {
    memory.cable_state = newton.cable_state();
    memory.unknowns = solution.unknowns;
    memory.jacobian_points = solution.summary.jacobians > 0 ? 1 : memory.jacobian_points + 1;
    solution.jacobian_sign = memory.jacobian_sign;
  } else {
    memory.clear();
  }
  if (newton.current().ok()) {
    solution.period = std::move(newton.current().period);
    solution.summary.energy_error = energy_error(solution.period, excitation);
  }
  solution.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return solution;
}

ArmSolution HarmonicBalance::solve(const Excitation& excitation, const Eigen::VectorXd& initial) const {
  HarmonicBalanceMemory memory;
  HarmonicBalanceWorkspace workspace = make_workspace();
  return solve(excitation, initial, memory, workspace);
}

}  // namespace stockbridge::damper
