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

namespace {

/// The largest of a stress over the points where it is known, and what it means.
struct Largest {
  double stress = 0.0;
  double frequency_hz = 0.0;
  int known = 0;  ///< points with the stress

  void add(double frequency, double s) {
    if (!std::isfinite(s)) return;
    ++known;
    if (s > stress) stress = s, frequency_hz = frequency;
  }
  /// Safe only when every point is known and within the limit; unsafe as soon as one
  /// known point exceeds it; uncertain where every point is known within it but a
  /// band's top (`high`, NaN: none) reaches above.
  Verdict verdict(int points, double limit, double high = std::numeric_limits<double>::quiet_NaN()) const {
    if (stress > limit) return Verdict::unsafe;
    if (known != points) return Verdict::unknown;
    return high > limit ? Verdict::uncertain : Verdict::safe;
  }
};

/// Miner's life from one stress per frequency, none where a stress is missing.
std::optional<LifeEstimate> life_of(const Span& span, const std::vector<double>& frequencies,
                                    const std::vector<double>& stresses) {
  if (!span.fatigue().life || frequencies.empty()) return std::nullopt;
  if (std::any_of(stresses.begin(), stresses.end(), [](double s) { return !std::isfinite(s); })) return std::nullopt;
  return estimate_life(frequencies, stresses, span.wind(), span.conductor().diameter, *span.fatigue().life,
                       span.sn_curve());
}

}  // namespace

BalanceSummary summarise(const Span& span, const std::vector<BalancePoint>& points) {
  BalanceSummary s;
  s.points = static_cast<int>(points.size());
  s.endurance_limit = span.endurance_limit();
  Largest damped, undamped, judged, undamped_judged;
  double high = std::numeric_limits<double>::quiet_NaN();
  // The S-N curves (the Safe Border Line, a fitted table) are stated for the Poffenberger-Swart
  // stress: the lives use it.
  std::vector<double> frequencies, stresses, undamped_stresses;
  for (const BalancePoint& p : points) {
    frequencies.push_back(p.frequency_hz);
    const double stress = p.converged() ? life_stress(p) : std::numeric_limits<double>::quiet_NaN();
    stresses.push_back(stress);
    undamped_stresses.push_back(p.undamped_life_stress);
    undamped.add(p.frequency_hz, p.undamped_stress_fymax);
    undamped_judged.add(p.frequency_hz, p.undamped_judged_stress);
    if (std::isfinite(p.undamped_bending_amplitude)) {
      s.undamped_max_bending_amplitude = std::max(s.undamped_max_bending_amplitude, p.undamped_bending_amplitude);
      s.undamped_max_stress_poffenberger_swart =
          std::max(s.undamped_max_stress_poffenberger_swart, p.undamped_stress_poffenberger_swart);
    }
    if (!p.converged()) continue;
    ++s.converged;
    damped.add(p.frequency_hz, p.stress_fymax);
    const GoverningPlace governing = governing_place(span, p);
    if (governing.stress > judged.stress) s.max_judged_stress_place = governing.place;
    judged.add(p.frequency_hz, governing.stress);
    // A point without a band (no vibration: stress 0) leaves the largest top as it is.
    if (const double top = judged_stress_high(span, p); std::isfinite(top) && !(top <= high)) high = top;
    s.max_bending_amplitude = std::max(s.max_bending_amplitude, p.bending_amplitude);
    s.max_stress_poffenberger_swart = std::max(s.max_stress_poffenberger_swart, p.stress_poffenberger_swart);
    s.max_damper_clamp_stress = std::max(s.max_damper_clamp_stress, p.damper_clamp_stress);
    if (p.several_states) ++s.several_states;
  }
  s.max_stress_fymax = damped.stress;
  s.max_stress_frequency_hz = damped.frequency_hz;
  s.max_judged_stress = judged.stress;
  s.max_judged_stress_frequency_hz = judged.frequency_hz;
  s.max_judged_stress_high = high;
  s.verdict = judged.verdict(s.points, s.endurance_limit, high);
  s.undamped_points = undamped.known;
  s.undamped_max_stress_fymax = undamped.stress;
  s.undamped_max_stress_frequency_hz = undamped.frequency_hz;
  s.undamped_max_judged_stress = undamped_judged.stress;
  s.undamped_verdict = undamped_judged.verdict(s.points, s.endurance_limit);
  if (span.fatigue().life) {
    s.life = life_of(span, frequencies, stresses);
    s.undamped_life = life_of(span, frequencies, undamped_stresses);
    s.life_missing_points = s.points - s.converged;
    s.undamped_life_missing_points = s.points - s.undamped_points;
  }
  return s;
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
