#include "stockbridge/section/masing_section.hpp"

#include <utility>

#include "stockbridge/core/error.hpp"

namespace stockbridge::section {

namespace {
MasingParameters validated(MasingParameters parameters) {
  validate(parameters);
  return parameters;
}
}  // namespace

MasingSection::MasingSection(MasingParameters parameters)
    : CommittedSectionLaw(SectionState::virgin(validated(parameters))), parameters_(std::move(parameters)) {}

void MasingSection::set_trial_curvature(double curvature) {
  require_finite("curvature", curvature, "1/m");
  curvature_update(parameters_, state_.committed(), curvature, state_.trial());
}

void MasingSection::set_trial_moment(double moment) {
  require_finite("moment", moment, "N m");
  moment_update(parameters_, state_.committed(), moment, state_.trial());
}

}  // namespace stockbridge::section
