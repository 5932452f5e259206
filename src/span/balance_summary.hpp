#pragma once
// The span's figures over the band from its balance points (balance.hpp's
// BalanceSummary): nothing in them rests on a point that did not converge.
// Library-internal.

#include <vector>

#include "stockbridge/span/balance.hpp"

namespace stockbridge::span {

/// The summary built point by point, in the band's order, as they are balanced: a
/// caller that hands its points on need not hold them. Per point it keeps the
/// frequency and the two life stresses (the lives are the band's: every point needed).
class SummaryBuilder {
 public:
  explicit SummaryBuilder(const Span& span);
  void add(const BalancePoint& p);
  /// The summary of the points added (summarise's).
  BalanceSummary result() const;

 private:
  /// The largest of a stress over the points where it is known.
  struct Largest {
    double stress = 0.0;
    double frequency_hz = 0.0;
    int known = 0;  ///< points with the stress
    void add(double frequency, double s);
    Verdict verdict(int points, double limit, double high) const;
  };
  const Span& span_;
  BalanceSummary s_;
  Largest damped_, undamped_, judged_, undamped_judged_;
  double high_;
  std::vector<double> frequencies_, stresses_, undamped_stresses_;
};

/// The largest stresses and their frequencies over the converged points, the
/// verdicts, and the lives (Poffenberger-Swart stresses, every point needed).
BalanceSummary summarise(const Span& span, const std::vector<BalancePoint>& points);
/// The balance's summary again from its points (after a measured sheet's band was
/// set on them: the verdict may become uncertain), its counters kept.
void refresh_summary(const Span& span, SpanBalance& balance);

}  // namespace stockbridge::span
