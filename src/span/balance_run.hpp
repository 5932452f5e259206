#pragma once
// run_balance one frequency at a time (balance.hpp): a caller that compares several
// arrangements' balances as they go (the line's schedule races them) advances each
// as it chooses. Library-internal.

#include <cstddef>
#include <functional>
#include <optional>

#include "balance_summary.hpp"
#include "polish.hpp"
#include "stockbridge/span/balance.hpp"

namespace stockbridge::span {

/// run_balance's loop, resumable: next() balances the next frequency (from the
/// lowest); finish() is run_balance's answer for the frequencies balanced so far.
/// The point next() returns is held (or handed to take_point) at the next call of
/// next() or finish(), so a caller sees it before it is final. The span, tables and
/// options must outlive the run, which is neither copied nor moved (the polish and
/// summary refer to the span).
class BalanceRun {
 public:
  /// run_balance's arguments and preconditions (its std::invalid_argument too).
  BalanceRun(const Span& span, const SpanTables& tables, const BalanceOptions& options,
             const UndampedFigures* undamped = nullptr, std::function<void(BalancePoint&&)> take_point = {});
  BalanceRun(const BalanceRun&) = delete;
  BalanceRun& operator=(const BalanceRun&) = delete;

  /// Every frequency balanced.
  bool done() const { return next_ == tables_.frequencies().size(); }
  /// The next frequency's point. Precondition: !done().
  const BalancePoint& next();
  /// The balance of the frequencies balanced so far.
  SpanBalance finish();

 private:
  /// The last point into the summary, then held or handed on.
  void settle_last();

  const Span& span_;
  const SpanTables& tables_;
  const BalanceOptions& options_;
  std::function<void(BalancePoint&&)> take_point_;
  std::optional<Polish> polish_;
  std::optional<UndampedFigures> own_undamped_;
  const UndampedFigures* undamped_;
  SummaryBuilder summary_;
  SpanBalance out_;
  std::optional<BalancePoint> last_;
  std::size_t next_ = 0;
};

}  // namespace stockbridge::span
