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

}  // namespace stockbridge
