// The Bouc-Wen cable law's load sensitivities (BoucWenCableLaw::load_sensitivity):
// each section's (kappa, eta) derivatives carried forward along a monotone step, the
// loads' derivatives from the tip kinematics; the loops built for the x86-64 baseline
// and for AVX2 with FMA, as the section loop is (bouc_wen_cable_law.cpp).
#include "stockbridge/cable/bouc_wen_cable_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Eigen/LU>

#include "exp_minus_one.hpp"
#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/cantilever.hpp"

namespace stockbridge::cable {

namespace {

/// One step's sensitivities (BoucWenLoadSensitivity::step) on raw columns: `p`
/// parameters, the sections' derivatives column by column (p x n, column-major).
struct StepSensitivity {
  std::size_t n;
  std::size_t p;
  const double *s, *w, *ei_min, *hysteretic, *chi0;
  const double *curvature_from, *curvature_to, *tangent_to;
  double length;
  double inverse[4];  // the step's flexibility inverted, row-major
  double *d_curvature, *d_eta, *decay, *a_decay, *on_curvature, *on_eta;
  double *d_rotation, *d_deflection, *d_clamp_moment, *d_tip_force;
};

/// E = exp(-|kappa - kappa_f| / chi0) of every section, four at a time (the padding's
/// lanes unused).
[[gnu::always_inline]] inline void step_decays(const StepSensitivity& t) {
  for (std::size_t i = 0; i < t.n; i += 4) {
    Lanes travel{};
    for (std::size_t k = 0; k < 4 && i + k < t.n; ++k) {
      travel[k] = std::abs(t.curvature_to[i + k] - t.curvature_from[i + k]) / t.chi0[i + k];
    }
    store_lanes(t.decay + i, 1.0 + exp_minus_one_of_nonpositive(-travel));
  }
}

/// The loops over the parameters run on vector registers (two or four lanes). alpha's
/// part from the step's start, on_curvature d kappa_f + on_eta d eta_f, is summed into
/// the tip kinematics' derivatives first and computed again in the second loop (two
/// multiplications, where storing and loading it cost more).
[[gnu::always_inline]] inline void propagate_step(const StepSensitivity& t) {
  const std::size_t p = t.p;
  step_decays(t);
  double* __restrict d_rotation = t.d_rotation;
  double* __restrict d_deflection = t.d_deflection;
  for (std::size_t i = 0; i < t.n; ++i) {
    const double b = t.hysteretic[i], chi0 = t.chi0[i], k = t.tangent_to[i];
    t.a_decay[i] = b > 0.0 ? (k - t.ei_min[i]) / b : 0.0;
    const double on_curvature = (b / k) * t.a_decay[i], on_eta = -(b / k) * (chi0 * t.decay[i]);
    t.on_curvature[i] = on_curvature;
    t.on_eta[i] = on_eta;
    const double weight = t.w[i], weight_arm = t.w[i] * (t.length - t.s[i]);
    const double* __restrict d_curvature = t.d_curvature + i * p;
    const double* __restrict d_eta = t.d_eta + i * p;
    for (std::size_t j = 0; j < p; ++j) {
      const double alpha = on_curvature * d_curvature[j] + on_eta * d_eta[j];
      d_rotation[j] -= weight * alpha;
      d_deflection[j] -= weight_arm * alpha;
    }
  }
  double* __restrict d_clamp_moment = t.d_clamp_moment;
  double* __restrict d_tip_force = t.d_tip_force;
  for (std::size_t j = 0; j < p; ++j) {
    d_clamp_moment[j] = t.inverse[0] * d_rotation[j] + t.inverse[1] * d_deflection[j];
    d_tip_force[j] = t.inverse[2] * d_rotation[j] + t.inverse[3] * d_deflection[j];
  }
  for (std::size_t i = 0; i < t.n; ++i) {
    const double inverse_k = 1.0 / t.tangent_to[i], s = t.s[i];
    const double on_alpha = t.a_decay[i] / t.chi0[i], decay = t.decay[i];
    const double on_curvature = t.on_curvature[i], on_eta = t.on_eta[i];
    double* __restrict d_curvature = t.d_curvature + i * p;
    double* __restrict d_eta = t.d_eta + i * p;
    for (std::size_t j = 0; j < p; ++j) {
      // d kappa_new - d kappa_f, then the new derivatives.
      const double alpha = (on_curvature * d_curvature[j] + on_eta * d_eta[j]) +
                           (inverse_k * (d_clamp_moment[j] - s * d_tip_force[j]) - d_curvature[j]);
      d_eta[j] = decay * d_eta[j] + on_alpha * alpha;
      d_curvature[j] += alpha;
    }
  }
}

// The two builds of the sensitivities' loops, as of the section loop.
void propagate_step_baseline(const StepSensitivity& t) { propagate_step(t); }
#if defined(__x86_64__)
__attribute__((target("arch=x86-64-v3"))) void propagate_step_avx2(const StepSensitivity& t) { propagate_step(t); }
#endif

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
    decay_.resize(lanes_padded(positions_.size()));
    a_decay_.resize(positions_.size());
    on_curvature_.resize(positions_.size());
    on_eta_.resize(positions_.size());
  }

  void step(const CableState& from, const CableState& to, Eigen::VectorXd& d_rotation, Eigen::VectorXd& d_deflection,
            Eigen::VectorXd& d_clamp_moment, Eigen::VectorXd& d_tip_force) override {
    const Eigen::Matrix2d inverse = to.flexibility.inverse();
    d_clamp_moment.resize(d_rotation.size());
    d_tip_force.resize(d_rotation.size());
    const StepSensitivity arrays{positions_.size(),
                                 static_cast<std::size_t>(d_curvature_.rows()),
                                 positions_.data(),
                                 weights_.data(),
                                 law_.ei_min_data(),
                                 law_.hysteretic_data(),
                                 law_.chi0_data(),
                                 from.curvature.data(),
                                 to.curvature.data(),
                                 to.tangent.data(),
                                 length_,
                                 {inverse(0, 0), inverse(0, 1), inverse(1, 0), inverse(1, 1)},
                                 d_curvature_.data(),
                                 d_eta_.data(),
                                 decay_.data(),
                                 a_decay_.data(),
                                 on_curvature_.data(),
                                 on_eta_.data(),
                                 d_rotation.data(),
                                 d_deflection.data(),
                                 d_clamp_moment.data(),
                                 d_tip_force.data()};
#if defined(__x86_64__)
    if (law_.uses_avx2()) {
      propagate_step_avx2(arrays);
      return;
    }
#endif
    propagate_step_baseline(arrays);
  }

  void mirror() override {
    d_curvature_ = -d_curvature_;
    d_eta_ = -d_eta_;
  }

  // z0 = (T, F, eta_j): d kappa_i = (dT - dF s_i - B_i chi0_i d eta_i) / EI_min_i.
  void seed_coordinates(Eigen::Index first) override {
    for (Eigen::Index i = 0; i < d_curvature_.cols(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double ei_min = law_.ei_min(k);
      d_curvature_(first, i) = 1.0 / ei_min;
      d_curvature_(first + 1, i) = -positions_[k] / ei_min;
      d_curvature_(first + 2 + i, i) = -law_.hysteretic_data()[k] * law_.chi0(k) / ei_min;
      d_eta_(first + 2 + i, i) = 1.0;
    }
  }

  void internal_derivatives(Eigen::MatrixXd& out) const override { out = d_eta_.transpose(); }

 private:
  std::vector<double> positions_, weights_;
  double length_;
  const BoucWenCableLaw& law_;
  Eigen::MatrixXd d_curvature_, d_eta_;  // parameters x sections
  std::vector<double> decay_, a_decay_, on_curvature_, on_eta_;
};

}  // namespace

std::unique_ptr<LoadSensitivity> BoucWenCableLaw::load_sensitivity(const Cable& cable) const {
  return std::make_unique<BoucWenLoadSensitivity>(cable, *this);
}

}  // namespace stockbridge::cable
