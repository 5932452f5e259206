#pragma once
// An independent, deliberately different and deliberately slow reference for the
// nonlinear impedance of a Stockbridge damper (MODEL.md sections 1, 3, 4, 5).
// It includes nothing from the library: the library's four periodic methods share
// one cable routine, so they cannot catch an error in the cable law; this can.
//
// Formulation (what differs from the library is marked "unlike the library"):
//
// * Cable (section 3): n equal sections of length l/n, each represented by its
//   midpoint s_i = (i + 1/2) l/n with weight l/n (midpoint rule; unlike the
//   library, no Gauss-Legendre). Section i carries the Jenkin moments H_ij. The
//   cable's state is (T, F, H): clamp moment, tip force and the element moments;
//   the curvature is derived, kappa_i = (T - F s_i - sum_j H_ij) / ei, and so are
//   the tip kinematics phi = sum w kappa_i, x = sum w (l - s_i) kappa_i.
//
// * Exact piecewise-linear path following (unlike the library's Newton on (T, F)
//   with a moment-driven return mapping): the tip is moved along the straight
//   segment from its current (phi, x) to the target. Along a segment with a fixed
//   set of sliding elements the map is linear: d(phi, x) = C d(T, F) with
//   C = sum w / k_i [1; l - s_i] [1, -s_i], k_i = ei + sum of c_j of the
//   non-sliding elements. The sliding set is made consistent with the direction
//   (a saturated element |H| = h slides iff dM_i H > 0, dM_i = dT - dF s_i; else it
//   unloads elastically), then the segment is cut at the first breakpoint, where a
//   sticking element reaches +-h exactly (H = clamp(H + c dkappa, -h, h) with the
//   clamp's kink located inside the step). The rest of the segment is followed with
//   the new set. Sliders dissipate h |dkappa| w exactly per piece.
//
// * Arm (section 4), unlike the library's periodic solvers: an explicit
//   velocity-Verlet (central difference) march of M u'' + (F, Q) = L x_c'' with
//   u = (x, phi), Q = T - F l, M = [[m, -m b], [-m b, Theta + m b^2]],
//   L = [-m; m b], from rest relative to the clamp and a virgin cable, with many
//   small equal steps, until successive periods agree (the impedance, the arm's
//   state and every H at the period starts).
//
// * Impedance (section 5): x_c = X sin(W t), F_c = m_c x_c'' - sum_k F_k sampled at
//   the steps of the last period, F1 = (2/N) sum F_c e^{-i W t}, Z = F1 / V,
//   P = V^2 Re Z / 2. The result also carries the energy the sliders dissipated in
//   that period / T and the shaker's mean power (1/T) int F_c v dt, so a caller can
//   check the energy balance.
//
// Errors: the midpoint rule, about O((l/n)^2) (slower where kappa(s) has kinks at
// the stick-slip boundaries: about 3x per doubling of n at 40 Hz); the time march
// O(dt^2), which includes following the straight chord of the tip path within a
// step. Both are measurable by refining n and dt (independent_reference_test.cpp).

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace stockbridge::testing::reference {

struct JenkinElement {
  double c = 0.0;  ///< spring, N m^2
  double h = 0.0;  ///< slip moment, N m
};

struct ArmNumbers {
  double mass = 0.0;     ///< m, kg
  double inertia = 0.0;  ///< Theta about the centre of gravity, kg m^2
  double offset = 0.0;   ///< b, m, cable tip to centre of gravity, toward the clamp
  double length = 0.0;   ///< l, m
  int sections = 0;      ///< n equal midpoint sections
  double ei = 0.0;       ///< N m^2
  std::vector<JenkinElement> jenkin;  ///< constant along the cable
};

struct DamperNumbers {
  double clamp_mass = 0.0;  ///< m_c, kg
  std::vector<ArmNumbers> arms;
};

struct MarchOptions {
  int steps_per_period = 2000;
  int min_periods = 4;
  int max_periods = 600;
  /// Relative change between successive periods (impedance, arm state, H / h).
  double periodicity_tolerance = 1e-7;
};

struct ReferenceResult {
  std::complex<double> impedance;  ///< Z = F1 / V, N s/m
  double power = 0.0;              ///< V^2 Re Z / 2, W
  double dissipated_power = 0.0;   ///< sliders' energy in the last period / T, W
  double input_power = 0.0;        ///< (1/T) int F_c v dt over the last period, W
  int periods = 0;                 ///< periods marched
  double periodicity_defect = 0.0;  ///< of the last period
};

/// Cramer's rule for [a b; c d] [p; q] = [r; s].
inline void solve_2x2(double a, double b, double c, double d, double r, double s, double& p, double& q) {
  const double det = a * d - b * c;
  p = (d * r - b * s) / det;
  q = (a * s - c * r) / det;
}

/// A quasi-static cantilever cable with exact path following (see the header comment).
class PathFollowingCable {
 public:
  explicit PathFollowingCable(const ArmNumbers& arm)
      : length_(arm.length),
        ei_(arm.ei),
        jenkin_(arm.jenkin),
        width_(arm.length / arm.sections),
        moments_(static_cast<std::size_t>(arm.sections) * arm.jenkin.size(), 0.0),
        sliding_(moments_.size(), 0) {
    for (int i = 0; i < arm.sections; ++i) midpoints_.push_back((i + 0.5) * width_);
  }

  double tip_force() const { return tip_force_; }                                 ///< F, N
  double tip_moment() const { return clamp_moment_ - tip_force_ * length_; }      ///< Q = T - F l, N m
  double dissipated() const { return dissipated_; }                               ///< J, since virgin
  const std::vector<double>& element_moments() const { return moments_; }         ///< H_ij, N m
  /// The cable's memory for the periodicity test, and its scales (h).
  const std::vector<double>& internal_state() const { return moments_; }
  std::vector<double> internal_scales() const {
    std::vector<double> scales;
    for (std::size_t i = 0; i < midpoints_.size(); ++i) {
      for (const JenkinElement& e : jenkin_) scales.push_back(e.h);
    }
    return scales;
  }

  double rotation() const {  ///< phi = int kappa ds
    double phi = 0.0;
    for (std::size_t i = 0; i < midpoints_.size(); ++i) phi += width_ * curvature(i);
    return phi;
  }
  double deflection() const {  ///< x = int (l - s) kappa ds
    double x = 0.0;
    for (std::size_t i = 0; i < midpoints_.size(); ++i) x += width_ * (length_ - midpoints_[i]) * curvature(i);
    return x;
  }

  /// Moves the tip along the straight segment to (phi, x), exactly (up to round-off).
  void move_tip_to(double rotation_target, double deflection_target) {
    // The remaining increment is recomputed from the state, so round-off cannot drift.
    for (int piece = 0; piece < 100000; ++piece) {
      const double dphi = rotation_target - rotation(), dx = deflection_target - deflection();
      const double scale = std::abs(rotation_target) * length_ + std::abs(deflection_target) + 1e-12;
      if (std::abs(dphi) * length_ + std::abs(dx) <= 1e-13 * scale) return;
      follow_piece(dphi, dx);
    }
    throw std::runtime_error("reference cable: too many breakpoints in one step");
  }

 private:
  double curvature(std::size_t i) const {
    double m = clamp_moment_ - tip_force_ * midpoints_[i];
    for (std::size_t j = 0; j < jenkin_.size(); ++j) m -= moments_[i * jenkin_.size() + j];
    return m / ei_;
  }
  bool saturated(std::size_t e) const { return std::abs(moments_[e]) >= jenkin_[e % jenkin_.size()].h; }

  /// Section tangent with the current sliding flags.
  double tangent(std::size_t i) const {
    double k = ei_;
    for (std::size_t j = 0; j < jenkin_.size(); ++j) {
      if (!sliding_[i * jenkin_.size() + j]) k += jenkin_[j].c;
    }
    return k;
  }

  /// d(T, F) for the tip increment (dphi, dx) with the current sliding flags.
  void load_increment(double dphi, double dx, double& dt, double& df) const {
    double c00 = 0.0, c01 = 0.0, c10 = 0.0, c11 = 0.0;
    for (std::size_t i = 0; i < midpoints_.size(); ++i) {
      const double g = width_ / tangent(i), s = midpoints_[i], arm = length_ - s;
      c00 += g;
      c01 -= g * s;
      c10 += g * arm;
      c11 -= g * arm * s;
    }
    solve_2x2(c00, c01, c10, c11, dphi, dx, dt, df);
  }

  /// Sets the sliding flags from a load direction; true if any flag changed.
  bool set_sliding(double dt, double df) {
    bool changed = false;
    for (std::size_t e = 0; e < moments_.size(); ++e) {
      const double dm = dt - df * midpoints_[e / jenkin_.size()];
      const char slide = saturated(e) && dm * moments_[e] > 0.0 ? 1 : 0;
      changed = changed || slide != sliding_[e];
      sliding_[e] = slide;
    }
    return changed;
  }

  /// Fixed-point iteration: sliding set -> load direction -> sliding set.
  void consistent_load_increment(double dphi, double dx, double& dt, double& df) {
    for (int iteration = 0; iteration < 200; ++iteration) {
      load_increment(dphi, dx, dt, df);
      if (!set_sliding(dt, df)) return;
    }
    throw std::runtime_error("reference cable: no consistent sliding set");
  }

  /// Where a sticking element moving toward +-h reaches it: the fraction of the load
  /// increment (+infinity if it does not move).
  double breakpoint_of(std::size_t e, double dt, double df) const {
    const std::size_t i = e / jenkin_.size();
    const JenkinElement& element = jenkin_[e % jenkin_.size()];
    const double dh = element.c * (dt - df * midpoints_[i]) / tangent(i);
    if (dh == 0.0) return std::numeric_limits<double>::infinity();
    return std::max(0.0, (std::copysign(element.h, dh) - moments_[e]) / dh);
  }

  /// The fraction (<= 1) of the load increment at the first breakpoint.
  double first_breakpoint(double dt, double df) const {
    double fraction = 1.0;
    for (std::size_t e = 0; e < moments_.size(); ++e) {
      if (!sliding_[e]) fraction = std::min(fraction, breakpoint_of(e, dt, df));
    }
    return fraction;
  }

  /// Puts the elements whose breakpoint is `fraction` exactly onto +-h (the advance
  /// may leave them an ulp short, which would make the next piece vanishingly small).
  void snap_to_bounds(const std::vector<std::size_t>& hitting, double dt, double df) {
    for (const std::size_t e : hitting) {
      const std::size_t i = e / jenkin_.size();
      moments_[e] = std::copysign(jenkin_[e % jenkin_.size()].h, dt - df * midpoints_[i]);
    }
  }

  /// Applies `fraction` of the load increment: sticking elements follow c dkappa (and are
  /// clamped exactly onto +-h at the breakpoint), sliders dissipate h |dkappa| w.
  void advance(double dt, double df, double fraction) {
    const std::size_t ne = jenkin_.size();
    for (std::size_t i = 0; i < midpoints_.size(); ++i) {
      const double dkappa = fraction * (dt - df * midpoints_[i]) / tangent(i);
      for (std::size_t j = 0; j < ne; ++j) {
        double& h = moments_[i * ne + j];
        if (sliding_[i * ne + j]) {
          dissipated_ += jenkin_[j].h * std::abs(dkappa) * width_;
        } else {
          h = std::clamp(h + jenkin_[j].c * dkappa, -jenkin_[j].h, jenkin_[j].h);
        }
      }
    }
    clamp_moment_ += fraction * dt;
    tip_force_ += fraction * df;
  }

  void follow_piece(double dphi, double dx) {
    double dt = 0.0, df = 0.0;
    consistent_load_increment(dphi, dx, dt, df);
    const double fraction = first_breakpoint(dt, df);
    std::vector<std::size_t> hitting;
    if (fraction < 1.0) {
      for (std::size_t e = 0; e < moments_.size(); ++e) {
        if (!sliding_[e] && breakpoint_of(e, dt, df) <= fraction * (1.0 + 1e-12)) hitting.push_back(e);
      }
    }
    advance(dt, df, fraction);
    snap_to_bounds(hitting, dt, df);
  }

  double length_, ei_;
  std::vector<JenkinElement> jenkin_;
  double width_;
  std::vector<double> midpoints_;
  std::vector<double> moments_;  // sections x elements
  std::vector<char> sliding_;
  double clamp_moment_ = 0.0, tip_force_ = 0.0, dissipated_ = 0.0;
};

/// One arm marched in time by velocity Verlet, its cable (a model with move_tip_to,
/// tip_force, tip_moment, dissipated, internal_state) following the tip.
template <class Numbers, class CableModel>
class MarchingArm {
 public:
  explicit MarchingArm(const Numbers& arm) : arm_(arm), cable_(arm) {}

  double tip_force() const { return cable_.tip_force(); }
  double dissipated() const { return cable_.dissipated(); }
  /// x, phi, x', phi' and the cable's memory (every H; every eta), for the periodicity test.
  std::vector<double> state() const {
    std::vector<double> s{x_, phi_, vx_, vphi_};
    s.insert(s.end(), cable_.internal_state().begin(), cable_.internal_state().end());
    return s;
  }
  /// Scales for state(): kinematics by the clamp's amplitudes, the memory by the cable's.
  std::vector<double> state_scales(double amplitude, double w) const {
    std::vector<double> s{amplitude, amplitude / arm_.length, amplitude * w, amplitude * w / arm_.length};
    const std::vector<double> memory = cable_.internal_scales();
    s.insert(s.end(), memory.begin(), memory.end());
    return s;
  }

  /// One step of dt; `clamp_acceleration_*` at the start and the end of the step.
  void step(double dt, double clamp_acceleration_now, double clamp_acceleration_next) {
    kick(0.5 * dt, clamp_acceleration_now);
    x_ += dt * vx_;
    phi_ += dt * vphi_;
    cable_.move_tip_to(phi_, x_);
    kick(0.5 * dt, clamp_acceleration_next);
  }

 private:
  /// v += h M^-1 (L x_c'' - (F, Q)).
  void kick(double h, double clamp_acceleration) {
    const double m = arm_.mass, b = arm_.offset;
    const double r0 = -m * clamp_acceleration - cable_.tip_force();
    const double r1 = m * b * clamp_acceleration - cable_.tip_moment();
    double ax = 0.0, aphi = 0.0;
    solve_2x2(m, -m * b, -m * b, arm_.inertia + m * b * b, r0, r1, ax, aphi);
    vx_ += h * ax;
    vphi_ += h * aphi;
  }

  Numbers arm_;
  CableModel cable_;
  double x_ = 0.0, phi_ = 0.0, vx_ = 0.0, vphi_ = 0.0;
};

/// Largest difference between two state vectors, component k divided by scales[k].
inline double relative_change(const std::vector<double>& a, const std::vector<double>& b,
                              const std::vector<double>& scales) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]) / scales[k]);
  return d;
}

/// The impedance of a damper (clamp_mass, arms of Numbers, each with a CableModel) at
/// clamp velocity amplitude V and frequency f (Hz), by the explicit march until
/// periodic. Throws std::runtime_error if not periodic in time.
template <class CableModel, class Damper>
ReferenceResult march_impedance(const Damper& damper, double frequency_hz, double velocity, const MarchOptions& options) {
  using Numbers = typename decltype(Damper::arms)::value_type;
  using Arm = MarchingArm<Numbers, CableModel>;
  const double w = 2.0 * std::numbers::pi * frequency_hz, amplitude = velocity / w, period = 1.0 / frequency_hz;
  const int n = options.steps_per_period;
  const double dt = period / n;
  std::vector<Arm> arms(damper.arms.begin(), damper.arms.end());
  std::vector<std::vector<double>> scales, previous_state(arms.size());
  for (const Arm& a : arms) scales.push_back(a.state_scales(amplitude, w));
  const auto clamp_acceleration = [&](long k) { return -w * w * amplitude * std::sin(w * dt * k); };
  const auto shaker_force = [&](long k) {
    double f = damper.clamp_mass * clamp_acceleration(k);
    for (const Arm& a : arms) f -= a.tip_force();
    return f;
  };

  ReferenceResult result;
  std::complex<double> previous_z;
  long k = 0;
  for (int p = 1; p <= options.max_periods; ++p) {
    double energy_start = 0.0;
    for (const Arm& a : arms) energy_start += a.dissipated();
    std::complex<double> f1;
    double work = 0.0;
    for (int j = 0; j < n; ++j, ++k) {
      const double f = shaker_force(k), t = dt * k;
      f1 += f * std::exp(std::complex<double>(0.0, -w * t));
      work += f * velocity * std::cos(w * t) * dt;
      for (Arm& a : arms) a.step(dt, clamp_acceleration(k), clamp_acceleration(k + 1));
    }
    double energy_end = 0.0;
    for (const Arm& a : arms) energy_end += a.dissipated();
    result.impedance = 2.0 * f1 / static_cast<double>(n) / velocity;
    result.power = velocity * velocity * result.impedance.real() / 2.0;
    result.dissipated_power = (energy_end - energy_start) / period;
    result.input_power = work / period;
    result.periods = p;
    double defect = std::abs(result.impedance - previous_z) / std::abs(result.impedance);
    for (std::size_t a = 0; a < arms.size(); ++a) {
      const std::vector<double> s = arms[a].state();
      if (!previous_state[a].empty()) defect = std::max(defect, relative_change(s, previous_state[a], scales[a]));
      previous_state[a] = s;
    }
    result.periodicity_defect = defect;
    previous_z = result.impedance;
    if (p >= options.min_periods && defect <= options.periodicity_tolerance) return result;
  }
  throw std::runtime_error("reference damper: not periodic after " + std::to_string(options.max_periods) +
                           " periods (defect " + std::to_string(result.periodicity_defect) + ")");
}

/// The Masing damper's impedance by the march (PathFollowingCable).
inline ReferenceResult reference_impedance(const DamperNumbers& damper, double frequency_hz, double velocity,
                                           const MarchOptions& options = {}) {
  return march_impedance<PathFollowingCable>(damper, frequency_hz, velocity, options);
}

}  // namespace stockbridge::testing::reference
