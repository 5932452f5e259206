#pragma once
// An independent reference for a damper whose messengers follow the Bouc-Wen law
// (MODEL.md section 13): slenderpy's equations, converged in space and time rather
// than solved exactly. It includes nothing from the library; unlike the library:
//
// * the law in its rate form, chi0 d eta = d chi - |d chi| eta, integrated along
//   each step by the trapezoid rule (implicit, second order; the library uses the
//   exact exponential solution of a monotone stretch): with eta_mid the mean of eta
//   before and after the step, d eta = (d chi - |d chi| eta_mid) / chi0 and
//   dM = [EI_min + B (1 - sign(d chi) eta_mid)] d chi, B = EI_max - EI_min;
// * the cable's state is (T, F, eta_i) and the curvature derived,
//   chi_i = (T - F s_i - B chi0 eta_i) / EI_min, on n equal midpoint sections (the
//   library: Gauss-Legendre points a zone); with n a multiple of 25 slenderpy's zone
//   edges at 0.2 l and 0.92 l fall on section edges;
// * each tip increment solves d(T, F) from the sections' trapezoid tangents by a
//   fixed-point iteration (tangents -> loads -> curvature increments -> eta_mid),
//   which closes the tip kinematics exactly at convergence;
// * the arm marched by velocity Verlet (reference_damper.hpp's march).
// Errors: the midpoint rule O((l/n)^2) inside the zones; the trapezoid rule
// O((d chi / chi0)^2) over a period, d chi the curvature step of one time step.

#include <cmath>
#include <stdexcept>
#include <vector>

#include "support/reference_damper.hpp"

namespace stockbridge::testing::reference {

/// A zone of the messenger from the previous zone's end (or the clamp) to `end`.
struct BoucWenZone {
  double end = 0.0;     ///< m from the clamp
  double ei_min = 0.0;  ///< N m^2
  double ei_max = 0.0;  ///< N m^2
  double chi0 = 0.0;    ///< 1/m
};

struct BoucWenArmNumbers {
  double mass = 0.0, inertia = 0.0, offset = 0.0;  ///< kg, kg m^2 about the centre of gravity, m
  double length = 0.0;                             ///< l, m
  int sections = 0;                                ///< n equal midpoint sections
  std::vector<BoucWenZone> zones;                  ///< ascending; the last ends at l
};

struct BoucWenDamperNumbers {
  double clamp_mass = 0.0;
  std::vector<BoucWenArmNumbers> arms;
};

/// The rate-form Bouc-Wen cantilever (see the header comment).
class RateFormBoucWenCable {
 public:
  explicit RateFormBoucWenCable(const BoucWenArmNumbers& arm) : length_(arm.length), width_(arm.length / arm.sections) {
    for (int i = 0; i < arm.sections; ++i) {
      const double s = (i + 0.5) * width_;
      std::size_t z = 0;
      while (z + 1 < arm.zones.size() && s > arm.zones[z].end) ++z;
      midpoints_.push_back(s);
      ei_min_.push_back(arm.zones[z].ei_min);
      hysteretic_.push_back(arm.zones[z].ei_max - arm.zones[z].ei_min);
      chi0_.push_back(arm.zones[z].chi0);
    }
    eta_.assign(midpoints_.size(), 0.0);
    eta_next_.assign(midpoints_.size(), 0.0);
    d_curvature_.assign(midpoints_.size(), 0.0);
    direction_.assign(midpoints_.size(), 1.0);
  }

  double tip_force() const { return tip_force_; }                             ///< F, N
  double tip_moment() const { return clamp_moment_ - tip_force_ * length_; }  ///< Q = T - F l, N m
  double dissipated() const { return dissipated_; }                           ///< J, since virgin
  const std::vector<double>& internal_state() const { return eta_; }          ///< eta_i
  std::vector<double> internal_scales() const { return std::vector<double>(eta_.size(), 1.0); }

  double rotation() const {
    double phi = 0.0;
    for (std::size_t i = 0; i < midpoints_.size(); ++i) phi += width_ * curvature(i);
    return phi;
  }
  double deflection() const {
    double x = 0.0;
    for (std::size_t i = 0; i < midpoints_.size(); ++i) x += width_ * (length_ - midpoints_[i]) * curvature(i);
    return x;
  }

  /// One trapezoid step of the tip to (phi, x).
  void move_tip_to(double rotation_target, double deflection_target) {
    const double dphi = rotation_target - rotation(), dx = deflection_target - deflection();
    const std::size_t n = midpoints_.size();
    eta_next_ = eta_;
    double dt = 0.0, df = 0.0;
    for (int iteration = 0;; ++iteration) {
      if (iteration == 200) {
        throw std::runtime_error("reference Bouc-Wen cable: the step's loads do not settle (last change " +
                                 std::to_string(last_change_ * 1e12) + "e-12" + " of the loads)");
      }
      // Tangents at eta_mid with the directions of the last estimate.
      double c00 = 0.0, c01 = 0.0, c10 = 0.0, c11 = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const double eta_mid = 0.5 * (eta_[i] + eta_next_[i]);
        const double direction = direction_[i];
        const double g = width_ / (ei_min_[i] + hysteretic_[i] * (1.0 - direction * eta_mid));
        const double s = midpoints_[i], arm = length_ - s;
        c00 += g;
        c01 -= g * s;
        c10 += g * arm;
        c11 -= g * arm * s;
      }
      double dt_new = 0.0, df_new = 0.0;
      solve_2x2(c00, c01, c10, c11, dphi, dx, dt_new, df_new);
      // Curvature increments and eta after the step: the trapezoid relation for eta
      // is linear in eta_next at a given d chi.
      for (std::size_t i = 0; i < n; ++i) {
        const double eta_mid = 0.5 * (eta_[i] + eta_next_[i]);
        const double direction = direction_[i];
        const double k = ei_min_[i] + hysteretic_[i] * (1.0 - direction * eta_mid);
        d_curvature_[i] = (dt_new - df_new * midpoints_[i]) / k;
        // A section whose moment hardly changes may flip its direction from one
        // estimate to the next; after 20 the directions stay (either way its tangent
        // multiplies a vanishing increment).
        if (iteration < 20) direction_[i] = d_curvature_[i] >= 0.0 ? 1.0 : -1.0;
        const double travel = std::abs(d_curvature_[i]) / chi0_[i];
        eta_next_[i] = (eta_[i] + d_curvature_[i] / chi0_[i] - 0.5 * travel * eta_[i]) / (1.0 + 0.5 * travel);
      }
      const double change = std::abs(dt_new - dt) * length_ + std::abs(df_new - df) * length_ * length_;
      const double scale = (std::abs(dt_new) + std::abs(df_new) * length_) * length_ + 1e-300;
      dt = dt_new;
      df = df_new;
      last_change_ = change / scale;
      if (change <= 1e-11 * scale) break;  // of the increment, whose own round-off is about 1e-13
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double eta_mid = 0.5 * (eta_[i] + eta_next_[i]);
      dissipated_ += width_ * hysteretic_[i] * chi0_[i] * eta_mid * eta_mid * std::abs(d_curvature_[i]);
    }
    eta_.swap(eta_next_);
    clamp_moment_ += dt;
    tip_force_ += df;
  }

 private:
  double curvature(std::size_t i) const {
    return (clamp_moment_ - tip_force_ * midpoints_[i] - hysteretic_[i] * chi0_[i] * eta_[i]) / ei_min_[i];
  }

  double length_, width_;
  std::vector<double> midpoints_, ei_min_, hysteretic_, chi0_;
  std::vector<double> eta_, eta_next_, d_curvature_, direction_;
  double clamp_moment_ = 0.0, tip_force_ = 0.0, dissipated_ = 0.0;
  double last_change_ = 0.0;
};

/// The Bouc-Wen damper's impedance by the march.
inline ReferenceResult reference_bouc_wen_impedance(const BoucWenDamperNumbers& damper, double frequency_hz,
                                                    double velocity, const MarchOptions& options = {}) {
  return march_impedance<RateFormBoucWenCable>(damper, frequency_hz, velocity, options);
}

}  // namespace stockbridge::testing::reference
