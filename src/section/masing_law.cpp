#include "stockbridge/section/masing_law.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::section {

void validate(const Jenkin& element, std::string_view name) {
  require_plausible(fmt::format("{}.c", name), element.c, "N m^2");
  require_plausible(fmt::format("{}.h", name), element.h, "N m");
}

double MasingParameters::max_stiffness() const {
  double sum = ei;
  for (const Jenkin& e : jenkin) sum += e.c;
  return sum;
}

double MasingParameters::total_slip_moment() const {
  double sum = 0.0;
  for (const Jenkin& e : jenkin) sum += e.h;
  return sum;
}

void validate(const MasingParameters& parameters) {
  require_plausible_or_zero("ei", parameters.ei, "N m^2");
  for (std::size_t j = 0; j < parameters.jenkin.size(); ++j) {
    validate(parameters.jenkin[j], fmt::format("jenkin[{}]", j));
  }
  if (parameters.ei == 0.0 && parameters.jenkin.empty()) {
    throw_invalid("ei", 0.0, "a value > 0 for a section without Jenkin elements");
  }
}

SectionState SectionState::virgin(const MasingParameters& parameters) {
  SectionState state;
  state.hysteretic.assign(parameters.jenkin.size(), 0.0);
  state.tangent = parameters.max_stiffness();
  return state;
}

void curvature_update(const MasingParameters& parameters, const SectionState& from,
                      double curvature, SectionState& to) {
  const JenkinStep step =
      jenkin_step(parameters.jenkin, from.hysteretic, curvature - from.curvature, to.hysteretic);
  to.curvature = curvature;
  to.moment = parameters.ei * curvature + step.moment;
  to.tangent = parameters.ei + step.stick_stiffness;
  to.dissipated = from.dissipated + step.dissipated;
}

void moment_update(const MasingParameters& parameters, const SectionState& from, double moment,
                   SectionState& to) {
  double dk = 0.0;
  if (!solve_curvature_increment(parameters.ei, parameters.jenkin, from.hysteretic, moment - from.moment, dk)) {
    throw NumericalError(fmt::format(
        "moment = {} N m: beyond what the section carries with ei = 0 (total slip moment {} N m)",
        format_value(moment), format_value(parameters.total_slip_moment())));
  }
  curvature_update(parameters, from, from.curvature + dk, to);
}

}  // namespace stockbridge::section
