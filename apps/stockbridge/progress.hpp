#pragma once
// Progress of a long computation on stderr, in points (or another unit): on a terminal a bar with
// the rate and the time left, redrawn in place; elsewhere (a log, a pipe) a plain
// line at most every 10 s, and only for runs that last longer than 10 s. Silent
// with --quiet.

#include <chrono>
#include <string>

#include "invocation.hpp"

namespace stockbridge::cli {

class ProgressReport {
 public:
  /// `what` starts every line ("impedance"); `quiet` silences everything; `unit`
  /// names what is counted. The invocation's warnings held are printed first.
  ProgressReport(Invocation& invocation, std::string what, bool quiet, std::string unit = "points");
  /// (points done, points in all); safe to call from the sweep's serialised callback.
  void operator()(int done, int total);

 private:
  std::string line(int done, int total, double seconds) const;

  std::string what_;
  std::string unit_;
  bool quiet_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  double last_plain_ = 0.0;  // seconds since the start of the last plain line
};

}  // namespace stockbridge::cli
