#pragma once
// A span's analysis in one call: the dampers' impedance tables over the
// frequencies, the dampers' best position where asked, the balance at every
// frequency with its polish, and the summary (balance.hpp). The command line's
// `stockbridge span`, Python's span() and a design study's candidates
// (design/study.hpp) all run it.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/position_search.hpp"

namespace stockbridge::span {

struct AnalysisOptions {
  BalanceOptions balance;  ///< a span file's [balance] table, the front end's changes on top
  /// Search the dampers' position in [lo, hi] (m from the span end's clamp), every
  /// damper moved together, then balance the span there. The tables are then at
  /// least as fine as ImpedanceTableOptions::for_position_search (the search
  /// compares positions on the tables alone).
  std::optional<Interval> position_range;

  /// Throws InvalidParameter naming the field ("table.velocities", "position_range").
  void validate() const;
};

/// What an analysis computed.
struct SpanAnalysis {
  Span span;  ///< as balanced: with the dampers at the position found
  std::optional<PositionSearch> position;
  SpanBalance balance;
  std::vector<double> frequencies;  ///< Hz, as balanced
};

/// Where the dampers' tables come from: made for the span (the default), or from a
/// cache (a design study's: tables depend only on the dampers, the frequencies and
/// the table options, not on the dampers' positions).
using TableSource = std::function<std::shared_ptr<const SpanTables>(const Span& span, const std::vector<double>& frequencies,
                                                                    const ImpedanceTableOptions& options)>;

/// The analysis of `span` at `frequencies` (Hz, strictly increasing; band_frequencies
/// gives the wind band's). `progress` counts the tables' nodes as they are solved.
/// Non-convergence is in the points and the summary, never an exception;
/// InvalidParameter for bad options (a position search without dampers names
/// "position_range").
SpanAnalysis analyse_span(const Span& span, std::vector<double> frequencies, const AnalysisOptions& options,
                          const damper::SweepProgress& progress = {}, const TableSource& tables = {});

}  // namespace stockbridge::span
