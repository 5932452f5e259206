#include "stockbridge/span/analysis.hpp"

#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

void AnalysisOptions::validate() const {
  balance.validate();
  if (position_range) {
    const double lo = position_range->lo, hi = position_range->hi;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0.0 && hi > lo)) {
      throw InvalidParameter("position_range", fmt::format(" = {}:{}: expected 0 < min < max (m from the span end's clamp)",
                                                           format_value(lo), format_value(hi)));
    }
  }
}

SpanAnalysis analyse_span(const Span& span, std::vector<double> frequencies, const AnalysisOptions& options,
                          const damper::SweepProgress& progress, const TableSource& tables) {
  options.validate();
  if (options.position_range && span.dampers().empty()) {
    throw InvalidParameter("position_range", ": the span has no damper to place");
  }
  const ImpedanceTableOptions table =
      options.position_range ? options.balance.table.for_position_search() : options.balance.table;
  const std::shared_ptr<const SpanTables> made =
      tables ? tables(span, frequencies, table) : std::make_shared<const SpanTables>(span, frequencies, table, progress);
  SpanAnalysis out{span, std::nullopt, {}, made->frequencies()};
  if (options.position_range) {
    out.position = optimise_position(span, *made, options.balance, options.position_range->lo, options.position_range->hi);
    out.span = span.with_dampers_at(out.position->position);
  }
  out.balance = run_balance(out.span, *made, options.balance);
  return out;
}

}  // namespace stockbridge::span
