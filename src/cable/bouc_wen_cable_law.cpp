#include "stockbridge/cable/bouc_wen_cable_law.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "cable_sums.hpp"
#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/cantilever.hpp"

namespace stockbridge::cable {

BoucWenCableLaw::BoucWenCableLaw(const CableDescription& description, std::span<const double> positions) {
  for (double position : positions) {
    const double s = description.profile_position(position);
    const double ei_min = description.bouc_wen.ei_min.at(s);
    ei_min_.push_back(ei_min);
    hysteretic_.push_back(description.bouc_wen.ei_max.at(s) - ei_min);
    chi0_.push_back(description.bouc_wen.chi0.at(s));
  }
}

BoucWenTravel bouc_wen_travel(double ei_min, double hysteretic, double chi0, double eta_from, double excess) {
  const double sign = excess > 0.0 ? 1.0 : -1.0;
  const double b = hysteretic * (1.0 - sign * eta_from);  // a (EI_max - EI_min), a in [0, 2]
  const double target = std::abs(excess) / chi0;
  const double k0 = ei_min + b;  // g'(0)
  // g(u) = ei_min u + b (1 - e^-u) is increasing and concave. Starts: the root of its
  // quadratic Taylor model k0 u - b u^2 / 2 (close for the small steps of a sampled
  // path), else the larger of the roots of its tangent at 0 and of its asymptote
  // ei_min u + b (both below the root).
  const double below = std::max(target / k0, (target - b) / ei_min);
  const double discriminant = k0 * k0 - 2.0 * b * target;
  double u = discriminant > 0.0 ? std::max(below, 2.0 * target / (k0 + std::sqrt(discriminant))) : below;
  // Halley's method, g'' = -b e^-u from the same exponential: cubic convergence (the
  // error after a step of order step^3, the derivatives' ratios being at most 1 in
  // u), so a step below 1e-6 of u leaves an error of order 1e-18 u^3, below
  // round-off, and needs no further exponential.
  double decay_minus_one = std::expm1(-u);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double decay = 1.0 + decay_minus_one;
    const double g = ei_min * u - b * decay_minus_one - target;
    const double g1 = ei_min + b * decay, g2 = -b * decay;
    const double step = -g / (g1 - 0.5 * g * g2 / g1);
    u += step;
    if (!(std::abs(step) > 1e-6 * u)) {
      // e^-(u + step) - 1 to third order in the (small) step.
      decay_minus_one += decay * (-step * (1.0 - step * (0.5 - step / 6.0)));
      break;
    }
    decay_minus_one = std::expm1(-u);
  }
  if (u < 0.0) return {0.0, 0.0};
  return {u, decay_minus_one};
}

void BoucWenCableLaw::apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force,
                                  CableState& to, CableWorkspace&) const {
  const std::size_t n = cable.sections();
  const double l = cable.length();
  const auto s = cable.positions();
  const auto w = cable.weights();
  const double d_clamp_moment = clamp_moment - from.clamp_moment;
  const double d_tip_force = tip_force - from.tip_force;
  CableSums sums;
  for (std::size_t i = 0; i < n; ++i) {
    const double excess = d_clamp_moment - d_tip_force * s[i];
    const double eta_from = from.hysteretic[i];
    double kappa = from.curvature[i], eta = eta_from, tangent = from.tangent[i], dissipated = 0.0;
    if (excess != 0.0) {
      const double sign = excess > 0.0 ? 1.0 : -1.0;
      const double b = hysteretic_[i], chi0 = chi0_[i];
      const BoucWenTravel travel = bouc_wen_travel(ei_min_[i], b, chi0, eta_from, excess);
      const double u = travel.u, decay_minus_one = travel.decay_minus_one;
      const double a = 1.0 - sign * eta_from;
      const double decay = 1.0 + decay_minus_one;
      kappa += sign * chi0 * u;
      eta = sign * (1.0 - a * decay);
      tangent = ei_min_[i] + b * a * decay;
      // (EI_max - EI_min) chi0 int eta^2 |d chi| along the stretch (section::bouc_wen_update),
      // with e^-2u - 1 = (e^-u - 1)(e^-u + 1).
      dissipated = b * chi0 * chi0 *
                   (u + 2.0 * a * decay_minus_one - 0.5 * a * a * decay_minus_one * (2.0 + decay_minus_one));
    }
    to.curvature[i] = kappa;
    to.hysteretic[i] = eta;
    to.tangent[i] = tangent;
    sums.add(w[i], s[i], l, kappa, 1.0 / tangent, dissipated);
  }
  sums.store(clamp_moment, tip_force, from, to);
}

double BoucWenCableLaw::internal_change(const CableState& start, const CableState& end) const {
  double change = 0.0;
  for (std::size_t i = 0; i < chi0_.size(); ++i) change = std::max(change, std::abs(end.hysteretic[i] - start.hysteretic[i]));
  return change;
}

namespace {

// The law is smooth along each monotone step, so the loads' derivatives follow the
// derivatives of every section's (kappa, eta) forward. A step from (kappa_f, eta_f)
// with E = exp(-|kappa - kappa_f| / chi0) and a E = (k_t - EI_min) / B (k_t the step's
// tangent, B = EI_max - EI_min) has
//     d eta = E d eta_f + (a E / chi0) (d kappa - d kappa_f),
//     dM = k_t d kappa + B (chi0 E d eta_f - a E d kappa_f),
// so d kappa = dM / k_t + alpha with alpha = (B / k_t) (a E d kappa_f - chi0 E d eta_f),
// and the tip kinematics close it: d(T, F) = J^-1 (du - sum_i w_i [1; l - s_i] alpha_i).
class BoucWenLoadSensitivity final : public LoadSensitivity {
 public:
  /// `law` outlives this (cables share their law; the one of the cable driven holds it).
  BoucWenLoadSensitivity(const Cable& cable, const BoucWenCableLaw& law)
      : positions_(cable.positions().begin(), cable.positions().end()),
        weights_(cable.weights().begin(), cable.weights().end()),
        length_(cable.length()),
        law_(law) {}

  void start(Eigen::Index parameters) override {
    const auto n = static_cast<Eigen::Index>(positions_.size());
    d_curvature_.setZero(parameters, n);
    d_eta_.setZero(parameters, n);
    alpha_.setZero(parameters, n);
  }

  void step(const CableState& from, const CableState& to, Eigen::VectorXd& d_rotation, Eigen::VectorXd& d_deflection,
            Eigen::VectorXd& d_clamp_moment, Eigen::VectorXd& d_tip_force) override {
    const std::size_t n = positions_.size();
    decay_.resize(n);
    a_decay_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto c = static_cast<Eigen::Index>(i);
      const double b = law_.ei_max(i) - law_.ei_min(i), chi0 = law_.chi0(i), k = to.tangent[i];
      decay_[i] = std::exp(-std::abs(to.curvature[i] - from.curvature[i]) / chi0);
      a_decay_[i] = b > 0.0 ? (k - law_.ei_min(i)) / b : 0.0;
      alpha_.col(c) = (b / k) * (a_decay_[i] * d_curvature_.col(c) - (chi0 * decay_[i]) * d_eta_.col(c));
      const double arm = length_ - positions_[i];
      d_rotation -= weights_[i] * alpha_.col(c);
      d_deflection -= (weights_[i] * arm) * alpha_.col(c);
    }
    const Eigen::Matrix2d inverse = to.flexibility.inverse();
    d_clamp_moment = inverse(0, 0) * d_rotation + inverse(0, 1) * d_deflection;
    d_tip_force = inverse(1, 0) * d_rotation + inverse(1, 1) * d_deflection;
    for (std::size_t i = 0; i < n; ++i) {
      const auto c = static_cast<Eigen::Index>(i);
      const double k = to.tangent[i], chi0 = law_.chi0(i);
      // d kappa_new - d kappa_f, then the new derivatives.
      alpha_.col(c) += (1.0 / k) * (d_clamp_moment - positions_[i] * d_tip_force) - d_curvature_.col(c);
      d_eta_.col(c) = decay_[i] * d_eta_.col(c) + (a_decay_[i] / chi0) * alpha_.col(c);
      d_curvature_.col(c) += alpha_.col(c);
    }
  }

  void mirror() override {
    d_curvature_ = -d_curvature_;
    d_eta_ = -d_eta_;
  }

 private:
  std::vector<double> positions_, weights_;
  double length_;
  const BoucWenCableLaw& law_;
  Eigen::MatrixXd d_curvature_, d_eta_, alpha_;  // parameters x sections
  std::vector<double> decay_, a_decay_;
};

}  // namespace

std::unique_ptr<LoadSensitivity> BoucWenCableLaw::load_sensitivity(const Cable& cable) const {
  return std::make_unique<BoucWenLoadSensitivity>(cable, *this);
}

}  // namespace stockbridge::cable
