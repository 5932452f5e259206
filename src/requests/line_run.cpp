#include "stockbridge/requests/line_run.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <numeric>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/parallel.hpp"
#include "stockbridge/requests/line_request.hpp"

namespace stockbridge::requests {

namespace {

// Names here are unique among the library's files (unity batches).

constexpr std::string_view kFailedMark = "failed\t";
constexpr std::string_view kNotScheduled = "not scheduled: ";

/// The records the workers have made, passed on on the calling thread.
class RecordQueue {
 public:
  void push(std::size_t t, std::string record) {
    {
      const std::lock_guard lock(mutex_);
      records_.emplace_back(t, std::move(record));
    }
    changed_.notify_all();
  }
  void worker_left() {
    {
      const std::lock_guard lock(mutex_);
      --running_;
    }
    changed_.notify_all();
  }
  void set_running(int n) { running_ = n; }
  /// The records so far, waiting up to `wait` for one; `finished` once every worker has left
  /// (then the records returned are the last).
  std::deque<std::pair<std::size_t, std::string>> take(std::chrono::milliseconds wait, bool& finished) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, wait, [&] { return !records_.empty() || running_ == 0; });
    finished = running_ == 0;
    return std::exchange(records_, {});
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<std::size_t, std::string>> records_;
  int running_ = 0;
};

}  // namespace

std::string_view span_end_name(SpanEnd end) {
  switch (end) {
    case SpanEnd::scheduled: return "scheduled";
    case SpanEnd::failed: return "failed";
    case SpanEnd::interrupted: return "interrupted";
  }
  return "interrupted";
}

std::string span_outcome_record(const SpanOutcome& outcome) {
  if (outcome.end == SpanEnd::interrupted || !outcome.row) return {};
  const std::string record = schedule_record(*outcome.row);
  return outcome.end == SpanEnd::failed ? std::string(kFailedMark) + record : record;
}

SpanOutcome parse_span_outcome(std::string_view record) {
  SpanOutcome o;
  if (record.starts_with(kFailedMark)) {
    o.end = SpanEnd::failed;
    record.remove_prefix(kFailedMark.size());
  }
  o.row = parse_schedule_record(record);
  o.index = o.row->index;
  if (o.end == SpanEnd::failed && !o.row->warnings.empty()) {
    std::string_view reason = o.row->warnings.front();
    if (reason.starts_with(kNotScheduled)) reason.remove_prefix(kNotScheduled.size());
    o.reason = std::string(reason);
  }
  return o;
}

bool earlier_span_record(std::string_view record) {
  if (record.starts_with(kFailedMark)) record.remove_prefix(kFailedMark.size());
  return record.starts_with("span-v1\t") || record.starts_with("span-v2\t");
}

Dealer thread_dealer() {
  return [](int threads, const std::vector<std::size_t>& todo, const std::function<std::string(std::size_t)>& run,
            const std::function<void(std::size_t, const std::string&)>& done, const std::function<void()>& heartbeat,
            const std::atomic<bool>& stop) {
    RecordQueue queue;
    const int workers_count = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), todo.size()));
    queue.set_running(workers_count);
    std::size_t next = 0;
    const auto source = [&]() -> std::optional<std::size_t> {
      if (next >= todo.size()) return std::nullopt;
      return todo[next++];
    };
    Workers workers(workers_count, source, [&](std::size_t t) { queue.push(t, run(t)); }, &stop,
                    [&queue] { queue.worker_left(); });
    for (bool finished = false; !finished;) {
      for (auto& [t, record] : queue.take(std::chrono::milliseconds(100), finished)) done(t, record);
      if (heartbeat) heartbeat();
    }
    workers.join();  // a task's exception (not a span's own failure) is raised here
  };
}

LineRun run_line(const io::LineFile& file, line::TableCache& cache, const LineRunOptions& options) {
  require_in_range("threads", options.threads, 1, 256);
  const std::size_t spans = file.line.spans().size();
  std::vector<std::size_t> todo = options.todo;
  if (todo.empty()) {
    todo.resize(spans);
    std::iota(todo.begin(), todo.end(), std::size_t{0});
  }
  for (const std::size_t i : todo) {
    if (i >= spans) throw InvalidParameter("todo", fmt::format(": span {} of a line of {} spans", i, spans));
  }
  static const std::atomic<bool> never{false};
  const std::atomic<bool>& stop = options.stop ? *options.stop : never;
  const std::function<bool()> stopped = [&stop] { return stop.load(); };
  const auto run = [&](std::size_t i) -> std::string {
    SpanOutcome o;
    o.index = i;
    try {
      line::SpanSchedule s = line::schedule_span(file.line, i, cache, stopped);
      if (options.on_scheduled) options.on_scheduled(s.row, s.analysis);
      o.row = std::move(s.row);
    } catch (const Interrupted&) {
      return {};
    } catch (const InvalidParameter& e) {
      o.end = SpanEnd::failed;
      o.row = failed_row(file, i, e.what());
    } catch (const NumericalError& e) {
      o.end = SpanEnd::failed;
      o.row = failed_row(file, i, e.what());
    }
    return span_outcome_record(o);
  };
  // Each outcome as its record gives it back (the same bits on every thread and rank).
  std::map<std::size_t, SpanOutcome> arrived;
  const auto done = [&](std::size_t i, const std::string& record) {
    if (record.empty()) return;  // stopped before its end
    SpanOutcome o = parse_span_outcome(record);
    o.index = i;
    if (options.on_outcome) options.on_outcome(o, record);
    arrived.insert_or_assign(i, std::move(o));
  };
  const Dealer dealer = options.dealer ? options.dealer : thread_dealer();
  dealer(options.threads, todo, run, done, options.heartbeat, stop);
  LineRun out;
  for (const std::size_t i : todo) {
    if (!arrived.contains(i)) arrived.emplace(i, SpanOutcome{i, SpanEnd::interrupted, "stopped", std::nullopt});
  }
  for (auto& [i, o] : arrived) {
    if (o.end == SpanEnd::interrupted) out.termination = Termination::interrupted;
    out.outcomes.push_back(std::move(o));
  }
  return out;
}

}  // namespace stockbridge::requests
