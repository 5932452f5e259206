#include "stockbridge/section/bouc_wen_section.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::section {

void validate(const BoucWenParameters& p) {
  require_positive("ei_min", p.ei_min, "N m^2");
  require_positive("ei_max", p.ei_max, "N m^2");
  require_positive("chi0", p.chi0, "1/m");
  if (p.ei_max < p.ei_min) {
    throw InvalidParameter("ei_max", fmt::format(" = {}: below ei_min = {} N m^2 (EI_max is the no-slip stiffness, "
                                                 "EI_min the free wires')",
                                                 p.ei_max, p.ei_min));
  }
}

BoucWenState BoucWenState::virgin(const BoucWenParameters& p) { return {0.0, 0.0, 0.0, p.ei_max, 0.0, 1}; }

BoucWenState bouc_wen_update(const BoucWenParameters& p, const BoucWenState& from, double curvature) {
  const double hysteretic = p.ei_max - p.ei_min;
  BoucWenState to = from;
  to.curvature = curvature;
  const double step = curvature - from.curvature;
  if (step != 0.0) to.direction = step > 0.0 ? 1 : -1;
  const double s = static_cast<double>(to.direction);
  // Along the stretch, s eta = 1 - a exp(-u): u >= 0 the curvature travelled over chi0.
  const double a = 1.0 - s * from.eta;
  const double u = std::abs(step) / p.chi0;
  const double decay = std::exp(-u);
  to.eta = s * (1.0 - a * decay);
  to.moment = p.ei_min * curvature + hysteretic * p.chi0 * to.eta;
  to.tangent = p.ei_min + hysteretic * (1.0 - s * to.eta);
  // D += (EI_max - EI_min) chi0 int eta^2 |d chi| = (EI_max - EI_min) chi0^2 int (1 - a e^-u)^2 du.
  const double one_minus_decay = -std::expm1(-u);
  const double one_minus_decay2 = -std::expm1(-2.0 * u);
  // The integral of a square: not negative, though its terms cancel to round-off of u
  // over a short stretch.
  to.dissipated = from.dissipated + hysteretic * p.chi0 * p.chi0 *
                                        std::max(u - 2.0 * a * one_minus_decay + 0.5 * a * a * one_minus_decay2, 0.0);
  return to;
}

namespace {
BoucWenParameters validated_bouc_wen(BoucWenParameters parameters) {
  validate(parameters);
  return parameters;
}
}  // namespace

BoucWenSection::BoucWenSection(BoucWenParameters parameters)
    : CommittedSectionLaw(BoucWenState::virgin(validated_bouc_wen(parameters))), parameters_(std::move(parameters)) {}

void BoucWenSection::set_trial_curvature(double curvature) {
  require_finite("curvature", curvature, "1/m");
  state_.trial() = bouc_wen_update(parameters_, state_.committed(), curvature);
}

}  // namespace stockbridge::section
