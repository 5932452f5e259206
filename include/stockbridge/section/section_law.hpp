#pragma once
// The interface every curvature-driven section law offers to drivers that choose a
// law at run time (the `loop` command): trial curvature in, moment and tangent out,
// then commit or revert. Hot loops (the cable) use the exact kernels directly.

#include <utility>

#include "stockbridge/section/committable.hpp"

namespace stockbridge::section {

class SectionLaw {
 public:
  virtual ~SectionLaw() = default;

  /// Sets the trial curvature (1/m); the path from the committed state is taken as monotone.
  virtual void set_trial_curvature(double curvature) = 0;
  virtual double curvature() const = 0;  ///< trial curvature, 1/m
  virtual double moment() const = 0;     ///< trial moment, N m
  virtual double tangent() const = 0;    ///< trial tangent stiffness dM/dkappa, N m^2
  /// Energy dissipated by the sliders since the virgin state, J/m, up to the trial state.
  virtual double dissipated_energy() const = 0;
  virtual void commit() = 0;
  virtual void revert_to_last_commit() = 0;
};

/// The protocol over a committed and a trial state whose fields are named as
/// SectionState's (curvature, moment, tangent, dissipated): a law writes only its
/// constructor and its trial update.
template <class State>
class CommittedSectionLaw : public SectionLaw {
 public:
  double curvature() const override { return state_.trial().curvature; }
  double moment() const override { return state_.trial().moment; }
  double tangent() const override { return state_.trial().tangent; }
  double dissipated_energy() const override { return state_.trial().dissipated; }
  void commit() override { state_.commit(); }
  void revert_to_last_commit() override { state_.revert_to_last_commit(); }

 protected:
  explicit CommittedSectionLaw(State initial) : state_(std::move(initial)) {}
  Committable<State> state_;
};

}  // namespace stockbridge::section
