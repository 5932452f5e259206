// parallel_for and Workers (core/parallel.hpp): every task once, the first exception carried, a stop
// honoured, the dealer's exits counted; under ThreadSanitizer too (the tsan preset runs "Threads").
#include "stockbridge/core/parallel.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace stockbridge {
namespace {

TEST(ParallelForThreads, RunsEveryIndexExactlyOnceOnAnyNumberOfThreads) {
  for (const int threads : {1, 2, 4, 16}) {
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{1000}}) {
      std::vector<std::atomic<int>> runs(count);
      parallel_for(count, threads, [&](std::size_t i) { ++runs[i]; });
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << threads << " threads, index " << i;
    }
  }
}

TEST(ParallelForThreads, OneThreadRunsTheIndicesInOrderOnTheCallersThread) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> order;
  parallel_for(5, 1, [&](std::size_t i) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    order.push_back(i);
  });
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

TEST(ParallelForThreads, TheFirstExceptionIsRethrownAndNoIndexIsHandedOutAfterIt) {
  std::vector<std::size_t> ran;
  EXPECT_THROW(parallel_for(10, 1,
                            [&](std::size_t i) {
                              ran.push_back(i);
                              if (i == 3) throw std::runtime_error("index 3");
                            }),
               std::runtime_error);
  EXPECT_EQ(ran, (std::vector<std::size_t>{0, 1, 2, 3}));

  // On several threads: the message of the one that threw first, and every thread joined.
  // The others' tasks last a millisecond once index 0 has thrown (999 of them would
  // take a third of a second on three threads), so that the handing out is seen to
  // stop: with empty tasks, the other threads could take every index while the
  // exception is still being thrown (slow under the sanitizers).
  std::atomic<int> started{0};
  std::atomic<bool> thrown{false};
  try {
    parallel_for(1000, 4, [&](std::size_t i) {
      ++started;
      if (i == 0) {
        thrown = true;
        throw std::invalid_argument("index 0");
      }
      while (!thrown) std::this_thread::yield();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "index 0");
  }
  EXPECT_LT(started.load(), 1000);
}

TEST(ParallelForThreads, AStopSetHandsOutNoFurtherIndex) {
  std::atomic<bool> stop{false};
  std::vector<std::size_t> ran;
  parallel_for(
      10, 1,
      [&](std::size_t i) {
        ran.push_back(i);
        if (i == 4) stop = true;
      },
      &stop);
  EXPECT_EQ(ran, (std::vector<std::size_t>{0, 1, 2, 3, 4}));

  std::atomic<int> runs{0};
  parallel_for(10, 4, [&](std::size_t) { ++runs; }, &stop);  // already set: nothing runs
  EXPECT_EQ(runs.load(), 0);
}

/// A source whose tasks arrive from elsewhere, as the command line's ranks deal them.
class DealtTasks {
 public:
  void add(std::size_t t) {
    { const std::lock_guard lock(mutex_); tasks_.push_back(t); }
    changed_.notify_all();
  }
  void close() {
    { const std::lock_guard lock(mutex_); closed_ = true; }
    changed_.notify_all();
  }
  std::optional<std::size_t> next() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !tasks_.empty() || closed_; });
    if (tasks_.empty()) return std::nullopt;
    const std::size_t t = tasks_.front();
    tasks_.pop_front();
    return t;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::size_t> tasks_;
  bool closed_ = false;
};

TEST(WorkersThreads, TakeTasksAsTheyArriveAndEachThreadSaysWhenItLeaves) {
  DealtTasks queue;
  std::vector<std::atomic<int>> runs(50);
  std::atomic<int> exits{0};
  Workers workers(3, [&] { return queue.next(); }, [&](std::size_t t) { ++runs[t]; }, nullptr, [&] { ++exits; });
  for (std::size_t t = 0; t < runs.size(); ++t) queue.add(t);
  queue.close();
  workers.join();
  for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1);
  EXPECT_EQ(exits.load(), 3);
}

TEST(WorkersThreads, ATaskThatThrowsStopsTheOthersTakingAndJoinRethrowsIt) {
  DealtTasks queue;
  for (std::size_t t = 0; t < 100; ++t) queue.add(t);
  queue.close();
  std::atomic<int> exits{0};
  Workers workers(2, [&] { return queue.next(); },
                  [](std::size_t t) {
                    if (t == 1) throw std::out_of_range("task 1");
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                  },
                  nullptr, [&] { ++exits; });
  EXPECT_THROW(workers.join(), std::out_of_range);
  EXPECT_EQ(exits.load(), 2);
  EXPECT_TRUE(queue.next().has_value());  // tasks were left in the source
}

// A source that blocks until the thread of the first task has left: that thread's
// task throws while the other thread waits in the source, and must record its
// exception and leave meanwhile (before, the workers' lock, held around the source,
// kept it from recording the exception: both threads waited for ever).
TEST(WorkersThreads, ASourceWaitingForAnotherThreadToLeaveLetsItsTaskThrowAndLeave) {
  std::mutex mutex;
  std::condition_variable changed;
  int calls = 0;
  int left = 0;
  const auto source = [&]() -> std::optional<std::size_t> {
    std::unique_lock lock(mutex);
    if (++calls == 1) return 0;
    changed.notify_all();  // the second call waits here: task 0 may throw now
    changed.wait(lock, [&] { return left > 0; });
    return 1;
  };
  std::atomic<int> runs{0};
  const auto task = [&](std::size_t t) {
    ++runs;
    if (t != 0) return;
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return calls == 2; });
    throw std::out_of_range("task 0");
  };
  const auto on_exit = [&] {
    {
      const std::lock_guard lock(mutex);
      ++left;
    }
    changed.notify_all();
  };
  Workers workers(2, source, task, nullptr, on_exit);
  EXPECT_THROW(workers.join(), std::out_of_range);
  EXPECT_EQ(left, 2);
  EXPECT_EQ(runs.load(), 1);  // task 1, given after task 0 threw, did not start
}

}  // namespace
}  // namespace stockbridge
