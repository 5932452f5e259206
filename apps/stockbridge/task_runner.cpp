#include "task_runner.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#ifdef STOCKBRIDGE_WITH_MPI
#include <mpi.h>
#endif

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
/// kind of machine: raw doubles keep every bit).
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
  void put(const design::Evaluation& e) {
    put<std::uint64_t>(e.x.size());
    put(e.x.data(), e.x.size() * sizeof(double));
    put<std::int32_t>(static_cast<std::int32_t>(e.termination));
    for (const double v : {e.objective, e.max_stress_ratio, e.max_stress, e.frequency_at_max_hz, e.total_mass,
                           e.messenger_curvature_max, e.shortest_life_years}) {
      put(v);
    }
    put<std::uint64_t>(e.span_at_max);
    put(e.failure);
    put(e.infeasibility);
  }
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
  design::Evaluation evaluation() {
    design::Evaluation e;
    e.x.resize(get<std::uint64_t>());
    get(e.x.data(), e.x.size() * sizeof(double));
    e.termination = static_cast<Termination>(get<std::int32_t>());
    for (double* v : {&e.objective, &e.max_stress_ratio, &e.max_stress, &e.frequency_at_max_hz, &e.total_mass,
                      &e.messenger_curvature_max, &e.shortest_life_years}) {
      *v = get<double>();
    }
    e.span_at_max = get<std::uint64_t>();
    e.failure = text();
    e.infeasibility = text();
    return e;
  }
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

/// Rank r runs tasks r, r + size, ... on its threads; every rank then has every
/// task's evaluations (MPI_Allgatherv). A task that throws on one rank makes every
/// rank throw its message.
class MpiRunner final : public design::TaskRunner {
 public:
  MpiRunner(int rank, int size, int threads) : rank_(rank), size_(size), threads_(threads) {}

  std::vector<design::TaskOutput> run(int tasks, const std::function<design::TaskOutput(int)>& task) override {
    std::vector<int> mine;
    for (int t = rank_; t < tasks; t += size_) mine.push_back(t);
    Bytes bytes;
    try {
      design::ThreadRunner threads(threads_);
      const auto results = threads.run(static_cast<int>(mine.size()), [&](int k) { return task(mine[k]); });
      bytes.put<std::uint8_t>(0);
      for (std::size_t k = 0; k < mine.size(); ++k) {
        bytes.put<std::int64_t>(mine[k]);
        bytes.put<std::uint64_t>(results[k].evaluations.size());
        for (const design::Evaluation& e : results[k].evaluations) bytes.put(e);
        bytes.put(results[k].optimiser);
      }
    } catch (const std::exception& error) {
      bytes = Bytes();
      bytes.put<std::uint8_t>(1);
      bytes.put(std::string(error.what()));
    }
    std::vector<char>& send = bytes.buffer();
    const int size = static_cast<int>(send.size());
    std::vector<int> sizes(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size_; ++r) {
      offsets[static_cast<std::size_t>(r)] = total;
      total += sizes[static_cast<std::size_t>(r)];
    }
    std::vector<char> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(send.data(), size, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, MPI_COMM_WORLD);
    std::vector<design::TaskOutput> out(static_cast<std::size_t>(tasks));
    for (int r = 0; r < size_; ++r) {
      Reader in(all.data() + offsets[static_cast<std::size_t>(r)], static_cast<std::size_t>(sizes[static_cast<std::size_t>(r)]));
      if (in.get<std::uint8_t>() != 0) throw std::runtime_error(in.text());
      while (!in.done()) {
        const auto t = static_cast<std::size_t>(in.get<std::int64_t>());
        const auto n = in.get<std::uint64_t>();
        for (std::uint64_t k = 0; k < n; ++k) out.at(t).evaluations.push_back(in.evaluation());
        out.at(t).optimiser = in.summary();
      }
    }
    return out;
  }

 private:
  int rank_, size_, threads_;
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

std::unique_ptr<design::TaskRunner> Processes::runner(int threads) const {
#ifdef STOCKBRIDGE_WITH_MPI
  if (mpi_) return std::make_unique<MpiRunner>(rank_, size_, threads);
#endif
  return std::make_unique<design::ThreadRunner>(threads);
}

}  // namespace stockbridge::cli
