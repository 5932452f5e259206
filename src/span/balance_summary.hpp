#pragma once
// The span's figures over the band from its balance points (balance.hpp's
// BalanceSummary): nothing in them rests on a point that did not converge.
// Library-internal.

#include <vector>

#include "stockbridge/span/balance.hpp"

namespace stockbridge::span {

/// The largest stresses and their frequencies over the converged points, the
/// verdicts, and the lives (Poffenberger-Swart stresses, every point needed).
BalanceSummary summarise(const Span& span, const std::vector<BalancePoint>& points);
/// The balance's summary again from its points (after a measured sheet's band was
/// set on them: the verdict may become uncertain), its counters kept.
void refresh_summary(const Span& span, SpanBalance& balance);

}  // namespace stockbridge::span
