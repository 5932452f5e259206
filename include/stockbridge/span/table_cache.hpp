#pragma once
// Impedance tables made once each and shared: a line's damper types across its
// spans and threads (ImpedanceTable by type, frequencies and table options), a design
// study's candidates that differ only in their positions (SpanTables by span and
// damper variables). A table depends on the damper, the frequencies and the table's
// options alone, so sharing changes no result.

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace stockbridge::span {

/// Tables by a key of the caller's (the numbers a table depends on). The first
/// thread to ask for a key makes its table; others asking for it meanwhile wait for
/// that one (none is made twice); a failure to make it is thrown to each of them,
/// and to every later ask (the same numbers fail alike). Safe to use from several threads. `Table` has `nodes()`: the (frequency,
/// velocity) nodes solved for it.
template <class Table>
class TableCache {
 public:
  using Key = std::vector<double>;
  using Make = std::function<std::shared_ptr<const Table>()>;

  std::shared_ptr<const Table> get(const Key& key, const Make& make) {
    std::promise<std::shared_ptr<const Table>> promise;
    std::shared_future<std::shared_ptr<const Table>> made;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (const auto found = tables_.find(key); found != tables_.end()) {
        made = found->second;
      } else {
        tables_.emplace(key, promise.get_future().share());
      }
    }
    if (made.valid()) return made.get();  // made, or being made by another thread: waited for outside the lock
    try {
      std::shared_ptr<const Table> table = make();
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        nodes_ += table->nodes();
      }
      promise.set_value(table);
      return table;
    } catch (...) {
      promise.set_exception(std::current_exception());
      throw;
    }
  }

  /// Tables made (or being made) so far, and the nodes solved for those made.
  int tables() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<int>(tables_.size());
  }
  long long nodes() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return nodes_;
  }

 private:
  mutable std::mutex mutex_;
  std::map<Key, std::shared_future<std::shared_ptr<const Table>>> tables_;
  long long nodes_ = 0;
};

}  // namespace stockbridge::span
