#pragma once
// A line's damper schedule run span by span, for both front ends (`stockbridge
// line`, Python's line): the spans dealt to workers (this process's threads, or the
// command line's MPI ranks through its own dealer), each span's outcome typed (its
// row, a failure and its reason, or an interruption), the schedule in the line's
// order with its bill of materials built once. A stop requested ends the run with
// the termination `interrupted`, not an exception.

#include <atomic>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/requests/line_request.hpp"

namespace stockbridge::requests {

/// How one span's scheduling ended.
enum class SpanEnd {
  scheduled,    ///< its row as computed
  failed,       ///< its own data made the schedule throw: a row of verdict unknown, the reason as its warning
  interrupted,  ///< a stop came before its end: no row
};
/// "scheduled", "failed" or "interrupted".
std::string_view span_end_name(SpanEnd end);

/// One span's outcome.
struct SpanOutcome {
  std::size_t index = 0;  ///< the span's place in the line
  SpanEnd end = SpanEnd::scheduled;
  std::string reason;                    ///< failed: the error's message
  std::optional<line::ScheduleRow> row;  ///< scheduled or failed
};

/// The outcome as one line of text (what crosses MPI ranks and the journal keeps):
/// the row's record (schedule_record), after "failed\t" for a failed span; empty
/// for an interrupted one.
std::string span_outcome_record(const SpanOutcome& outcome);
/// The outcome of a record (InvalidParameter naming "record" where it is none: a
/// record cut short). A record without the "failed" mark is a scheduled span's.
SpanOutcome parse_span_outcome(std::string_view record);
/// Whether a record is a schedule record of an earlier program (span-v1, span-v2:
/// before the dampers beside the masses and the governing place), which
/// parse_span_outcome refuses: its span is computed again.
bool earlier_span_record(std::string_view record);

/// Deals tasks to workers: runs `run(t)` for every t of `todo` on `threads` threads
/// (and, for the command line's, on other ranks), passing each result to
/// `done(t, record)` on the calling thread as it arrives, and calling `heartbeat` there
/// every 100 ms or so while it waits; hands out no task once `stop` is set. An empty
/// record is a task that was stopped.
using Dealer = std::function<void(int threads, const std::vector<std::size_t>& todo,
                                  const std::function<std::string(std::size_t)>& run,
                                  const std::function<void(std::size_t, const std::string&)>& done,
                                  const std::function<void()>& heartbeat, const std::atomic<bool>& stop)>;
/// The dealer of this process's threads (core/parallel.hpp's Workers).
Dealer thread_dealer();

struct LineRunOptions {
  int threads = 1;  ///< 1 to 256
  /// The spans to compute, in the order they are handed out; empty: every span.
  std::vector<std::size_t> todo;
  /// Set, from any thread or a signal handler, to stop: spans running end at their
  /// next balance, none starts.
  const std::atomic<bool>* stop = nullptr;
  /// On the worker, as a span is scheduled: its row and its balance (the command
  /// line's --details).
  std::function<void(const line::ScheduleRow&, const span::SpanAnalysis&)> on_scheduled;
  /// On the calling thread, as each span's outcome arrives (in the order they end):
  /// the outcome and its record (progress, the journal).
  std::function<void(const SpanOutcome&, const std::string& record)> on_outcome;
  /// On the calling thread every 100 ms or so while the workers run (Python looks
  /// for Ctrl-C there).
  std::function<void()> heartbeat;
  /// How the spans are dealt; empty: thread_dealer().
  Dealer dealer;
};

/// The spans of options.todo scheduled: their outcomes in the line's order, and
/// `interrupted` where a stop came before every one of them had its outcome.
struct LineRun {
  Termination termination = Termination::converged;
  std::vector<SpanOutcome> outcomes;
};

/// Runs the spans of options.todo on the tables of `cache` (shared by every span
/// and thread). InvalidParameter for bad options; a span's own failure is its outcome.
LineRun run_line(const io::LineFile& file, line::TableCache& cache, const LineRunOptions& options);

}  // namespace stockbridge::requests
