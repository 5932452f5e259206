#include "stockbridge/cable/cantilever.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/LU>

#include "cable_sums.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::cable {

Eigen::Matrix2d tip_flexibility(const Cable& cable, std::span<const double> tangent) {
  CableSums sums;
  for (std::size_t i = 0; i < cable.sections(); ++i) {
    sums.add(cable.weights()[i], cable.positions()[i], cable.length(), 0.0, 1.0 / tangent[i], 0.0);
  }
  return sums.flexibility;
}

CableState CableState::virgin(const Cable& cable) {
  const std::size_t n = cable.sections();
  CableState state;
  state.curvature.assign(n, 0.0);
  state.hysteretic.assign(n * cable.law().internal_variables(), 0.0);
  state.tangent.resize(n);
  for (std::size_t i = 0; i < n; ++i) state.tangent[i] = cable.law().stick_stiffness(i);
  state.flexibility = tip_flexibility(cable, state.tangent);
  return state;
}

void CableState::mirror() {
  clamp_moment = -clamp_moment;
  tip_force = -tip_force;
  rotation = -rotation;
  deflection = -deflection;
  flexibility_change = -flexibility_change;
  for (double& k : curvature) k = -k;
  for (double& h : hysteretic) h = -h;
}

void CableState::move_halfway_to(const CableState& other) {
  auto halfway = [](double& value, double to) { value = 0.5 * (value + to); };
  halfway(clamp_moment, other.clamp_moment);
  halfway(tip_force, other.tip_force);
  halfway(rotation, other.rotation);
  halfway(deflection, other.deflection);
  for (std::size_t i = 0; i < curvature.size(); ++i) halfway(curvature[i], other.curvature[i]);
  for (std::size_t i = 0; i < hysteretic.size(); ++i) halfway(hysteretic[i], other.hysteretic[i]);
}

Eigen::Matrix2d CableState::tip_stiffness(double length) const { return cable::tip_stiffness(flexibility, length); }

Eigen::Matrix2d tip_stiffness(const Eigen::Matrix2d& flexibility, double length) {
  const Eigen::Matrix2d k = flexibility.inverse();  // d(T, F)/d(phi, x)
  Eigen::Matrix2d out;  // d(F, Q)/d(x, phi), Q = T - F l
  out(0, 0) = k(1, 1);
  out(0, 1) = k(1, 0);
  out(1, 0) = k(0, 1) - length * k(1, 1);
  out(1, 1) = k(0, 0) - length * k(1, 0);
  return out;
}

void apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force, CableState& to,
                 CableWorkspace& workspace) {
  cable.law().apply_loads(cable, from, clamp_moment, tip_force, to, workspace);
}

void CantileverOptions::validate() const {
  require_in_range("max_iterations", max_iterations, 1, 10000);
  require_positive("tolerance", tolerance, "");
  require_in_range("max_halvings", max_halvings, 0, 200);
}

Cantilever::Cantilever(Cable cable, CantileverOptions options)
    : cable_(std::move(cable)),
      options_(validated(options)),
      state_(CableState::virgin(cable_)),
      inverse_length_(1.0 / cable_.length()),
      second_order_(cable_.law().has_flexibility_change()),
      elastic_flexibility_(state_.committed().flexibility),
      candidate_(state_.committed()) {}

void Cantilever::commit() {
  const double l = cable_.length();
  last_increment_ = {trial().rotation - committed().rotation, (trial().deflection - committed().deflection) / l};
  state_.commit();
}

void Cantilever::reset() {
  state_ = SwappingCommittable<CableState>(CableState::virgin(cable_));
  last_increment_.setZero();
}

void Cantilever::restore(const CableState& state) {
  state_ = SwappingCommittable<CableState>(state);
  last_increment_.setZero();
}

void Cantilever::mirror() {
  CableState& mirrored = state_.trial_to_overwrite();
  mirrored = state_.committed();
  mirrored.mirror();
  state_.commit();
  last_increment_ = -last_increment_;
}

void Cantilever::commit_halfway_to(const CableState& other) {
  CableState& moved = state_.trial_to_overwrite();
  moved = state_.committed();
  moved.move_halfway_to(other);
  state_.commit();
  last_increment_.setZero();  // as after restore(): no step led here
}

void Cantilever::set_trial_loads(double clamp_moment, double tip_force) {
  require_finite("clamp_moment", clamp_moment, "N m");
  require_finite("tip_force", tip_force, "N");
  apply_loads(cable_, state_.committed(), clamp_moment, tip_force, state_.trial_to_overwrite(), workspace_);
}

// What a state determination prescribes, in scaled variables: loads p = (T, F l) in
// N m, kinematics k = (phi, x / l) in rad. Its unknowns q give the loads p = B q and
// are given by them, q = B+ p (B's pseudo-inverse); the residual is C k - target, and
// the Jacobian of C k by q is C g B for the scaled flexibility g. Each case spells its
// B, B+ and C out, so that no step multiplies by an identity.
struct Cantilever::BothTipCoordinates {  // B = B+ = C = I: the unknowns are the loads
  static constexpr int K = 2;
  using Vector = Eigen::Vector2d;
  static Eigen::Vector2d loads(const Vector& q) { return q; }
  static Vector unknowns(const Eigen::Vector2d& p) { return p; }
  static Vector prescribed(const Eigen::Vector2d& k) { return k; }
  static Eigen::Matrix2d jacobian(const Eigen::Matrix2d& g) { return g; }
};
struct Cantilever::DeflectionOnly {  // Q = 0: T = F l, p = (1, 1) q, only x / l prescribed
  static constexpr int K = 1;
  using Vector = Eigen::Matrix<double, 1, 1>;
  static Eigen::Vector2d loads(const Vector& q) { return {q(0), q(0)}; }
  static Vector unknowns(const Eigen::Vector2d& p) { return Vector(0.5 * (p(0) + p(1))); }
  static Vector prescribed(const Eigen::Vector2d& k) { return Vector(k(1)); }
  static Eigen::Matrix<double, 1, 1> jacobian(const Eigen::Matrix2d& g) {
    return Eigen::Matrix<double, 1, 1>(g(1, 0) + g(1, 1));
  }
};

StateDetermination Cantilever::set_trial_tip(double deflection, double rotation) {
  require_finite("deflection", deflection, "m");
  require_finite("rotation", rotation, "rad");
  return solve<BothTipCoordinates>(Eigen::Vector2d(rotation, deflection * inverse_length_));
}

StateDetermination Cantilever::set_trial_deflection(double deflection) {
  require_finite("deflection", deflection, "m");
  return solve<DeflectionOnly>(DeflectionOnly::Vector(deflection / cable_.length()));
}

/// The Jacobian's inverse applied to a vector, as Eigen's inverse() then product
/// would (the same roundings), in scalars: the compiler built Eigen's version from
/// two scalar stores and a stalled vector load (this runs for every sample of every
/// pass; the example sweep 3 % faster).
inline Eigen::Matrix<double, 1, 1> inverse_times(const Eigen::Matrix<double, 1, 1>& a,
                                                 const Eigen::Matrix<double, 1, 1>& v) {
  return Eigen::Matrix<double, 1, 1>((1.0 / a(0, 0)) * v(0));
}
inline Eigen::Vector2d inverse_times(const Eigen::Matrix2d& a, const Eigen::Vector2d& v) {
  const double inverse_determinant = 1.0 / (a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0));
  const double i00 = a(1, 1) * inverse_determinant, i01 = -a(0, 1) * inverse_determinant;
  const double i10 = -a(1, 0) * inverse_determinant, i11 = a(0, 0) * inverse_determinant;
  return {i00 * v(0) + i01 * v(1), i10 * v(0) + i11 * v(1)};
}

/// The second-order term of the scaled kinematics (phi, x / l) under a change d of
/// the scaled loads (T, F l), from CableState::flexibility_change:
/// sum w c dM^2 [1; (l - s) / l] with dM = dT - dF s.
inline Eigen::Vector2d second_order_term(const Eigen::Matrix<double, 2, 3>& change, const Eigen::Vector2d& d,
                                         double inverse_l) {
  const double t = d(0), f = d(1) * inverse_l;
  const double tt = t * t, tf = 2.0 * t * f, ff = f * f;
  return {change(0, 0) * tt - change(0, 1) * tf + change(0, 2) * ff,
          (change(1, 0) * tt - change(1, 1) * tf + change(1, 2) * ff) * inverse_l};
}

// Newton's method in the scaled variables. Norms are compared squared (no square
// root a step: this runs for every sample of every pass). Where the law's tangents
// vary smoothly (CableLaw::has_flexibility_change) the predictor and each step take
// the second order too: for the kinematics k(q) = k0 + G d + H(d) / 2 the step
// d = d1 - G^-1 H(d1) / 2 from the first-order d1 = G^-1 (target - k0) (Chebyshev's
// method: cubic), which lands a Bouc-Wen cable's sample in one correction where the
// first-order steps took two.
template <class Prescribed>
StateDetermination Cantilever::solve(const typename Prescribed::Vector& target) {
  using Vector = typename Prescribed::Vector;
  const double inverse_l = inverse_length_;
  auto scaled_kinematics = [inverse_l](const CableState& s) {
    return Eigen::Vector2d(s.rotation, s.deflection * inverse_l);
  };
  // g = diag(1, 1/l) f diag(1, 1/l): (T, F l) -> (phi, x / l)
  auto jacobian = [inverse_l](const Eigen::Matrix2d& f) {
    Eigen::Matrix2d g;
    g << f(0, 0), f(0, 1) * inverse_l, f(1, 0) * inverse_l, f(1, 1) * inverse_l * inverse_l;
    return Prescribed::jacobian(g);
  };
  const CableState& from = state_.committed();
  StateDetermination result;
  auto evaluate = [&](const Vector& q, CableState& into) -> Vector {
    const Eigen::Vector2d p = Prescribed::loads(q);
    apply_loads(cable_, from, p(0), p(1) * inverse_l, into, workspace_);
    ++result.evaluations;
    return Prescribed::prescribed(scaled_kinematics(into)) - target;
  };

  // Predictor: the committed tangent when loading goes on in the same direction,
  // the all-stick tangent after a reversal (where every element sticks again).
  Vector q = Prescribed::unknowns(Eigen::Vector2d(from.clamp_moment, from.tip_force * cable_.length()));
  const Vector committed_kinematics = Prescribed::prescribed(scaled_kinematics(from));
  const Vector increment = target - committed_kinematics;
  const bool continuing = Prescribed::prescribed(last_increment_).dot(increment) > 0.0;
  // The second order's correction of a first-order change d1 of the unknowns,
  // -G^-1 H(d1) / 2, taken where it is at most a quarter of d1 (a quadratic model of a
  // step that crosses a turn of the law, or is large, can be far off: there the
  // first-order step and the line search go on alone).
  auto add_second_order = [inverse_l](const CableState& at, const auto& g, Vector& d1) {
    const Vector correction = -inverse_times(
        g, 0.5 * Prescribed::prescribed(second_order_term(at.flexibility_change, Prescribed::loads(d1), inverse_l)));
    if (correction.squaredNorm() <= 0.0625 * d1.squaredNorm()) d1 += correction;
  };
  const auto predictor_jacobian = jacobian(continuing ? from.flexibility : elastic_flexibility_);
  Vector change = inverse_times(predictor_jacobian, increment);
  if (continuing && second_order_) add_second_order(from, predictor_jacobian, change);
  const Vector predicted = q + change;
  if (predicted.allFinite()) q = predicted;  // else start from the committed loads

  const double scale = std::max({target.template lpNorm<Eigen::Infinity>(),
                                 committed_kinematics.template lpNorm<Eigen::Infinity>(), 1e-12});
  const double tolerance_squared = std::pow(options_.tolerance * scale, 2);
  CableState& trial = state_.trial_to_overwrite();  // apply_loads fills every field
  Vector residual = evaluate(q, trial);
  double norm_squared = residual.squaredNorm();
  while (true) {
    if (norm_squared <= tolerance_squared) {
      result.termination = Termination::converged;
      break;
    }
    if (!std::isfinite(norm_squared)) {
      result.termination = Termination::non_finite;
      break;
    }
    if (result.newton_iterations == options_.max_iterations) {
      result.termination = Termination::max_iterations;
      break;
    }
    ++result.newton_iterations;
    const auto newton_jacobian = jacobian(trial.flexibility);
    Vector step = -inverse_times(newton_jacobian, residual);
    if (second_order_) add_second_order(trial, newton_jacobian, step);
    if (!step.allFinite()) {  // a singular flexibility
      result.termination = Termination::singular_jacobian;
      result.reciprocal_condition = 0.0;
      break;
    }
    bool accepted = false;
    double alpha = 1.0;
    for (int halving = 0; halving <= options_.max_halvings; ++halving, alpha *= 0.5) {
      const Vector q_try = q + alpha * step;
      const Vector residual_try = evaluate(q_try, candidate_);
      const double norm_squared_try = residual_try.squaredNorm();
      if (norm_squared_try <= std::pow(1.0 - 1e-4 * alpha, 2) * norm_squared) {  // sufficient decrease of the norm
        q = q_try;
        residual = residual_try;
        norm_squared = norm_squared_try;
        std::swap(trial, candidate_);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      result.termination = Termination::line_search_failed;
      break;
    }
  }
  result.residual = std::sqrt(norm_squared);
  return result;
}

}  // namespace stockbridge::cable
