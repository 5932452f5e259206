#pragma once
// The library's one way of running work on threads: `parallel_for` over an index
// range (the sweep's blocks, the design's candidates, the fit's points, a line's
// spans) and `Workers`, threads that take tasks from a source as it gives them (the
// command line's dealing, whose tasks arrive from other ranks). Tasks are taken in
// turn as threads free up; what a task computes goes to its own slot, so that the
// results do not depend on the number of threads.
//
// Stopping: the first exception a task throws stops the handing out of tasks (those
// running finish) and is rethrown once every thread has joined, and so is a stop
// requested through the stop flag (a signal handler may set it): no task starts
// after it, and the caller tells which ran.

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace stockbridge {

/// Threads that run `task(t)` for every t that `next()` gives until it gives none
/// (it may block waiting for one; it is called by one thread at a time, and while it
/// waits the other threads finish their tasks, record an exception and leave), a
/// stop is requested or a task throws. A task `next()` gives once a task has thrown
/// or a stop is requested is not run. They start at construction; `join` waits for
/// them.
class Workers {
 public:
  using Source = std::function<std::optional<std::size_t>()>;
  using Task = std::function<void(std::size_t)>;

  /// `threads` >= 0 new threads (0: none; the caller may `work` itself). Each calls
  /// `on_exit`, if given, as it stops taking tasks (a dealer waiting on its threads).
  Workers(int threads, Source next, Task task, const std::atomic<bool>* stop = nullptr,
          std::function<void()> on_exit = {});
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;
  /// Joins (an exception of a task is then dropped: call `join` to see it).
  ~Workers();

  /// Runs tasks on the calling thread too, until there are no more.
  void work();
  /// Waits for every thread; rethrows the first exception a task threw.
  void join();

 private:
  std::optional<std::size_t> take();
  /// A task threw or a stop is requested: no task is to start.
  bool stopping();

  Source next_;
  Task task_;
  const std::atomic<bool>* stop_;
  std::function<void()> on_exit_;
  std::mutex source_mutex_;  // held while next_ runs (one thread at a time), not while a task runs
  std::mutex mutex_;         // failed_ and failure_; never held while next_ runs
  std::exception_ptr failure_;
  bool failed_ = false;
  std::vector<std::thread> threads_;
};

/// Runs `body(i)` for every i in [0, count) on at most `threads` threads, the calling
/// thread one of them (with one thread, or one index, nothing is started: the
/// caller runs them in order). Returns when every body has returned; rethrows the
/// first exception a body threw (no index is handed out after it). With `stop`
/// set, no index is handed out after it is seen.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body,
                  const std::atomic<bool>* stop = nullptr);

}  // namespace stockbridge
