#pragma once
// An independent reference for the span balance with several dampers per end
// (MODEL.md section 9), deliberately formulated otherwise than the library's
// (span/travelling_wave.cpp, span/polish.cpp):
//
// * Transfer matrices on the state (y, F), F = T y' the transverse force, instead of
//   (Y, Y') with the slope jump written out: the free string over a distance d,
//       [y; F] -> [cos kd, sin kd / (T k); -T k sin kd, cos kd] [y; F],
//   a damper of impedance Z, F -> F + i w Z y (T (Y'(a+) - Y'(a-)) = i w Z Y(a)),
//   from the fixed end (y, F) = (0, 1). Past the last damper, y = A' + B' and
//   F = i k T (B' - A'), scaled so that |A'| + |B'| = 1.
// * The power an end takes is summed over its dampers, Re Z_j w^2 |y_j|^2 / 2,
//   not taken from the waves.
// * The balance's amplitude: P_w - P_s - P_d(1) Y^2 sampled on its own log grid
//   (100 points a decade) and bisected, instead of TOMS 748.
// * The clamp velocities: every (end, damper) a separate unknown (no symmetry
//   used), Newton's method in log v with a forward-difference Jacobian (each
//   damper solved again at 1.0001 v), from a given start; each damper's Z from a
//   cold harmonic-balance solve (damper::solve_steady_state) at its velocity,
//   never from a tracked path.
// The wind and self-damping laws are the library's (tested on their own).

#include <cmath>
#include <complex>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/span/span.hpp"

namespace stockbridge::testing::reference_span {

/// One damper on one end: its position and its clamp impedance at a velocity.
struct Slot {
  double position = 0.0;
  std::function<std::complex<double>(double velocity)> impedance;
};

/// An end at unit antinode amplitude with the dampers' impedances z.
struct EndAtUnit {
  std::vector<std::complex<double>> y;  ///< at each damper
  double absorbed = 0.0;                ///< W at Y = 1
  double loop = 0.0;                    ///< S at Y = 1
};

class ReferenceSpan {
 public:
  ReferenceSpan(const span::Span& span, double frequency)
      : span_(span), f_(frequency), w_(2.0 * std::numbers::pi * frequency) {
    tension_ = span.tension();
    k_ = w_ / std::sqrt(tension_ / span.conductor().mass_per_length);
  }

  EndAtUnit end(const std::vector<double>& positions, const std::vector<std::complex<double>>& z) const {
    Eigen::Vector2cd state(0.0, 1.0);  // (y, F) at the fixed end
    double x = 0.0;
    EndAtUnit out;
    for (std::size_t j = 0; j < positions.size(); ++j) {
      const double d = positions[j] - x;
      Eigen::Matrix2cd field;
      field << std::cos(k_ * d), std::sin(k_ * d) / (tension_ * k_), -tension_ * k_ * std::sin(k_ * d), std::cos(k_ * d);
      state = field * state;
      Eigen::Matrix2cd point;
      point << 1.0, 0.0, std::complex<double>(0.0, w_) * z[j], 1.0;
      out.y.push_back(state(0));
      state = point * state;
      x = positions[j];
    }
    const std::complex<double> ikt(0.0, k_ * tension_);
    const std::complex<double> b = 0.5 * (state(0) + state(1) / ikt), a = 0.5 * (state(0) - state(1) / ikt);
    const double scale = 1.0 / (std::abs(a) + std::abs(b));
    for (std::size_t j = 0; j < out.y.size(); ++j) {
      out.y[j] *= scale;
      out.absorbed += 0.5 * z[j].real() * w_ * w_ * std::norm(out.y[j]);
    }
    out.loop = scale / (tension_ * k_);  // y = F0 sin(k x) / (T k) before the first damper
    return out;
  }

  /// The smallest Y where P_w - P_s - absorbed Y^2 turns from + to -, by a grid and bisection.
  double amplitude(double absorbed_at_unit) const {
    const double d = span_.conductor().diameter;
    const auto net = [&](double y) {
      return span_.wind().power(y, f_, d, span_.length()) -
             span_.self_damping().power(y, f_, span_.conductor(), span_.tension(), span_.length()) -
             absorbed_at_unit * y * y;
    };
    double lo = 1e-6 * d;
    if (net(lo) <= 0.0) return 0.0;
    const double ratio = std::pow(10.0, 0.01);
    double hi = lo * ratio;
    while (net(hi) > 0.0) {
      lo = hi;
      hi *= ratio;
      if (hi > 10.0 * d) throw std::runtime_error("reference: no balance up to 10 D");
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (net(mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  /// The state at clamp velocities v of the slots of both ends (end 1's, then end 2's).
  struct State {
    double amplitude = 0.0;
    double loop = 0.0;  ///< S at end 1
    std::vector<std::complex<double>> z;
    std::vector<double> velocities;  ///< w |y_j| Y: what v gives back
  };
  State at(const std::vector<std::vector<Slot>>& ends, const std::vector<double>& v) const {
    State s;
    std::vector<EndAtUnit> units;
    double absorbed = 0.0;
    std::size_t i = 0;
    for (const std::vector<Slot>& end : ends) {
      std::vector<double> positions;
      std::vector<std::complex<double>> z;
      for (const Slot& slot : end) {
        positions.push_back(slot.position);
        z.push_back(slot.impedance(v[i++]));
      }
      units.push_back(this->end(positions, z));
      absorbed += units.back().absorbed;
      s.z.insert(s.z.end(), z.begin(), z.end());
    }
    s.amplitude = amplitude(absorbed);
    s.loop = units.empty() ? s.amplitude : units.front().loop * s.amplitude;
    for (const EndAtUnit& u : units) {
      for (const std::complex<double>& y : u.y) s.velocities.push_back(w_ * std::abs(y) * s.amplitude);
    }
    return s;
  }

  /// Newton in log v with a forward-difference Jacobian and a backtracking line
  /// search on max |h|, from `start`; throws where it does not converge to
  /// `tolerance` (max |log G - log v|) in 30 steps. The dampers' Z solved cold
  /// carries the harmonic balance's own scatter, about 1e-7 of |Z|.
  State solve(const std::vector<std::vector<Slot>>& ends, std::vector<double> v, double tolerance = 1e-6) const {
    const auto n = static_cast<Eigen::Index>(v.size());
    const auto residual = [&](const std::vector<double>& at_v, State& s) {
      s = at(ends, at_v);
      Eigen::VectorXd h(n);
      for (Eigen::Index i = 0; i < n; ++i) h[i] = std::log(s.velocities[i] / at_v[i]);
      return h;
    };
    State s;
    Eigen::VectorXd h = residual(v, s);
    for (int step = 0; step < 30; ++step) {
      if (h.cwiseAbs().maxCoeff() <= tolerance) return s;
      Eigen::MatrixXd jacobian(n, n);
      for (Eigen::Index m = 0; m < n; ++m) {
        std::vector<double> moved = v;
        moved[m] *= std::exp(1e-4);
        State unused;
        jacobian.col(m) = (residual(moved, unused) - h) / 1e-4;
      }
      Eigen::VectorXd du = jacobian.fullPivLu().solve(-h);
      for (int halving = 0; halving < 20; ++halving, du *= 0.5) {
        std::vector<double> next = v;
        for (Eigen::Index i = 0; i < n; ++i) next[i] *= std::exp(du[i]);
        State trial;
        const Eigen::VectorXd h_next = residual(next, trial);
        if (h_next.cwiseAbs().maxCoeff() < h.cwiseAbs().maxCoeff()) {
          v = next, s = trial, h = h_next;
          break;
        }
      }
    }
    throw std::runtime_error("reference: the clamp velocities did not converge in 30 Newton steps");
  }

 private:
  const span::Span& span_;
  double f_, w_, tension_, k_;
};

/// A damper's Z from a cold harmonic-balance solve at each velocity asked (memoised).
inline std::function<std::complex<double>(double)> cold_impedance(const damper::Damper& damper, double frequency) {
  auto cache = std::make_shared<std::map<double, std::complex<double>>>();
  return [&damper, frequency, cache](double v) {
    if (const auto found = cache->find(v); found != cache->end()) return found->second;
    const damper::DamperSteadyState s =
        damper::solve_steady_state(damper, damper::Excitation::from_velocity(frequency, v), damper::SolverOptions{});
    if (!s.point.converged()) throw std::runtime_error("reference: a cold solve failed: " + s.point.failure);
    return cache->emplace(v, s.point.impedance).first->second;
  };
}

}  // namespace stockbridge::testing::reference_span
