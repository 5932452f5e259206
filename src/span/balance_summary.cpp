#include "balance_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::span {

std::string_view verdict_name(Verdict verdict) {
  switch (verdict) {
    case Verdict::safe: return "safe";
    case Verdict::unsafe: return "unsafe";
    case Verdict::unknown: return "unknown";
    case Verdict::uncertain: return "uncertain";
  }
  return "unknown";
}

GoverningPlace governing_place(const Span& span, const BalancePoint& point) {
  const bool ps = span.judges_poffenberger_swart();
  GoverningPlace out{ps ? point.stress_poffenberger_swart : point.stress_fymax, "span clamp 1"};
  if (const double two = ps ? point.stress_poffenberger_swart_end2 : point.stress_fymax_end2; two > out.stress) {
    out = {two, "span clamp 2"};
  }
  for (const MassAtBalance& m : point.masses) {
    if (m.clamp_stress > out.stress) {
      out = {m.clamp_stress, fmt::format("{} at {:.4g} m", span.masses()[m.mass].name, m.position)};
    }
  }
  return out;
}

double life_stress(const BalancePoint& point) {
  double stress = point.stress_poffenberger_swart;
  if (point.stress_poffenberger_swart_end2 > stress) stress = point.stress_poffenberger_swart_end2;
  for (const MassAtBalance& m : point.masses) stress = std::max(stress, m.clamp_stress);
  return stress;
}

double judged_stress(const Span& span, const BalancePoint& point) { return governing_place(span, point).stress; }

double judged_stress_high(const Span& span, const BalancePoint& point) {
  if (!std::isfinite(point.stress_fymax_high) || !(point.stress_fymax > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return judged_stress(span, point) * point.stress_fymax_high / point.stress_fymax;
}

void SummaryBuilder::Largest::add(double frequency, double s) {
  if (!std::isfinite(s)) return;
  ++known;
  if (s > stress) stress = s, frequency_hz = frequency;
}

/// Safe only when every point is known and within the limit; unsafe as soon as one
/// known point exceeds it; uncertain where every point is known within it but a
/// band's top (`high`, NaN: none) reaches above.
Verdict SummaryBuilder::Largest::verdict(int points, double limit, double high) const {
  if (stress > limit) return Verdict::unsafe;
  if (known != points) return Verdict::unknown;
  return high > limit ? Verdict::uncertain : Verdict::safe;
}

namespace {

/// Miner's life from one stress per frequency, none where a stress is missing.
std::optional<LifeEstimate> life_of(const Span& span, const std::vector<double>& frequencies,
                                    const std::vector<double>& stresses) {
  if (!span.fatigue().life || frequencies.empty()) return std::nullopt;
  if (std::any_of(stresses.begin(), stresses.end(), [](double s) { return !std::isfinite(s); })) return std::nullopt;
  return estimate_life(frequencies, stresses, span.wind(), span.conductor().diameter, *span.fatigue().life,
                       span.sn_curve());
}

}  // namespace

SummaryBuilder::SummaryBuilder(const Span& span)
    : span_(span), high_(std::numeric_limits<double>::quiet_NaN()) {
  s_.endurance_limit = span.endurance_limit();
}

void SummaryBuilder::add(const BalancePoint& p) {
  ++s_.points;
  // The S-N curves (the Safe Border Line, a fitted table) are stated for the Poffenberger-Swart
  // stress: the lives use it.
  if (span_.fatigue().life) {
    frequencies_.push_back(p.frequency_hz);
    stresses_.push_back(p.converged() ? life_stress(p) : std::numeric_limits<double>::quiet_NaN());
    undamped_stresses_.push_back(p.undamped_life_stress);
  }
  undamped_.add(p.frequency_hz, p.undamped_stress_fymax);
  undamped_judged_.add(p.frequency_hz, p.undamped_judged_stress);
  if (std::isfinite(p.undamped_bending_amplitude)) {
    s_.undamped_max_bending_amplitude = std::max(s_.undamped_max_bending_amplitude, p.undamped_bending_amplitude);
    s_.undamped_max_stress_poffenberger_swart =
        std::max(s_.undamped_max_stress_poffenberger_swart, p.undamped_stress_poffenberger_swart);
  }
  if (!p.converged()) return;
  ++s_.converged;
  damped_.add(p.frequency_hz, p.stress_fymax);
  const GoverningPlace governing = governing_place(span_, p);
  if (governing.stress > judged_.stress) s_.max_judged_stress_place = governing.place;
  judged_.add(p.frequency_hz, governing.stress);
  // A point without a band (no vibration: stress 0) leaves the largest top as it is.
  if (const double top = judged_stress_high(span_, p); std::isfinite(top) && !(top <= high_)) high_ = top;
  s_.max_bending_amplitude = std::max(s_.max_bending_amplitude, p.bending_amplitude);
  s_.max_stress_poffenberger_swart = std::max(s_.max_stress_poffenberger_swart, p.stress_poffenberger_swart);
  s_.max_damper_clamp_stress = std::max(s_.max_damper_clamp_stress, p.damper_clamp_stress);
  if (p.several_states) ++s_.several_states;
}

BalanceSummary SummaryBuilder::result() const {
  BalanceSummary s = s_;
  s.max_stress_fymax = damped_.stress;
  s.max_stress_frequency_hz = damped_.frequency_hz;
  s.max_judged_stress = judged_.stress;
  s.max_judged_stress_frequency_hz = judged_.frequency_hz;
  s.max_judged_stress_high = high_;
  s.verdict = judged_.verdict(s.points, s.endurance_limit, high_);
  s.undamped_points = undamped_.known;
  s.undamped_max_stress_fymax = undamped_.stress;
  s.undamped_max_stress_frequency_hz = undamped_.frequency_hz;
  s.undamped_max_judged_stress = undamped_judged_.stress;
  s.undamped_verdict = undamped_judged_.verdict(s.points, s.endurance_limit, std::numeric_limits<double>::quiet_NaN());
  if (span_.fatigue().life) {
    s.life = life_of(span_, frequencies_, stresses_);
    s.undamped_life = life_of(span_, frequencies_, undamped_stresses_);
    s.life_missing_points = s.points - s.converged;
    s.undamped_life_missing_points = s.points - s.undamped_points;
  }
  return s;
}

BalanceSummary summarise(const Span& span, const std::vector<BalancePoint>& points) {
  SummaryBuilder builder(span);
  for (const BalancePoint& p : points) builder.add(p);
  return builder.result();
}

}  // namespace stockbridge::span

namespace stockbridge::span {

void refresh_summary(const Span& span, SpanBalance& balance) {
  BalanceSummary s = summarise(span, balance.points);
  s.impedance_nodes = balance.summary.impedance_nodes;
  s.failed_impedance_nodes = balance.summary.failed_impedance_nodes;
  s.direct_solves = balance.summary.direct_solves;
  balance.summary = s;
}

}  // namespace stockbridge::span
