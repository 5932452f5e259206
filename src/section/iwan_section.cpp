#include "stockbridge/section/iwan_section.hpp"

#include <algorithm>
#include <cmath>

#include "stockbridge/core/error.hpp"

namespace stockbridge::section {

void validate(const IwanParameters& p) {
  require_plausible("ei", p.ei, "N m^2");
  require_plausible("slip_moment", p.slip_moment, "N m");
  require_plausible("tangent_stiffness", p.tangent_stiffness, "N m^2");
  if (!(std::isfinite(p.exponent) && p.exponent > -1.0 && p.exponent <= 0.0)) {
    throw_invalid("exponent", p.exponent, "a value > -1 and <= 0");
  }
  if (!(std::isfinite(p.beta) && p.beta >= 0.0 && p.beta <= 1e6)) throw_invalid("beta", p.beta, "a value from 0 to 1e6");
}

IwanBackbone::IwanBackbone(const IwanParameters& p) : chi(p.exponent), slip_moment(p.slip_moment) {
  const double c = p.beta + (chi + 1.0) / (chi + 2.0);
  phi_max = p.slip_moment * (1.0 + p.beta) / (p.tangent_stiffness * c);
  r = p.slip_moment * (chi + 1.0) / (std::pow(phi_max, chi + 2.0) * c);
  s = p.slip_moment * p.beta / (phi_max * c);
  phi_power = std::pow(phi_max, chi + 1.0);
}

double IwanBackbone::moment(double u) const {
  if (u >= phi_max) return slip_moment;
  const double u1 = std::pow(u, chi + 1.0);
  return r * u * u1 / (chi + 2.0) + r * u * (phi_power - u1) / (chi + 1.0) + s * u;
}

double IwanBackbone::tangent(double u) const {
  if (u >= phi_max) return 0.0;
  return r * (phi_power - std::pow(u, chi + 1.0)) / (chi + 1.0) + s;
}

double IwanBackbone::dissipation(double v) const {
  const double k = (chi + 2.0) * (chi + 3.0);
  if (v < phi_max) return r * std::pow(v, chi + 3.0) / k;
  return r * phi_power * phi_max * phi_max / k + slip_moment * (v - phi_max);
}

namespace {

std::size_t count_of(std::span<const double> memory) { return iwan_reversals(memory); }

/// The branch the memory is on: the virgin curve, or the branch from its last
/// reversal, in direction d, up to its target (the reversal before, or -kappa_1).
struct Branch {
  bool virgin = true;
  double kappa_r = 0.0, moment_r = 0.0;
  int direction = 0;
  double target_kappa = 0.0, target_moment = 0.0;
};

Branch branch_of(std::span<const double> memory) {
  const std::size_t k = count_of(memory);
  Branch b;
  if (k == 0) return b;
  b.virgin = false;
  b.kappa_r = memory[2 * k - 2];
  b.moment_r = memory[2 * k - 1];
  if (k == 1) {
    b.direction = b.kappa_r > 0.0 ? -1 : 1;
    b.target_kappa = -b.kappa_r;
    b.target_moment = -b.moment_r;
  } else {
    b.target_kappa = memory[2 * k - 4];
    b.target_moment = memory[2 * k - 3];
    b.direction = b.target_kappa > b.kappa_r ? 1 : -1;
  }
  return b;
}

double moment_on(const IwanBackbone& bb, const Branch& b, double kappa) {
  if (b.virgin) return std::copysign(bb.moment(std::abs(kappa)), kappa);
  return b.moment_r + b.direction * 2.0 * bb.moment(0.5 * std::abs(kappa - b.kappa_r));
}

double tangent_on(const IwanBackbone& bb, const Branch& b, double kappa) {
  return b.virgin ? bb.tangent(std::abs(kappa)) : bb.tangent(0.5 * std::abs(kappa - b.kappa_r));
}

/// The energy dissipated along the branch from its start to kappa.
double energy_on(const IwanBackbone& bb, const Branch& b, double kappa) {
  return b.virgin ? bb.dissipation(std::abs(kappa)) : 2.0 * bb.dissipation(0.5 * std::abs(kappa - b.kappa_r));
}

/// Relative: a path this close to a branch's target has reached it.
constexpr double kJoinTolerance = 1e-10;

void push(std::span<double> memory, double kappa, double moment) {
  std::size_t k = count_of(memory);
  if (k == kIwanMemory) {  // full: the oldest two reversals forgotten
    std::copy(memory.begin() + 4, memory.end(), memory.begin());
    k -= 2;
  }
  memory[2 * k] = kappa != 0.0 ? kappa : 1e-300;
  memory[2 * k + 1] = moment;
  if (2 * k + 2 < memory.size()) memory[2 * k + 2] = 0.0;
}

void pop(std::span<double> memory, std::size_t n) {
  const std::size_t k = count_of(memory) - n;
  for (std::size_t j = 2 * k; j < 2 * (k + n); ++j) memory[j] = 0.0;
}

/// x >= 0 where ei x + scale B(x / scale) = rhs, by Newton from x0 (whose value is not
/// above rhs): the left side is increasing and concave, so the iterates rise to the root.
double solve_branch(const IwanBackbone& bb, double ei, double scale, double rhs, double x0) {
  double x = std::max(x0, 0.0);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double u = x / scale;
    double moment = bb.slip_moment, tangent = 0.0;
    if (u < bb.phi_max) {  // B and B' with one power
      const double u1 = std::pow(u, bb.chi + 1.0);
      moment = bb.r * u * u1 / (bb.chi + 2.0) + bb.r * u * (bb.phi_power - u1) / (bb.chi + 1.0) + bb.s * u;
      tangent = bb.r * (bb.phi_power - u1) / (bb.chi + 1.0) + bb.s;
    }
    const double f = ei * x + scale * moment - rhs;
    const double dx = -f / (ei + tangent);
    x = std::max(x + dx, 0.0);
    if (!(std::abs(dx) > 1e-15 * x)) break;
  }
  return x;
}

}  // namespace

std::size_t iwan_reversals(std::span<const double> memory) {
  std::size_t k = 0;
  while (2 * k < memory.size() && memory[2 * k] != 0.0) ++k;
  return k;
}

double iwan_moment(const IwanBackbone& backbone, std::span<const double> memory, double curvature) {
  return moment_on(backbone, branch_of(memory), curvature);
}

IwanStep iwan_step(const IwanBackbone& bb, double ei, std::span<double> memory, double from, double target,
                   bool by_moment) {
  const auto value = [&](double kappa, double moment) { return by_moment ? ei * kappa + moment : kappa; };
  Branch b = branch_of(memory);
  const double moment_from = moment_on(bb, b, from);
  const double start = value(from, moment_from);
  if (target == start) return {from, moment_from, tangent_on(bb, b, from), 0.0};
  const int delta = target > start ? 1 : -1;
  // A reversal at `from` (where the branch turns back exactly at its reversal, the
  // branch before goes on).
  if (b.virgin) {
    if (from != 0.0 && (from > 0.0) != (delta > 0)) push(memory, from, moment_from);
  } else if (b.direction != delta) {
    if (from == b.kappa_r) {
      pop(memory, 1);
    } else {
      push(memory, from, moment_from);
    }
  }
  double kappa = from, dissipated = 0.0;
  for (;;) {
    b = branch_of(memory);
    const double at_target = b.virgin ? 0.0 : value(b.target_kappa, b.target_moment);
    if (!b.virgin && (target - at_target) * delta > -kJoinTolerance * (std::abs(at_target) + std::abs(target))) {
      // Past the branch's target: it joins the branch before it. A path that comes
      // back to the target within round-off closes the loop too (its moment is the
      // same either way), so that a periodic path's peaks, reached again within
      // round-off of where they were, give the same memory each period.
      dissipated += energy_on(bb, b, b.target_kappa) - energy_on(bb, b, kappa);
      kappa = b.target_kappa;
      pop(memory, count_of(memory) == 1 ? 1 : 2);
      continue;
    }
    double end = target;
    if (by_moment) {
      if (b.virgin) {
        end = delta * solve_branch(bb, ei, 1.0, delta * target, std::abs(kappa));
      } else {
        const double rhs = delta * (target - ei * b.kappa_r - b.moment_r);
        end = b.kappa_r + delta * solve_branch(bb, ei, 2.0, rhs, std::abs(kappa - b.kappa_r));
      }
    }
    dissipated += energy_on(bb, b, end) - energy_on(bb, b, kappa);
    return {end, moment_on(bb, b, end), tangent_on(bb, b, end), dissipated};
  }
}

namespace {
IwanState virgin_iwan(const IwanParameters& p) {
  validate(p);
  IwanState state;
  state.tangent = p.ei + p.tangent_stiffness;
  return state;
}
}  // namespace

IwanSection::IwanSection(IwanParameters parameters)
    : CommittedSectionLaw(virgin_iwan(parameters)), parameters_(parameters), backbone_(parameters) {}

void IwanSection::set_trial_curvature(double curvature) {
  require_finite("curvature", curvature, "1/m");
  IwanState& trial = state_.trial();
  const IwanState& committed = state_.committed();
  trial.memory = committed.memory;
  const IwanStep step = iwan_step(backbone_, parameters_.ei, trial.memory, committed.curvature, curvature, false);
  trial.curvature = curvature;
  trial.moment = parameters_.ei * curvature + step.moment;
  trial.tangent = parameters_.ei + step.tangent;
  trial.dissipated = committed.dissipated + step.dissipated;
}

}  // namespace stockbridge::section
