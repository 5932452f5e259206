#include "stockbridge/span/profile.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <numbers>

#include <fmt/format.h>

#include "frequency_balance.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

/// The impedances of `layout`'s dampers at `point` (their balanced Z), in its order.
std::vector<std::complex<double>> chain_impedances(const Span& span, const EndLayout& layout, const BalancePoint& point) {
  std::vector<std::complex<double>> z;
  for (std::size_t j = 0; j < layout.positions.size(); ++j) {
    const double from_end1 = layout.end == 1 ? layout.positions[j] : span.length() - layout.positions[j];
    const auto d = std::find_if(point.dampers.begin(), point.dampers.end(), [&](const DamperAtBalance& a) {
      return a.damper == layout.damper[j] && std::abs(a.position - from_end1) <= 1e-9 * span.length();
    });
    if (d == point.dampers.end()) throw std::logic_error("span_profile: a damper of the chain is not in the point");
    z.push_back(d->impedance);
  }
  return z;
}

std::vector<ProfileAttachment> attachments_of(const Span& span) {
  std::vector<ProfileAttachment> out;
  for (const SpanDamper& d : span.dampers()) {
    for (const double x : d.positions_from_end1(span.length())) out.push_back({x, d.name, false});
  }
  for (const SpanMass& m : span.masses()) {
    for (const double x : m.positions) out.push_back({x, m.name, true});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const ProfileAttachment& a, const ProfileAttachment& b) { return a.position < b.position; });
  return out;
}

}  // namespace

SpanProfile span_profile(const Span& span, const BalancePoint& point, int points_per_wavelength) {
  if (!point.converged()) {
    throw InvalidParameter("frequency", fmt::format(" = {:.4g} Hz: its balance did not converge: no profile", point.frequency_hz));
  }
  require_in_range("points_per_wavelength", points_per_wavelength, 2, 1000);
  const Conductor& c = span.conductor();
  const double length = span.length();
  StringWave wave;
  wave.angular_frequency = 2.0 * std::numbers::pi * point.frequency_hz;
  wave.wavenumber = wavenumber(c, span.tension(), point.frequency_hz);
  wave.wave_impedance = wave_impedance(c, span.tension());
  SpanProfile out;
  out.frequency_hz = point.frequency_hz;
  out.attachments = attachments_of(span);
  const auto steps = static_cast<std::size_t>(std::ceil(points_per_wavelength * length * wave.wavenumber / (2.0 * std::numbers::pi)));
  for (std::size_t i = 0; i <= steps; ++i) out.x.push_back(length * static_cast<double>(i) / static_cast<double>(steps));
  for (const ProfileAttachment& a : out.attachments) out.x.push_back(a.position);
  std::sort(out.x.begin(), out.x.end());
  out.x.erase(std::unique(out.x.begin(), out.x.end()), out.x.end());
  // Each end's chain covers its half (the whole span where only one end has a chain).
  std::vector<EndLayout> layouts = end_layouts(span);
  if (layouts.empty()) layouts.push_back(EndLayout{});  // the bare string from end 1
  out.displacement.resize(out.x.size());
  out.envelope.resize(out.x.size());
  for (const EndLayout& layout : layouts) {
    const bool whole = layouts.size() == 1;
    std::vector<std::size_t> index;
    std::vector<double> distances;
    for (std::size_t i = 0; i < out.x.size(); ++i) {
      const double x = out.x[i];
      const bool mine = whole || (layout.end == 1 ? x <= 0.5 * length : x > 0.5 * length);
      if (!mine) continue;
      index.push_back(i);
      distances.push_back(layout.end == 1 ? x : length - x);
    }
    if (layout.end == 2) std::reverse(index.begin(), index.end()), std::reverse(distances.begin(), distances.end());
    const EndSamples s = sample_end(wave, layout.positions, chain_impedances(span, layout, point), point.amplitude,
                                    layout.attachments, distances);
    for (std::size_t n = 0; n < index.size(); ++n) {
      out.displacement[index[n]] = s.displacement[n];
      out.envelope[index[n]] = s.antinode[n];
    }
  }
  return out;
}

bool governs_instead(const Span& span, const BalancePoint& p, const BalancePoint* best) {
  return p.converged() && (!best || judged_stress(span, p) > judged_stress(span, *best));
}

const BalancePoint& governing_point(const Span& span, const SpanBalance& balance) {
  const BalancePoint* best = nullptr;
  for (const BalancePoint& p : balance.points) {
    if (governs_instead(span, p, best)) best = &p;
  }
  if (!best) throw InvalidParameter("frequency", ": no point of the balance converged: no governing frequency");
  return *best;
}

}  // namespace stockbridge::span
