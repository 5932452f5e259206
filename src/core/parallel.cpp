#include "stockbridge/core/parallel.hpp"

#include <algorithm>
#include <utility>

namespace stockbridge {

Workers::Workers(int threads, Source next, Task task, const std::atomic<bool>* stop, std::function<void()> on_exit)
    : next_(std::move(next)), task_(std::move(task)), stop_(stop), on_exit_(std::move(on_exit)) {
  threads_.reserve(static_cast<std::size_t>(std::max(threads, 0)));
  try {
    for (int k = 0; k < threads; ++k) {
      threads_.emplace_back([this] {
        work();
        if (on_exit_) on_exit_();
      });
    }
  } catch (...) {  // a thread that could not start: those started stop and are joined
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      failed_ = true;
    }
    for (std::thread& t : threads_) t.join();
    throw;
  }
}

Workers::~Workers() {
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
}

bool Workers::stopping() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return failed_ || (stop_ && stop_->load());
}

std::optional<std::size_t> Workers::take() {
  if (stopping()) return std::nullopt;  // without waiting for a thread that waits in the source
  std::optional<std::size_t> t;
  {
    const std::lock_guard<std::mutex> source_lock(source_mutex_);
    if (stopping()) return std::nullopt;
    t = next_();  // may block: meanwhile the other threads record their exceptions and leave
  }
  if (stopping()) return std::nullopt;  // a task threw or a stop came while the source waited
  return t;
}

void Workers::work() {
  while (const std::optional<std::size_t> t = take()) {
    try {
      task_(*t);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!failed_) failure_ = std::current_exception();
      failed_ = true;
    }
  }
}

void Workers::join() {
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body,
                  const std::atomic<bool>* stop) {
  std::size_t next = 0;
  const auto source = [&]() -> std::optional<std::size_t> {
    if (next >= count) return std::nullopt;
    return next++;
  };
  const int helpers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count)) - 1;
  Workers workers(std::max(helpers, 0), source, body, stop);
  workers.work();
  workers.join();
}

}  // namespace stockbridge
