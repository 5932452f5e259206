#pragma once
// Frequency sweeps of the impedance at constant velocity amplitude (or constant
// displacement amplitude), with frequency continuation: each distinct arm walks
// the frequencies in order, the previous solution (scaled to the new displacement
// amplitude) predicting the next. Independent runs (amplitudes x distinct arms)
// go to parallel threads.
//
// Non-uniqueness: where the harmonic-balance Jacobian's determinant changes sign
// between neighbouring frequencies, the response curve folds back there and
// several steady states coexist; both points are flagged `non_unique` with a note,
// rather than one branch being picked silently.

#include <functional>
#include <vector>

#include "stockbridge/damper/impedance.hpp"

namespace stockbridge::damper {

struct SweepSpec {
  std::vector<double> frequencies;  ///< Hz, > 0, strictly increasing
  std::vector<double> amplitudes;   ///< V in m/s (or X in m with constant_displacement), > 0
  bool constant_displacement = false;
  SolverOptions solver;
  int threads = 1;                  ///< >= 1
  /// Frequencies per continuation block (0: one block). Each amplitude's sweep is cut
  /// into blocks of about this many frequencies, each followed by its own
  /// continuation from a cold start one frequency before it, so that the threads
  /// share even a single amplitude; the cut does not depend on `threads`, nor do the
  /// results.
  int block_points = 50;

  void validate() const;
  Excitation excitation(double frequency_hz, double amplitude) const;
};

struct SweepRun {
  double amplitude = 0.0;  ///< as given (V or X)
  std::vector<ImpedancePoint> points;  ///< one per frequency
};

/// Called as points (amplitude x frequency) are done, with (points done, points in
/// all): once per point, `done` counting up by one; calls are serialised. With
/// several distinct arms a point counts when as many arm solves as it needs are done.
using SweepProgress = std::function<void(int, int)>;

/// Called with each point as it is final, in the runs' order (each amplitude's
/// frequencies in turn): (amplitude index, frequency index, the point); calls are
/// serialised, never two at once.
using SweepSink = std::function<void(std::size_t, std::size_t, ImpedancePoint&&)>;

/// Runs every amplitude over every frequency, handing each point to `sink` as soon
/// as it is final (a fold is flagged once its neighbour is in), in order. What it
/// holds meanwhile is the points the threads have solved ahead of the first one not
/// yet final: memory does not grow with the number of points. Never throws for
/// non-convergence: such points have converged == false and a message. An
/// exception `sink` throws stops the sweep and is rethrown.
void stream_sweep(const Damper& damper, const SweepSpec& spec, const SweepSink& sink,
                  const SweepProgress& progress = {});

/// stream_sweep's points, gathered: one run per amplitude.
std::vector<SweepRun> run_sweep(const Damper& damper, const SweepSpec& spec,
                                const SweepProgress& progress = {});

/// Log-spaced frequencies from fmin to fmax (points >= 2), Hz.
std::vector<double> log_spaced(double fmin, double fmax, int points);

}  // namespace stockbridge::damper
