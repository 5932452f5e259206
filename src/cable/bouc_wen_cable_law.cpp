#include "stockbridge/cable/bouc_wen_cable_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

#include <Eigen/LU>

#include "cable_sums.hpp"
#include "exp_minus_one.hpp"
#include "stockbridge/cable/cable.hpp"
#include "stockbridge/cable/cantilever.hpp"

namespace stockbridge::cable {

namespace {

/// AVX2 with FMA on this processor.
bool avx2_available() {
#if defined(__x86_64__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

}  // namespace

BoucWenCableLaw::BoucWenCableLaw(const CableDescription& description, std::span<const double> positions,
                                 BoucWenKernels kernels) {
  for (double position : positions) {
    const double s = description.profile_position(position);
    const double ei_min = description.number("ei_min").at(s);
    ei_min_.push_back(ei_min);
    hysteretic_.push_back(description.number("ei_max").at(s) - ei_min);
    chi0_.push_back(description.number("chi0").at(s));
    inverse_chi0_.push_back(1.0 / chi0_.back());
  }
  // Padded to whole groups of four sections with empty steps (apply_loads).
  const std::size_t padded = lanes_padded(ei_min_.size());
  ei_min_.resize(padded, 1.0);
  hysteretic_.resize(padded, 0.0);
  chi0_.resize(padded, 1.0);
  inverse_chi0_.resize(padded, 1.0);
  avx2_ = kernels == BoucWenKernels::best && avx2_available();
}

namespace {

// g(u) = ei_min u + ba (1 - e^-u) - target (ba = (EI_max - EI_min) a, a in [0, 2]) is
// increasing and concave in u >= 0. The sections are solved four at a time, on lanes:
// a start, then series or Halley steps until every lane's step is below 1e-3 of its u.

[[gnu::always_inline]] inline Lanes max_lanes(Lanes a, Lanes b) { return a < b ? b : a; }
[[gnu::always_inline]] inline Lanes min_lanes(Lanes a, Lanes b) { return a < b ? a : b; }
[[gnu::always_inline]] inline Lanes abs_lanes(Lanes a) { return a < 0.0 ? -a : a; }

/// The travels of four sections: u >= 0 with g(u) = 0, and e^-u - 1 there.
///
/// From any u with E = e^-u known the rest d of the way solves the same kind of
/// equation, ei_min d + ba E (1 - e^-d) = -g(u), that is d - beta (d^2/2 - d^3/6 + ...)
/// = r with r = -g / g' and beta = ba E / g' in [0, 1]. Where |r| <= 0.03 the series of
/// its inverse to r^5 gives d within about r^6 / 6 (1e-10 at 0.03), and e^-d to d^8
/// carries E along without an exponential; where |r| <= 1e-3 min(u, 1) that error is
/// below 1e-18 of u and the step ends the solve. Farther off, Halley's step
/// d = r / (1 - beta r / 2) (cubic; g'' = -ba E) and one exponential at the new u.
/// Where every open lane's |r| is within 1e-6 of min(u, 1) (the step after a series or
/// Halley step mostly is) the series to r^2 and e^-d to d^3 end the solve: the terms
/// left out are below 1e-18 of u there.
///
/// The start is the last evaluation's travel where g there (from its own exponential,
/// exact) is within 1e-3 of the target: the cantilever's Newton corrections move the
/// loads a little from the same state. Else u = 0 (E = 1), where the series takes the
/// small steps of a sampled path (r = target / g'(0) <= 0.03); else the root of the
/// quadratic Taylor model ei_min u + ba (u - u^2 / 2), or the larger of the roots of g's
/// tangent at 0 and of its asymptote ei_min u + ba (both below the root), with one
/// exponential. Any start converges to the same root: the result does not depend on it
/// beyond round-off.
[[gnu::always_inline]] inline void solve_four_travels(Lanes ei_min, Lanes ba, Lanes target, Lanes last_u,
                                                      Lanes last_decay_minus_one, Lanes& u_out,
                                                      Lanes& decay_minus_one_out) {
  const LaneMask near_last =
      abs_lanes(ei_min * last_u - ba * last_decay_minus_one - target) <= 1e-3 * target;
  const Lanes k0 = ei_min + ba;  // g'(0)
  const LaneMask far = ~near_last & (target > 0.03 * k0);
  Lanes u = near_last ? last_u : Lanes{}, decay_minus_one = near_last ? last_decay_minus_one : Lanes{};
  if (any_lane(far)) {
    const Lanes below = max_lanes(target / k0, (target - ba) / ei_min);
    const Lanes discriminant = k0 * k0 - 2.0 * ba * target;
    Lanes root = max_lanes(discriminant, Lanes{});
    for (int k = 0; k < 4; ++k) root[k] = std::sqrt(root[k]);
    const Lanes modelled = discriminant > 0.0 ? max_lanes(below, 2.0 * target / (k0 + root)) : below;
    u = far ? modelled : u;
    decay_minus_one = far ? exp_minus_one_of_nonpositive(-modelled) : decay_minus_one;
  }
  LaneMask open = u == u;  // every lane
  for (int iteration = 0; iteration < 50 && any_lane(open); ++iteration) {
    const Lanes decay = 1.0 + decay_minus_one;
    const Lanes g = ei_min * u - ba * decay_minus_one - target;
    const Lanes b = ba * decay, inverse_g1 = 1.0 / (ei_min + b);
    const Lanes r = -g * inverse_g1, beta = b * inverse_g1;
    const Lanes size = abs_lanes(r), reach = min_lanes(u, Lanes{} + 1.0);
    if (!any_lane(open & (size > 1e-6 * reach))) {
      // Every open lane has all but arrived (the step after a series or Halley step
      // mostly has): the series to r^2, its error below beta r^3 / 3 < 1e-18 u, and
      // e^-d - 1 to d^3.
      const Lanes step = r * (1.0 + 0.5 * beta * r), d = -step;
      const Lanes exp_step_minus_one = d * (1.0 + d * (0.5 + d * (1.0 / 6.0)));
      u = open ? u + step : u;
      decay_minus_one = open ? decay_minus_one + decay * exp_step_minus_one : decay_minus_one;
      break;
    }
    const LaneMask by_series = size <= 0.03;
    const LaneMask close = size <= 1e-3 * reach;
    // The inverse series' coefficients: r + c2 r^2 + ... + c5 r^5.
    const Lanes c2 = 0.5 * beta, c3 = beta * (0.5 * beta - 1.0 / 6.0),
                c4 = beta * (beta * (0.625 * beta - 5.0 / 12.0) + 1.0 / 24.0),
                c5 = beta * (beta * (beta * (0.875 * beta - 0.875) + 5.0 / 24.0) - 1.0 / 120.0);
    // Estrin's scheme: the powers of r beside the coefficients (shorter chains of
    // dependent operations than Horner's).
    const Lanes r2 = r * r;
    const Lanes series = r * ((1.0 + c2 * r) + r2 * ((c3 + c4 * r) + r2 * c5));
    // Halley's step (a division) and the exponential only where an open lane takes it.
    const bool any_halley = any_lane(open & ~by_series);
    const Lanes step = any_halley ? (by_series ? series : r / (1.0 - 0.5 * beta * r)) : series;
    const Lanes next = u + step;
    // e^-d - 1 to d^8, by Estrin's scheme.
    const Lanes d = -step, d2 = d * d, d4 = d2 * d2;
    const Lanes exp_step_minus_one =
        d * (((1.0 + 0.5 * d) + d2 * (1.0 / 6.0 + 1.0 / 24.0 * d)) +
             d4 * ((1.0 / 120.0 + 1.0 / 720.0 * d) + d2 * (1.0 / 5040.0 + 1.0 / 40320.0 * d)));
    const Lanes followed = decay_minus_one + decay * exp_step_minus_one;
    const Lanes next_decay_minus_one =
        any_halley ? (by_series ? followed : exp_minus_one_of_nonpositive(-next)) : followed;
    u = open ? next : u;
    decay_minus_one = open ? next_decay_minus_one : decay_minus_one;
    open &= ~close;
  }
  const LaneMask negative = u < 0.0;
  u_out = negative ? Lanes{} : u;
  decay_minus_one_out = negative ? Lanes{} : decay_minus_one;
}

/// A cable's sections for one evaluation: the law's numbers (each padded to whole
/// groups of four), the positions and weights, the state moved from and the one moved
/// to (n entries each), and the last evaluation's travels (padded; starts, updated).
struct SectionArrays {
  std::size_t n;
  const double *s, *w, *ei_min, *hysteretic, *chi0, *inverse_chi0;
  const double *curvature_from, *eta_from, *tangent_from;
  double *curvature, *eta, *tangent;
  double *last_u, *last_decay_minus_one;
};

/// The sums over the sections (CableSums), lane by lane, added at the end. The first
/// group sets them (step_group<true>): zeroing them first cost a string store an
/// evaluation.
struct LaneSums {
  Lanes rotation, moment_of_rotation, dissipated;  // sum w kappa, sum w s kappa
  Lanes compliance[3];                             // sum w s^p / k, p = 0, 1, 2
  Lanes change[4];                                 // sum w c s^p, p = 0 .. 3
};

/// sum += term, or sum = term for the first group.
template <bool kFirst>
[[gnu::always_inline]] inline void accumulate(Lanes& sum, Lanes term) {
  if constexpr (kFirst) {
    sum = term;
  } else {
    sum += term;
  }
}

/// Four sections' steps: the positions, weights and states at `at` (the cable's from
/// section i on, or a padded copy of its last group), the law's numbers at i.
struct GroupArrays {
  const double *s, *w, *curvature_from, *eta_from, *tangent_from;
  double *curvature, *eta, *tangent;
};

template <bool kFirst>
[[gnu::always_inline]] inline void step_group(const SectionArrays& a, std::size_t i, const GroupArrays& at,
                                              double d_clamp_moment, double d_tip_force, LaneSums& sums) {
  const Lanes s = load_lanes(at.s), w = load_lanes(at.w), eta_from = load_lanes(at.eta_from);
  const Lanes hysteretic = load_lanes(a.hysteretic + i), chi0 = load_lanes(a.chi0 + i);
  const Lanes ei_min = load_lanes(a.ei_min + i);
  const Lanes excess = d_clamp_moment - d_tip_force * s;
  const Lanes sign = excess > 0.0 ? Lanes{} + 1.0 : Lanes{} - 1.0;
  const Lanes slack = 1.0 - sign * eta_from;  // a = 1 - sign(excess) eta_from, in [0, 2]
  const Lanes ba = hysteretic * slack;
  const Lanes target = abs_lanes(excess) * load_lanes(a.inverse_chi0 + i);
  Lanes u, decay_minus_one;
  solve_four_travels(ei_min, ba, target, load_lanes(a.last_u + i), load_lanes(a.last_decay_minus_one + i), u,
                     decay_minus_one);
  store_lanes(a.last_u + i, u);
  store_lanes(a.last_decay_minus_one + i, decay_minus_one);
  // The new state (a section without excess keeps its own, tangent included).
  const LaneMask moves = excess != 0.0;
  const Lanes decay = 1.0 + decay_minus_one;
  const Lanes curvature = load_lanes(at.curvature_from) + sign * chi0 * u;
  const Lanes tangent = moves ? ei_min + ba * decay : load_lanes(at.tangent_from);
  store_lanes(at.curvature, curvature);
  store_lanes(at.eta, moves ? sign * (1.0 - slack * decay) : eta_from);
  store_lanes(at.tangent, tangent);
  // (EI_max - EI_min) chi0 int eta^2 |d chi| along the stretch (section::bouc_wen_update),
  // with e^-2u - 1 = (e^-u - 1)(e^-u + 1). The integral of a square is not negative;
  // the terms cancel for a short stretch, to round-off of u, which the bound removes.
  accumulate<kFirst>(
      sums.dissipated,
      w * hysteretic * chi0 * chi0 *
          max_lanes(u + decay_minus_one * (2.0 * slack - 0.5 * slack * slack * (2.0 + decay_minus_one)), Lanes{}));
  const Lanes compliance = 1.0 / tangent;
  const Lanes g = w * compliance;
  const Lanes w_curvature = w * curvature;
  accumulate<kFirst>(sums.rotation, w_curvature);
  accumulate<kFirst>(sums.moment_of_rotation, w_curvature * s);
  accumulate<kFirst>(sums.compliance[0], g);
  accumulate<kFirst>(sums.compliance[1], g * s);
  accumulate<kFirst>(sums.compliance[2], g * s * s);
  // w d^2 kappa / dM^2 = w sign (k - EI_min) / (chi0 k^3): dk/dchi = -sign (k - EI_min) / chi0.
  const Lanes c0 = moves ? sign * (tangent - ei_min) * load_lanes(a.inverse_chi0 + i) * g * compliance * compliance
                         : Lanes{};
  const Lanes c1 = c0 * s, c2 = c1 * s;
  accumulate<kFirst>(sums.change[0], c0);
  accumulate<kFirst>(sums.change[1], c1);
  accumulate<kFirst>(sums.change[2], c2);
  accumulate<kFirst>(sums.change[3], c2 * s);
}

/// The last group of a cable whose count is not a multiple of four, padded with empty
/// steps of weight 0.
template <bool kFirst>
[[gnu::always_inline]] inline void step_last_group(const SectionArrays& a, std::size_t i, double d_clamp_moment,
                                                   double d_tip_force, LaneSums& sums) {
  const std::size_t count = a.n - i;
  double s[4] = {}, w[4] = {}, curvature_from[4] = {}, eta_from[4] = {}, tangent_from[4] = {1.0, 1.0, 1.0, 1.0};
  double curvature[4], eta[4], tangent[4];
  auto copy_in = [&](const double* from, double* to) { std::copy(from + i, from + a.n, to); };
  copy_in(a.s, s);
  copy_in(a.w, w);
  copy_in(a.curvature_from, curvature_from);
  copy_in(a.eta_from, eta_from);
  copy_in(a.tangent_from, tangent_from);
  step_group<kFirst>(a, i, {s, w, curvature_from, eta_from, tangent_from, curvature, eta, tangent}, d_clamp_moment,
                     d_tip_force, sums);
  std::copy(curvature, curvature + count, a.curvature + i);
  std::copy(eta, eta + count, a.eta + i);
  std::copy(tangent, tangent + count, a.tangent + i);
}

/// Every section's monotone step from its state under the moment excess
/// d_clamp_moment - d_tip_force s, four sections at a time, and the sums the tip
/// kinematics and flexibility take.
[[gnu::always_inline]] inline CableSums step_sections(const SectionArrays& a, double d_clamp_moment,
                                                      double d_tip_force, double length) {
  auto whole_group = [&](std::size_t i) {
    return GroupArrays{a.s + i,         a.w + i,   a.curvature_from + i, a.eta_from + i, a.tangent_from + i,
                       a.curvature + i, a.eta + i, a.tangent + i};
  };
  LaneSums sums;
  if (a.n < 4) {
    step_last_group<true>(a, 0, d_clamp_moment, d_tip_force, sums);
  } else {
    step_group<true>(a, 0, whole_group(0), d_clamp_moment, d_tip_force, sums);
    std::size_t i = 4;
    for (; i + 4 <= a.n; i += 4) step_group<false>(a, i, whole_group(i), d_clamp_moment, d_tip_force, sums);
    if (i < a.n) step_last_group<false>(a, i, d_clamp_moment, d_tip_force, sums);
  }
  // The arm l - s multiplied out: sum w (l - s) f = l sum w f - sum w s f.
  auto total = [](const Lanes& v) { return (v[0] + v[1]) + (v[2] + v[3]); };
  CableSums cable_sums;
  const double rotation = total(sums.rotation);
  cable_sums.rotation = rotation;
  cable_sums.deflection = length * rotation - total(sums.moment_of_rotation);
  cable_sums.dissipated = total(sums.dissipated);
  const double g0 = total(sums.compliance[0]), g1 = total(sums.compliance[1]), g2 = total(sums.compliance[2]);
  cable_sums.flexibility << g0, -g1, length * g0 - g1, -(length * g1 - g2);
  double c[4];
  for (int p = 0; p < 4; ++p) c[p] = total(sums.change[p]);
  for (int p = 0; p < 3; ++p) {
    cable_sums.flexibility_change(0, p) = c[p];
    cable_sums.flexibility_change(1, p) = length * c[p] - c[p + 1];
  }
  return cable_sums;
}

// The two builds of the section loop: for the x86-64 baseline (two lanes a register),
// and for processors with AVX2 and FMA (four).
CableSums step_sections_baseline(const SectionArrays& a, double d_clamp_moment, double d_tip_force, double length) {
  return step_sections(a, d_clamp_moment, d_tip_force, length);
}
#if defined(__x86_64__)
__attribute__((target("arch=x86-64-v3"))) CableSums step_sections_avx2(const SectionArrays& a, double d_clamp_moment,
                                                                       double d_tip_force, double length) {
  return step_sections(a, d_clamp_moment, d_tip_force, length);
}
#endif

}  // namespace

BoucWenTravel bouc_wen_travel(double ei_min, double hysteretic, double chi0, double eta_from, double excess,
                              const BoucWenTravel& start) {
  const double sign = excess > 0.0 ? 1.0 : -1.0;
  const double ba = hysteretic * (1.0 - sign * eta_from);
  const double target = std::abs(excess) / chi0;
  // One lane of a group; the others solve the empty step (u = 0).
  Lanes u, decay_minus_one;
  solve_four_travels(Lanes{} + ei_min, Lanes{ba}, Lanes{target}, Lanes{start.u}, Lanes{start.decay_minus_one}, u,
                     decay_minus_one);
  return {u[0], decay_minus_one[0]};
}

void BoucWenCableLaw::apply_loads(const Cable& cable, const CableState& from, double clamp_moment, double tip_force,
                                  CableState& to, CableWorkspace& workspace) const {
  const std::size_t padded = ei_min_.size();
  if (workspace.travel.size() != 2 * padded) workspace.travel.assign(2 * padded, 0.0);
  const SectionArrays arrays{cable.sections(),
                             cable.positions().data(),
                             cable.weights().data(),
                             ei_min_.data(),
                             hysteretic_.data(),
                             chi0_.data(),
                             inverse_chi0_.data(),
                             from.curvature.data(),
                             from.hysteretic.data(),
                             from.tangent.data(),
                             to.curvature.data(),
                             to.hysteretic.data(),
                             to.tangent.data(),
                             workspace.travel.data(),
                             workspace.travel.data() + padded};
  const double d_clamp_moment = clamp_moment - from.clamp_moment, d_tip_force = tip_force - from.tip_force;
#if defined(__x86_64__)
  const CableSums sums = avx2_ ? step_sections_avx2(arrays, d_clamp_moment, d_tip_force, cable.length())
                               : step_sections_baseline(arrays, d_clamp_moment, d_tip_force, cable.length());
#else
  const CableSums sums = step_sections_baseline(arrays, d_clamp_moment, d_tip_force, cable.length());
#endif
  sums.store(clamp_moment, tip_force, from, to);
}

double BoucWenCableLaw::internal_change(const CableState& start, const CableState& end) const {
  double change = 0.0;
  for (std::size_t i = 0; i < start.hysteretic.size(); ++i) {
    change = std::max(change, std::abs(end.hysteretic[i] - start.hysteretic[i]));
  }
  return change;
}

std::size_t BoucWenCableLaw::periodic_coordinates(const Cable& cable) const { return cable.sections() + 2; }

void BoucWenCableLaw::coordinates(const CableState& state, Eigen::VectorXd& z) const {
  z.resize(static_cast<Eigen::Index>(state.hysteretic.size()) + 2);
  z(0) = state.clamp_moment;
  z(1) = state.tip_force;
  for (std::size_t i = 0; i < state.hysteretic.size(); ++i) z(static_cast<Eigen::Index>(i) + 2) = state.hysteretic[i];
}

// M_i = T - F s_i = EI_min kappa_i + (EI_max - EI_min) chi0 eta_i: at given loads and
// eta the curvature follows, and with it the tip kinematics (phi, x) = sum w_i
// kappa_i [1, l - s_i].
bool BoucWenCableLaw::shift(const Cable& cable, CableState& state, const Eigen::VectorXd& dz) const {
  const std::size_t n = cable.sections();
  if (!dz.allFinite()) return false;
  const double d_clamp_moment = dz(0), d_tip_force = dz(1);
  state.clamp_moment += d_clamp_moment;
  state.tip_force += d_tip_force;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = cable.positions()[i], w = cable.weights()[i];
    // eta within [-1, 1]: a section the step would carry beyond saturates.
    const double d_eta = std::clamp(state.hysteretic[i] + dz(static_cast<Eigen::Index>(i) + 2), -1.0, 1.0) -
                         state.hysteretic[i];
    const double d_curvature = (d_clamp_moment - d_tip_force * s - hysteretic_[i] * chi0_[i] * d_eta) / ei_min_[i];
    state.hysteretic[i] += d_eta;
    state.curvature[i] += d_curvature;
    state.rotation += w * d_curvature;
    state.deflection += w * (cable.length() - s) * d_curvature;
  }
  return true;
}


}  // namespace stockbridge::cable

// The Bouc-Wen law's descriptor (section_law_descriptor.hpp).

#include <fmt/format.h>

#include "stockbridge/cable/cable_description.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/section/bouc_wen_section.hpp"

namespace stockbridge::cable {

namespace {

constexpr LawNumber kBoucWenNumbers[] = {
    {"ei_min", "N m^2", "the free wires' (asymptotic) stiffness EI_min", typical::ei, 3, StartRole::stiffness,
     FitScale::logarithmic},
    {"ei_max", "N m^2", "the no-slip (initial) stiffness EI_max", typical::ei, 3, StartRole::stiffness,
     FitScale::logarithmic},
    {"chi0", "1/m", "the curvature scale chi0 of the transition", typical::bouc_wen_chi0, -2, StartRole::slip,
     FitScale::logarithmic},
};

/// ei_max >= ei_min everywhere: both piecewise linear and held beyond their ends, so
/// their difference is too, with its corners at either table's points.
void require_ei_max_at_least_ei_min(const Profile& ei_min, const Profile& ei_max) {
  std::vector<double> corners(ei_min.positions().begin(), ei_min.positions().end());
  corners.insert(corners.end(), ei_max.positions().begin(), ei_max.positions().end());
  for (double s : corners) {
    if (ei_max.at(s) < ei_min.at(s)) {
      throw InvalidParameter("ei_max", fmt::format(" = {} at s = {} m: below ei_min = {} N m^2 there (EI_max is the "
                                                   "no-slip stiffness, EI_min the free wires')",
                                                   ei_max.at(s), s, ei_min.at(s)));
    }
  }
}

section::BoucWenParameters bouc_wen_parameters(const std::vector<double>& values) {
  return {values.at(0), values.at(1), values.at(2)};
}

struct BoucWenLaw final : SectionLawDescriptor {
  std::string_view name() const override { return "bouc-wen"; }
  std::string_view title() const override { return "Bouc-Wen"; }
  int order() const override { return 1; }
  std::span<const LawNumber> numbers() const override { return kBoucWenNumbers; }

  void validate(const CableDescription& d) const override {
    SectionLawDescriptor::validate(d);
    require_ei_max_at_least_ei_min(d.number("ei_min"), d.number("ei_max"));
  }

  std::string summary(const CableDescription& c, std::string (*number)(double)) const override {
    return fmt::format("Bouc-Wen law, EI at the clamp {} N m² slipping, {} N m² sticking, chi0 {} 1/m",
                       number(c.number("ei_min").at(0.0)), number(c.number("ei_max").at(0.0)),
                       number(c.number("chi0").at(0.0)));
  }

  std::shared_ptr<const CableLaw> make(const CableDescription& d, std::span<const double> positions,
                                       std::span<const double>) const override {
    return std::make_shared<BoucWenCableLaw>(d, positions);
  }

  std::unique_ptr<section::SectionLaw> section(const std::vector<double>& values) const override {
    return std::make_unique<section::BoucWenSection>(bouc_wen_parameters(values));
  }

  std::vector<double> moments(const std::vector<double>& values, std::span<const double> curvature) const override {
    const section::BoucWenParameters parameters = bouc_wen_parameters(values);
    section::BoucWenState state = section::BoucWenState::virgin(parameters);
    std::vector<double> out;
    out.reserve(curvature.size());
    for (const double kappa : curvature) {
      state = section::bouc_wen_update(parameters, state, kappa);
      out.push_back(state.moment);
    }
    return out;
  }

  /// Local: EI_min from the slope at the extremes, EI_max from the slope after the
  /// reversals, chi0 from the half-height of the loop about the EI_min line over
  /// EI_max - EI_min; the hysteretic stiffness and chi0 scaled. Global, from the
  /// four-step Masing cable: EI_min its ei (slipping), EI_max its ei + c (sticking),
  /// chi0 its slip curvature h / c (where the hysteretic moment (EI_max - EI_min)
  /// chi0 tanh(chi_a / chi0) levels off at about h); EI_min and chi0 varied.
  std::vector<std::vector<double>> starts(const MasingEstimate& e, FitKind kind) const override {
    std::vector<std::vector<double>> x;
    if (kind == FitKind::local) {
      const double ei_min = e.ei, hysteretic = e.c;
      for (const auto& [b_factor, chi0_factor] :
           {std::pair{1.0, 1.0}, std::pair{0.5, 1.0}, std::pair{2.0, 1.0}, std::pair{1.0, 0.5}, std::pair{1.0, 2.0}}) {
        const double b = b_factor * hysteretic;
        x.push_back({ei_min, ei_min + b, chi0_factor * e.h / hysteretic});
      }
      return x;
    }
    for (const auto& [ei_factor, chi0_factor] : {std::pair{1.0, 1.0}, std::pair{1.0, 0.5}, std::pair{1.0, 2.0},
                                                 std::pair{0.7, 1.0}, std::pair{1.4, 1.0}}) {
      x.push_back({e.ei * ei_factor, e.ei * ei_factor + e.c, chi0_factor * e.h / e.c});
    }
    return x;
  }

  /// log EI_min, log (EI_max - EI_min), log chi0: EI_max > EI_min throughout.
  std::vector<double> pack(const std::vector<double>& v) const override {
    return {std::log(v.at(0)), std::log(v.at(1) - v.at(0)), std::log(v.at(2))};
  }
  std::vector<double> unpack(const std::vector<double>& x) const override {
    const double ei_min = std::exp(x.at(0));
    return {ei_min, ei_min + std::exp(x.at(1)), std::exp(x.at(2))};
  }

  /// Fitted in logarithms each: ei_max > ei_min.
  void check_start(const std::vector<double>& v, const std::string& prefix) const override {
    if (!(v.at(1) > v.at(0))) {
      throw InvalidParameter(prefix + "ei_max", fmt::format(" = {} N m^2: expected a starting value above ei_min = {} "
                                                            "N m^2 (a cable without hysteresis leaves chi0 undetermined)",
                                                            format_value(v.at(1)), format_value(v.at(0))));
    }
  }
};

}  // namespace

const SectionLawDescriptor& bouc_wen_section_law() {
  static const BoucWenLaw law;
  return law;
}

}  // namespace stockbridge::cable
