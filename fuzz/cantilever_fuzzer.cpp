// libFuzzer target: the cable's state determination (quasi-static cantilever) under
// random cables (2-12 sections; the Masing law with 0-2 Jenkin elements, optionally
// the modified Masing model, or the Bouc-Wen law) and random sequences of prescribed
// loads, tip deflections, rotations and both, committed or reverted. Invariants
// after every trial:
//   * finite kinematics and loads, and a reported residual that is finite;
//   * every section in equilibrium, ei kappa_i + sum H = T - F s_i (Bouc-Wen:
//     ei_min kappa_i + (ei_max - ei_min) chi0 eta_i), and each element within its
//     slip bound (h, or h0 + k0 cap in the modified model; Bouc-Wen: |eta| <= 1);
//   * dissipation never decreases from the committed state;
//   * the flexibility, in the work-conjugate pairs (Q, phi) and (F, x), symmetric
//     positive definite;
//   * a converged kinematic trial meets the prescribed deflection and rotation.
// Not converging is allowed (reported); an exception or a crash is a finding.

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>

#include <Eigen/LU>  // determinant()

#include "fuzz_support.hpp"
#include "stockbridge/cable/bouc_wen_cable_law.hpp"
#include "stockbridge/cable/cantilever.hpp"
#include "stockbridge/cable/masing_cable_law.hpp"

namespace {

using namespace stockbridge;

cable::CableDescription random_cable(FuzzedDataProvider& in) {
  const double length = in.ConsumeFloatingPointInRange(0.02, 1.0);
  const int sections = in.ConsumeIntegralInRange(cable::min_sections, 12);
  const double ei = in.ConsumeFloatingPointInRange(0.05, 50.0);
  if (in.ConsumeBool()) {
    const double ei_max = ei * (1.0 + in.ConsumeFloatingPointInRange(0.0, 20.0));
    return cable::CableDescription::uniform(*cable::find_section_law("bouc-wen"), length, sections, {ei, ei_max,
                                                     in.ConsumeFloatingPointInRange(1e-3, 1.0)});
  }
  std::vector<std::pair<double, double>> elements;
  const int count = in.ConsumeIntegralInRange(0, 2);
  for (int j = 0; j < count; ++j) {
    elements.emplace_back(in.ConsumeFloatingPointInRange(0.05, 500.0), in.ConsumeFloatingPointInRange(0.01, 5.0));
  }
  cable::CableDescription d = cable::CableDescription::uniform(length, sections, ei, elements);
  if (!d.jenkin.empty() && in.ConsumeBool()) d.jenkin[0].k0 = in.ConsumeFloatingPointInRange(1e-3, 5.0);
  return d;
}

/// What the invariants need of either law: each section's moment from its state, the
/// bound of each internal variable, and the largest moment the hysteresis carries.
struct LawView {
  const cable::MasingCableLaw* masing = nullptr;
  const cable::BoucWenCableLaw* bouc_wen = nullptr;
  double lever_arm_limit = 0.0;

  explicit LawView(const cable::Cable& cable)
      : masing(dynamic_cast<const cable::MasingCableLaw*>(&cable.law())),
        bouc_wen(dynamic_cast<const cable::BoucWenCableLaw*>(&cable.law())),
        lever_arm_limit(cable.description().lever_arm_limit()) {}

  std::size_t variables() const { return masing ? masing->elements() : 1; }
  double bound(std::size_t i, std::size_t j) const {
    return masing ? masing->jenkin(i)[j].h + masing->k0()[j] * lever_arm_limit : 1.0;
  }
  /// The moment the hysteresis can carry at section i: sum of slip bounds, or (EI_max - EI_min) chi0.
  double hysteretic_capacity(std::size_t i) const {
    if (bouc_wen) return (bouc_wen->ei_max(i) - bouc_wen->ei_min(i)) * bouc_wen->chi0(i);
    double total = 0.0;
    for (std::size_t j = 0; j < variables(); ++j) total += bound(i, j);
    return total;
  }
  double moment(std::size_t i, const cable::CableState& s) const {
    if (bouc_wen) {
      return bouc_wen->ei_min(i) * s.curvature[i] +
             (bouc_wen->ei_max(i) - bouc_wen->ei_min(i)) * bouc_wen->chi0(i) * s.hysteretic[i];
    }
    double m = masing->ei(i) * s.curvature[i];
    for (std::size_t j = 0; j < variables(); ++j) m += s.hysteretic[i * variables() + j];
    return m;
  }
};

/// `history`: the sum of every committed state's |T| + |F| l so far.
void check_state(const cable::Cable& cable, const cable::CableState& from, const cable::CableState& s,
                 double history) {
  const double l = cable.length();
  fuzz::require(std::isfinite(s.clamp_moment) && std::isfinite(s.tip_force) && std::isfinite(s.rotation) &&
                    std::isfinite(s.deflection) && std::isfinite(s.dissipated) && s.flexibility.allFinite(),
                "finite state");
  const LawView law(cable);
  const std::size_t n = law.variables();
  const double slip_total = law.hysteretic_capacity(0);
  // Round-off: the curvatures move by increments from state to state, so the
  // sections balance to eps times the moments they went through: the two states'
  // and every committed one's before (a small state reached back from a large one
  // keeps the large one's round-off).
  const double scale = std::abs(s.clamp_moment) + std::abs(s.tip_force) * l + std::abs(from.clamp_moment) +
                       std::abs(from.tip_force) * l + slip_total + history;
  for (std::size_t i = 0; i < cable.sections(); ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      fuzz::require(std::abs(s.hysteretic[i * n + j]) <= law.bound(i, j) * (1.0 + 1e-12), "within the slip bound");
    }
    const double moment = law.moment(i, s);
    const double expected = s.clamp_moment - s.tip_force * cable.positions()[i];
    fuzz::require(std::abs(moment - expected) <= 1e-9 * scale, "every section in equilibrium");
  }
  fuzz::require(s.dissipated >= from.dissipated - 1e-12 * (std::abs(from.dissipated) + 1e-300),
                "dissipation never decreases");
  // d(phi, x)/d(Q, F) = f [[1, l], [0, 1]] (T = Q + F l) is a compliance: symmetric, positive definite.
  Eigen::Matrix2d g = s.flexibility;
  g.col(1) += l * s.flexibility.col(0);
  const double size = std::abs(g(0, 0)) + std::abs(g(1, 1));
  fuzz::require(std::abs(g(0, 1) - g(1, 0)) <= 1e-9 * size, "symmetric compliance");
  fuzz::require(g(0, 0) > 0.0 && g(1, 1) > 0.0 && g.determinant() > 0.0, "positive definite compliance");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const cable::CableDescription description = random_cable(in);
  cable::Cantilever cantilever{cable::Cable(description)};
  const cable::Cable& c = cantilever.cable();
  const double l = c.length();
  const double slip_total = LawView(c).hysteretic_capacity(0);
  const double moment_max = 3.0 * (slip_total + 0.1);
  // Tip motions up to those of an elastic cable (its slip stiffness alone) under moment_max.
  const double phi_max = moment_max * l / c.law().slip_stiffness(0);
  const double x_max = phi_max * l;
  double history = 0.0;
  while (in.remaining_bytes() > 0) {
    const cable::CableState from = cantilever.committed();
    const int kind = in.ConsumeIntegralInRange(0, 3);
    const double a = in.ConsumeFloatingPointInRange(-1.0, 1.0);
    const double b = in.ConsumeFloatingPointInRange(-1.0, 1.0);
    if (kind == 0) {
      cantilever.set_trial_loads(a * moment_max, b * moment_max / l);
    } else {
      double x = a * x_max, phi = b * phi_max;
      cable::StateDetermination d;
      if (kind == 1) {
        d = cantilever.set_trial_deflection(x);
      } else if (kind == 2) {
        x = 0.0;
        d = cantilever.set_trial_rotation(phi);
      } else {
        d = cantilever.set_trial_tip(x, phi);
      }
      fuzz::require(std::isfinite(d.residual) && d.newton_iterations >= 0, "a finite residual is reported");
      if (d.converged()) {
        const cable::CableState& s = cantilever.trial();
        fuzz::require(std::abs(s.deflection - x) <= 1e-7 * (x_max + std::abs(from.deflection)), "deflection met");
        if (kind != 1) fuzz::require(std::abs(s.rotation - phi) <= 1e-7 * (phi_max + std::abs(from.rotation)), "rotation met");
        if (kind == 1) fuzz::require(std::abs(s.tip_moment(l)) <= 1e-9 * (std::abs(s.clamp_moment) + slip_total), "Q = 0 in (a)");
      }
    }
    check_state(c, from, cantilever.trial(), history);
    if (in.ConsumeBool()) {
      cantilever.commit();
      history += std::abs(cantilever.committed().clamp_moment) + std::abs(cantilever.committed().tip_force) * l;
    } else {
      cantilever.revert_to_last_commit();
    }
  }
  return 0;
}
