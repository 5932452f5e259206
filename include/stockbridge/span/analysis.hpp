#pragma once
// A span's analysis in one call: the dampers' impedance tables over the
// frequencies, the dampers' best position where asked, the balance at every
// frequency with its polish, and the summary (balance.hpp). The command line's
// `stockbridge span`, Python's span() and a design study's candidates
// (design/study.hpp) all run it.

#include <functional>
#include <memory>
#include <limits>
#include <optional>
#include <vector>

#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/position_search.hpp"

namespace stockbridge::span {

struct AnalysisOptions {
  BalanceOptions balance;  ///< a span file's [balance] table, the front end's changes on top
  /// Search every damper's position within these rules (position_search.hpp), then
  /// balance the span there. The tables are then at least as fine as
  /// ImpedanceTableOptions::for_position_search (the search compares arrangements on
  /// the tables alone).
  std::optional<PositionRules> positions;
  /// Takes each point as it is final, with the span as balanced (its dampers where
  /// the search put them), instead of the analysis holding it (a caller that needs
  /// each point once, a row or a running figure, in the band's order): the
  /// balance's points are then none, its summary and warnings the same. With
  /// measured dampers the points are held until the sheets' band is set on them
  /// (it is the worst over all of them), then handed on.
  std::function<void(const Span&, BalancePoint&&)> take_point;

  /// Throws InvalidParameter naming the field ("table.velocities", "position_min", "spacing_min").
  void validate() const;
};

/// What an analysis computed.
struct SpanAnalysis {
  Span span;  ///< as balanced: with the dampers at the position found
  std::optional<PositionSearch> position;
  SpanBalance balance;
  std::vector<double> frequencies;  ///< Hz, as balanced
  /// With measured dampers (sheets): the largest relative change of the fymax stress
  /// when every other curve of the sheets is left out (NaN without sheets, or where
  /// no sheet has the four curves or more that takes), and what the user should
  /// know (a sheet too coarse for the span, velocities outside a sheet).
  double sheet_error_estimate = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> warnings;

  /// Whether the balance ended before the band's top (a SpanAnalysisRun finished early):
  /// its points are then the lowest frequencies', and it has no sheet band or warnings.
  bool stopped_early() const { return static_cast<std::size_t>(balance.summary.points) < frequencies.size(); }
};

/// The relative sheet error above which a warning says the sheet is too coarse.
inline constexpr double sheet_error_warning = 0.1;

/// Where the dampers' tables come from: made for the span (the default), or from a
/// cache (a design study's: tables depend only on the dampers, the frequencies and
/// the table options, not on the dampers' positions).
using TableSource = std::function<std::shared_ptr<const SpanTables>(const Span& span, const std::vector<double>& frequencies,
                                                                    const ImpedanceTableOptions& options)>;

/// The analysis of `span` at `frequencies` (Hz, strictly increasing; band_frequencies
/// gives the wind band's). `progress` counts the tables' nodes as they are solved.
/// Non-convergence is in the points and the summary, never an exception;
/// InvalidParameter for bad options (a position search without dampers names
/// "damper"). With measured dampers, the balance is repeated on the sheets of
/// every other curve (ImpedanceSheet::every_other; the model dampers as they are):
/// sheet_error_estimate is the largest relative change of a point's fymax stress from
/// the full sheets' (the coarser sheets' error bounds the full sheets' own, which is
/// smaller), and each point's stress_fymax_low and _high are its stress times
/// (1 -+ that estimate).
SpanAnalysis analyse_span(const Span& span, std::vector<double> frequencies, const AnalysisOptions& options,
                          const damper::SweepProgress& progress = {}, const TableSource& tables = {});

class BalanceRun;

/// analyse_span one frequency at a time, for a caller that compares several spans'
/// balances as they go (a line's schedule races its arrangements): the tables made
/// and the position searched on construction, then next() balances the next
/// frequency, from the lowest, and finish() is analyse_span's answer for the
/// frequencies balanced so far (stopped early where not done()). Neither copied nor
/// moved.
class SpanAnalysisRun {
 public:
  /// analyse_span's arguments, exceptions and work before the balance.
  SpanAnalysisRun(const Span& span, std::vector<double> frequencies, const AnalysisOptions& options,
                  const damper::SweepProgress& progress = {}, const TableSource& tables = {});
  SpanAnalysisRun(const SpanAnalysisRun&) = delete;
  SpanAnalysisRun& operator=(const SpanAnalysisRun&) = delete;
  ~SpanAnalysisRun();

  /// Every frequency balanced.
  bool done() const;
  /// The next frequency's point, final once next() or finish() is called again.
  /// Precondition: !done().
  const BalancePoint& next();
  /// The span as balanced (with the dampers where the search put them).
  const Span& span() const { return out_.span; }
  /// The analysis: once, at the end.
  SpanAnalysis finish();

 private:
  AnalysisOptions options_;
  std::shared_ptr<const SpanTables> tables_;
  SpanAnalysis out_;
  bool hold_ = true;  ///< the points held for the sheets' band before take_point has them
  std::unique_ptr<BalanceRun> run_;
};

}  // namespace stockbridge::span
