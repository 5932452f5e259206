// libFuzzer target: the exact Masing section law under random parameters and a
// random path of curvature- and moment-driven trials, commits and reverts.
// Invariants after every trial:
//   * every value finite; each element's moment within its slip bound, |H_j| <= h_j;
//   * M = ei kappa + sum H_j, so |M - ei kappa| <= sum h_j;
//   * the tangent between ei and ei + sum c_j;
//   * dissipation never decreases from the committed state;
//   * the two drives are inverse: the moment-driven update to a curvature-driven
//     trial's moment gives back its curvature (ei > 0), and a moment-driven trial
//     carries the moment asked for.

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>

#include "fuzz_support.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/section/masing_law.hpp"
#include "stockbridge/section/masing_section.hpp"

namespace {

using namespace stockbridge;

section::MasingParameters random_parameters(FuzzedDataProvider& in) {
  section::MasingParameters p;
  p.ei = in.ConsumeBool() ? 0.0 : in.ConsumeFloatingPointInRange(1e-3, 100.0);
  const int elements = in.ConsumeIntegralInRange(0, 4);
  for (int j = 0; j < elements; ++j) {
    p.jenkin.push_back({in.ConsumeFloatingPointInRange(1e-3, 1e3), in.ConsumeFloatingPointInRange(1e-3, 10.0)});
  }
  if (p.jenkin.empty() && p.ei == 0.0) p.ei = 1.0;
  return p;
}

void check_state(const section::MasingParameters& p, const section::SectionState& from,
                 const section::SectionState& s, double moment_scale) {
  fuzz::require(std::isfinite(s.curvature) && std::isfinite(s.moment) && std::isfinite(s.tangent) &&
                    std::isfinite(s.dissipated),
                "finite state");
  double sum = p.ei * s.curvature;
  for (std::size_t j = 0; j < p.jenkin.size(); ++j) {
    fuzz::require(std::abs(s.hysteretic[j]) <= p.jenkin[j].h, "|H_j| <= h_j");
    sum += s.hysteretic[j];
  }
  fuzz::require(std::abs(s.moment - sum) <= 1e-12 * moment_scale, "M = ei kappa + sum H");
  fuzz::require(s.tangent >= p.ei && s.tangent <= p.max_stiffness() * (1.0 + 1e-15), "ei <= tangent <= ei + sum c");
  fuzz::require(s.dissipated >= from.dissipated, "dissipation never decreases");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const section::MasingParameters p = random_parameters(in);
  section::MasingSection law(p);
  // Curvatures up to 20 times the largest slip curvature h/c (or 1/m without elements).
  double slip_curvature = 1.0;
  for (const section::Jenkin& e : p.jenkin) slip_curvature = std::max(slip_curvature, e.h / e.c);
  const double kappa_max = 20.0 * slip_curvature;
  const double moment_max = p.ei * kappa_max + 1.5 * p.total_slip_moment();
  section::SectionState inverse = law.committed_state();
  while (in.remaining_bytes() > 0) {
    const section::SectionState from = law.committed_state();
    // Round-off: the elements' moments move by c times a curvature difference of
    // values up to |kappa|, so their sum is exact to eps (ei + sum c) |kappa|.
    const double scale =
        p.max_stiffness() * (std::abs(from.curvature) + kappa_max) + p.total_slip_moment() + std::abs(from.moment);
    if (in.ConsumeBool()) {
      const double kappa = in.ConsumeFloatingPointInRange(-kappa_max, kappa_max);
      law.set_trial_curvature(kappa);
      check_state(p, from, law.trial_state(), scale);
      if (p.ei > 0.0) {
        section::moment_update(p, from, law.moment(), inverse);
        const double tolerance = 1e-9 * (std::abs(kappa) + std::abs(from.curvature) + slip_curvature);
        fuzz::require(std::abs(inverse.curvature - kappa) <= tolerance, "moment drive inverts curvature drive");
      }
    } else {
      const double moment = in.ConsumeFloatingPointInRange(-moment_max, moment_max);
      try {
        law.set_trial_moment(moment);
      } catch (const NumericalError&) {
        // Only a section without elastic stiffness cannot carry a moment, beyond its slip moments.
        fuzz::require(p.ei == 0.0 && std::abs(moment) >= p.total_slip_moment() * (1.0 - 1e-12),
                      "moment drive fails only beyond sum h with ei = 0");
        continue;
      }
      check_state(p, from, law.trial_state(), scale);
      fuzz::require(std::abs(law.moment() - moment) <= 1e-12 * scale, "moment drive carries the moment asked for");
    }
    if (in.ConsumeBool()) {
      law.commit();
    } else {
      law.revert_to_last_commit();
    }
  }
  return 0;
}
