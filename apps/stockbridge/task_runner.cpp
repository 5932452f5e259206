#include "task_runner.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>
#include <utility>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#ifdef STOCKBRIDGE_WITH_MPI
#include <mpi.h>
#endif

#include "stockbridge/core/parallel.hpp"
#include "stockbridge/requests/design_request.hpp"
#include "stockbridge/requests/line_run.hpp"

namespace stockbridge::cli {

namespace {

/// Started by mpirun (OpenMPI, MPICH and Slurm's PMI say so in the environment).
bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name)) return true;
  }
  return false;
}

#ifdef STOCKBRIDGE_WITH_MPI

/// Evaluations and summaries to bytes and back (the ranks are the same program on the same
/// kind of machine).
class Bytes {
 public:
  void put(const void* data, std::size_t size) {
    const auto* p = static_cast<const char*>(data);
    buffer_.insert(buffer_.end(), p, p + size);
  }
  template <class T>
  void put(T value) {
    put(&value, sizeof value);
  }
  void put(const std::string& text) {
    put<std::uint64_t>(text.size());
    put(text.data(), text.size());
  }
  /// An evaluation as the journal's record (requests::evaluation_record): one format
  /// for both, every double in its shortest exact form.
  void put(const design::Evaluation& e) { put(requests::evaluation_record(e)); }
  void put(const SolverSummary& s) {
    put<std::int32_t>(static_cast<std::int32_t>(s.termination));
    put<std::int32_t>(s.evaluations);
    put(s.where);
  }
  std::vector<char>& buffer() { return buffer_; }

 private:
  std::vector<char> buffer_;
};

class Reader {
 public:
  Reader(const char* data, std::size_t size) : data_(data), end_(data + size) {}
  bool done() const { return data_ == end_; }
  void get(void* out, std::size_t size) {
    if (static_cast<std::size_t>(end_ - data_) < size) throw std::runtime_error("design: a rank's results are cut short");
    std::memcpy(out, data_, size);
    data_ += size;
  }
  template <class T>
  T get() {
    T value;
    get(&value, sizeof value);
    return value;
  }
  std::string text() {
    std::string s(get<std::uint64_t>(), '\0');
    get(s.data(), s.size());
    return s;
  }
  design::Evaluation evaluation() { return requests::parse_evaluation_record(text()); }
  SolverSummary summary() {
    SolverSummary s;
    s.termination = static_cast<Termination>(get<std::int32_t>());
    s.evaluations = get<std::int32_t>();
    s.where = text();
    return s;
  }

 private:
  const char* data_;
  const char* end_;
};

/// The tasks dealt one at a time to whichever thread of whichever rank is free
/// (Processes::deal: candidates differ in cost); rank 0 gathers every task's
/// evaluations and sends them all to every rank (MPI_Bcast), so that every rank goes
/// on with the same. A task that throws makes every rank throw its message.
class MpiRunner final : public design::TaskRunner {
 public:
  MpiRunner(const Processes& processes, int threads) : processes_(processes), threads_(threads) {}

  std::vector<design::TaskOutput> run(int tasks, const std::function<design::TaskOutput(int)>& task) override {
    std::vector<std::size_t> todo(static_cast<std::size_t>(tasks));
    for (std::size_t t = 0; t < todo.size(); ++t) todo[t] = t;
    std::vector<std::string> records(todo.size());
    const auto run_one = [&](std::size_t t) {
      Bytes bytes;
      try {
        const design::TaskOutput out = task(static_cast<int>(t));
        bytes.put<std::uint8_t>(0);
        bytes.put<std::uint64_t>(out.evaluations.size());
        for (const design::Evaluation& e : out.evaluations) bytes.put(e);
        bytes.put(out.optimiser);
      } catch (const std::exception& error) {
        bytes = Bytes();
        bytes.put<std::uint8_t>(1);
        bytes.put(std::string(error.what()));
      }
      return std::string(bytes.buffer().begin(), bytes.buffer().end());
    };
    const std::atomic<bool> never(false);
    processes_.deal(threads_, todo, run_one, [&](std::size_t t, const std::string& record) { records.at(t) = record; },
                    never);
    // Rank 0 has every record: to every rank, each with its length.
    Bytes all;
    if (processes_.rank() == 0) {
      for (const std::string& r : records) all.put(r);
    }
    std::uint64_t size = all.buffer().size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    all.buffer().resize(size);
    MPI_Bcast(all.buffer().data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
    Reader records_in(all.buffer().data(), all.buffer().size());
    std::vector<design::TaskOutput> out(todo.size());
    for (design::TaskOutput& o : out) {
      const std::string record = records_in.text();
      Reader in(record.data(), record.size());
      if (in.get<std::uint8_t>() != 0) throw std::runtime_error(in.text());
      const auto n = in.get<std::uint64_t>();
      for (std::uint64_t k = 0; k < n; ++k) o.evaluations.push_back(in.evaluation());
      o.optimiser = in.summary();
    }
    return out;
  }

 private:
  const Processes& processes_;
  int threads_;
};

#endif

}  // namespace

Processes::Processes() {
#ifndef STOCKBRIDGE_WITH_MPI
  mpirun_without_mpi_ = launched_by_mpirun();
#else
  if (!launched_by_mpirun()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (rank_ != 0) {
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)) {
      // Nothing to do: the rank's messages then duplicate rank 0's.
    }
  }
#endif
}

Processes::~Processes() {
#ifdef STOCKBRIDGE_WITH_MPI
  if (mpi_) MPI_Finalize();
#endif
}

namespace {

#ifdef STOCKBRIDGE_WITH_MPI

/// The tasks and records of one rank's threads (MPI's dealing): tasks in, records out.
class DealState {
 public:
  /// A task for a thread, waiting for one; none when there are no more.
  std::optional<std::size_t> next_task() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return !tasks_.empty() || no_more_; });
    if (tasks_.empty()) return std::nullopt;
    const std::size_t t = tasks_.front();
    tasks_.pop_front();
    return t;
  }
  void add_task(std::size_t t) {
    { const std::lock_guard<std::mutex> lock(mutex_); tasks_.push_back(t); }
    changed_.notify_all();
  }
  void no_more_tasks() {
    { const std::lock_guard<std::mutex> lock(mutex_); no_more_ = true; }
    changed_.notify_all();
  }
  void finish(std::size_t t, std::string record) {
    { const std::lock_guard<std::mutex> lock(mutex_); records_.emplace_back(t, std::move(record)); ++free_; }
    changed_.notify_all();
  }
  void thread_exited() {
    { const std::lock_guard<std::mutex> lock(mutex_); ++exited_; }
    changed_.notify_all();
  }
  /// The records so far, waiting up to `wait` for one (or for every thread to exit).
  std::deque<std::pair<std::size_t, std::string>> take_records(std::chrono::milliseconds wait, int threads) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, wait, [&] { return !records_.empty() || exited_ == threads; });
    return std::exchange(records_, {});
  }
  bool all_exited(int threads) {
    const std::lock_guard<std::mutex> lock(mutex_);
    return exited_ == threads && records_.empty();
  }
  /// Threads without a task (each asks for one), counted down as they are given.
  int take_free() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(free_, 0);
  }
  void set_free(int n) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_ = n;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::size_t> tasks_;
  std::deque<std::pair<std::size_t, std::string>> records_;
  bool no_more_ = false;
  int exited_ = 0;
  int free_ = 0;
};

/// How often a rank's dealing thread looks for messages and finished tasks: seldom
/// enough not to take the core from a computing thread that shares it (mpirun binds
/// each rank to one core), often enough next to tasks of a second or more.
constexpr std::chrono::milliseconds kDealPoll{20};

enum DealTag : int { kDealRequest = 11, kDealTask = 12, kDealRecord = 13, kDealDone = 14 };

/// A rank but 0: asks rank 0 for a task for each free thread, sends each record back,
/// and says when its threads are done.
void deal_as_worker(int threads, const std::function<std::string(std::size_t)>& run) {
  DealState state;
  state.set_free(threads);
  Workers workers(threads, [&state] { return state.next_task(); },
                  [&state, &run](std::size_t t) { state.finish(t, run(t)); }, nullptr, [&state] { state.thread_exited(); });
  bool no_more = false;
  while (true) {
    for (auto& [t, record] : state.take_records(kDealPoll, threads)) {
      std::vector<char> bytes(sizeof(std::uint64_t) + record.size());
      const std::uint64_t index = t;
      std::memcpy(bytes.data(), &index, sizeof index);
      std::memcpy(bytes.data() + sizeof index, record.data(), record.size());
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, kDealRecord, MPI_COMM_WORLD);
    }
    for (int k = state.take_free(); k > 0 && !no_more; --k) {
      const int ask = 0;
      std::int64_t task = -1;
      MPI_Send(&ask, 1, MPI_INT, 0, kDealRequest, MPI_COMM_WORLD);
      MPI_Recv(&task, 1, MPI_INT64_T, 0, kDealTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (task < 0) {
        no_more = true;
        state.no_more_tasks();
      } else {
        state.add_task(static_cast<std::size_t>(task));
      }
    }
    if (state.all_exited(threads)) break;  // no more tasks, or a task threw (join rethrows it)
  }
  workers.join();
  const int done = 0;
  MPI_Send(&done, 1, MPI_INT, 0, kDealDone, MPI_COMM_WORLD);
}

/// Rank 0's messages waiting: requests answered with the next task, records passed on.
/// Returns the ranks that said they are done.
int serve_ranks(const std::function<std::optional<std::size_t>()>& take,
                const std::function<void(std::size_t, const std::string&)>& done) {
  int finished = 0;
  while (true) {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) return finished;
    if (status.MPI_TAG == kDealRequest) {
      int ask = 0;
      MPI_Recv(&ask, 1, MPI_INT, status.MPI_SOURCE, kDealRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const std::optional<std::size_t> t = take();
      const std::int64_t task = t ? static_cast<std::int64_t>(*t) : -1;
      MPI_Send(&task, 1, MPI_INT64_T, status.MPI_SOURCE, kDealTask, MPI_COMM_WORLD);
    } else if (status.MPI_TAG == kDealRecord) {
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::vector<char> bytes(static_cast<std::size_t>(size));
      MPI_Recv(bytes.data(), size, MPI_CHAR, status.MPI_SOURCE, kDealRecord, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      std::uint64_t index = 0;
      std::memcpy(&index, bytes.data(), sizeof index);
      const std::string record(bytes.data() + sizeof index, bytes.size() - sizeof index);
      if (!record.empty()) done(static_cast<std::size_t>(index), record);
    } else {
      int said = 0;
      MPI_Recv(&said, 1, MPI_INT, status.MPI_SOURCE, kDealDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      ++finished;
    }
  }
}
#endif

}  // namespace

void Processes::deal(int threads, const std::vector<std::size_t>& todo,
                     const std::function<std::string(std::size_t)>& run,
                     const std::function<void(std::size_t, const std::string&)>& done,
                     const std::atomic<bool>& stop) const {
  const auto pass_on = [&](std::size_t t, const std::string& record) {
    if (!record.empty()) done(t, record);
  };
  if (!mpi_) {
    requests::thread_dealer()(threads, todo, run, pass_on, {}, stop);
    return;
  }
#ifdef STOCKBRIDGE_WITH_MPI
  if (rank_ != 0) {
    deal_as_worker(threads, run);
    return;
  }
  std::mutex dealing;
  std::size_t next = 0;
  const auto take = [&]() -> std::optional<std::size_t> {
    const std::lock_guard<std::mutex> lock(dealing);
    if (stop.load() || next >= todo.size()) return std::nullopt;
    return todo[next++];
  };
  // Rank 0's own threads take their tasks straight from the deal.
  DealState state;
  Workers workers(threads, take, [&](std::size_t t) { state.finish(t, run(t)); }, nullptr,
                  [&state] { state.thread_exited(); });
  int ranks_open = size_ - 1;
  while (true) {
    for (auto& [t, record] : state.take_records(kDealPoll, threads)) pass_on(t, record);
    ranks_open -= serve_ranks(take, done);
    if (ranks_open == 0 && state.all_exited(threads)) break;
  }
  workers.join();
#endif
}

std::unique_ptr<design::TaskRunner> Processes::runner(int threads) const {
#ifdef STOCKBRIDGE_WITH_MPI
  if (mpi_) return std::make_unique<MpiRunner>(*this, threads);
#endif
  return std::make_unique<design::ThreadRunner>(threads);
}

}  // namespace stockbridge::cli
