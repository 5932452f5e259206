#pragma once
// The trial/commit protocol, written once (after OpenSees' materials): a solver
// sets trial states any number of times; only a converged step is committed, and
// a trial can always be reverted to the last committed state.

#include <utility>

namespace stockbridge {

template <class State>
class Committable {
 public:
  explicit Committable(State initial) : committed_(initial), trial_(std::move(initial)) {}

  const State& committed() const { return committed_; }
  const State& trial() const { return trial_; }
  State& trial() { return trial_; }

  /// The trial state becomes the committed one.
  void commit() { committed_ = trial_; }
  /// The trial state is discarded.
  void revert_to_last_commit() { trial_ = committed_; }

 private:
  State committed_;
  State trial_;
};

/// The same protocol for a large state whose every field a trial overwrites (a cable's
/// sections, CableState): commit() swaps instead of copying, and the trial, stale after
/// a commit or a revert, is copied from the committed state only when it is read or
/// modified before being overwritten. A solver that overwrites it whole asks for
/// trial_to_overwrite() and pays for no copy. The cache makes trial() const write:
/// one object is not to be used from two threads at once (as every solver's state).
template <class State>
class SwappingCommittable {
 public:
  explicit SwappingCommittable(State initial) : committed_(initial), trial_(std::move(initial)) {}

  const State& committed() const { return committed_; }
  const State& trial() const {
    refresh();
    return trial_;
  }
  /// The trial state to be modified (brought up to date first).
  State& trial() {
    refresh();
    return trial_;
  }
  /// The trial state to be overwritten whole: its present contents are not to be read.
  State& trial_to_overwrite() {
    stale_ = false;
    return trial_;
  }

  /// The trial state becomes the committed one (nothing changes if no trial was set).
  void commit() {
    if (stale_) return;  // the trial is the committed state
    std::swap(committed_, trial_);
    stale_ = true;
  }
  /// The trial state is discarded.
  void revert_to_last_commit() { stale_ = true; }

 private:
  void refresh() const {
    if (!stale_) return;
    trial_ = committed_;
    stale_ = false;
  }

  State committed_;
  mutable State trial_;
  mutable bool stale_ = false;
};

}  // namespace stockbridge
