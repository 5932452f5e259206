#pragma once
// One Masing section with the exact (piecewise linear) law and the trial/commit
// protocol, driven by curvature or by moment.

#include "stockbridge/section/committable.hpp"
#include "stockbridge/section/masing_law.hpp"
#include "stockbridge/section/section_law.hpp"

namespace stockbridge::section {

class MasingSection final : public CommittedSectionLaw<SectionState> {
 public:
  /// Validates the parameters (InvalidParameter) and starts from the virgin state.
  explicit MasingSection(MasingParameters parameters);

  void set_trial_curvature(double curvature) override;
  /// Moment-driven trial: the exact curvature at which the section carries `moment`.
  void set_trial_moment(double moment);

  const MasingParameters& parameters() const { return parameters_; }
  const SectionState& committed_state() const { return state_.committed(); }
  const SectionState& trial_state() const { return state_.trial(); }

 private:
  MasingParameters parameters_;
};

}  // namespace stockbridge::section
