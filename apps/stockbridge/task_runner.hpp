#pragma once
// How `stockbridge design` spreads its candidates: on threads, and across MPI ranks
// when the program was started by mpirun (and built with MPI).

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stockbridge/design/search.hpp"

namespace stockbridge::cli {

/// The processes of a run: one, or the MPI ranks. Starts MPI (when launched by
/// mpirun) and finishes it when destroyed; every rank but 0 is silenced (its
/// stdout and stderr go to /dev/null), so that messages and files come once.
class Processes {
 public:
  Processes();
  ~Processes();
  Processes(const Processes&) = delete;
  Processes& operator=(const Processes&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Started by mpirun, but this program was built without MPI: each process would
  /// run the whole study alone.
  bool mpirun_without_mpi() const { return mpirun_without_mpi_; }
  /// Tasks on `threads` threads of each rank, the ranks taking tasks in turn.
  std::unique_ptr<design::TaskRunner> runner(int threads) const;

  /// Tasks `todo` dealt one at a time to whichever thread of whichever rank is free
  /// (tasks differ in cost: a fixed deal leaves ranks idle). `run` gives a task's
  /// record (empty: not finished, e.g. interrupted); on rank 0, `done` gets each
  /// record as it arrives, from the calling thread, one at a time. Rank 0 stops
  /// dealing once `stop` is set (the tasks under way finish or give up). Returns on
  /// every rank when no task is under way. One process (no MPI): the library's
  /// requests::thread_dealer on this process's threads.
  void deal(int threads, const std::vector<std::size_t>& todo, const std::function<std::string(std::size_t)>& run,
            const std::function<void(std::size_t, const std::string&)>& done, const std::atomic<bool>& stop) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
  bool mpirun_without_mpi_ = false;
};

}  // namespace stockbridge::cli
