#include "stockbridge/span/profile.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "frequency_balance.hpp"
#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

/// A load on an end's chain: its distance from the clamp and Z / Z0.
struct ChainLoad {
  double distance = 0.0;
  std::complex<double> ratio;
};

/// The loads of `layout` at `point`: its masses (j w M) and dampers (their balanced Z).
std::vector<ChainLoad> chain_loads(const Span& span, const EndLayout& layout, const BalancePoint& point,
                                   const StringWave& wave) {
  std::vector<ChainLoad> loads;
  for (std::size_t i = 0; i < layout.attachments.masses.size(); ++i) {
    loads.push_back({layout.attachments.mass_positions[i],
                     {0.0, wave.angular_frequency * layout.attachments.masses[i] / wave.wave_impedance}});
  }
  for (std::size_t j = 0; j < layout.positions.size(); ++j) {
    const double from_end1 = layout.end == 1 ? layout.positions[j] : span.length() - layout.positions[j];
    const auto d = std::find_if(point.dampers.begin(), point.dampers.end(), [&](const DamperAtBalance& a) {
      return a.damper == layout.damper[j] && std::abs(a.position - from_end1) <= 1e-9 * span.length();
    });
    if (d == point.dampers.end()) throw std::logic_error("span_profile: a damper of the chain is not in the point");
    loads.push_back({layout.positions[j], d->impedance / wave.wave_impedance});
  }
  std::stable_sort(loads.begin(), loads.end(), [](const ChainLoad& a, const ChainLoad& b) { return a.distance < b.distance; });
  return loads;
}

/// The chain of one end sampled at `distances` (ascending, from its clamp): |Y| and
/// the local antinode amplitude, scaled so that the wave past its last load has
/// antinode amplitude `antinode`.
struct Sampled {
  std::vector<double> displacement, envelope;
};
Sampled sample_chain(const std::vector<ChainLoad>& loads, const StringWave& wave, double antinode,
                     const std::vector<double>& distances) {
  const double k = wave.wavenumber;
  const std::complex<double> jk(0.0, k);
  const auto carry = [k](std::complex<double>& y, std::complex<double>& slope, double d) {
    const double c = std::cos(k * d), s = std::sin(k * d);
    const std::complex<double> next = y * c + slope * s / k;
    slope = -y * k * s + slope * c;
    y = next;
  };
  const auto local = [jk](std::complex<double> y, std::complex<double> slope) {
    return std::abs(0.5 * (y + slope / jk)) + std::abs(0.5 * (y - slope / jk));
  };
  // The states just past each load (unit slope at the clamp).
  std::vector<std::complex<double>> ys{0.0}, slopes{1.0};
  std::vector<double> at{0.0};
  for (const ChainLoad& load : loads) {
    std::complex<double> y = ys.back(), slope = slopes.back();
    carry(y, slope, load.distance - at.back());
    slope += jk * load.ratio * y;
    ys.push_back(y), slopes.push_back(slope), at.push_back(load.distance);
  }
  const double scale = antinode / local(ys.back(), slopes.back());
  Sampled out;
  std::size_t stretch = 0;
  for (const double s : distances) {
    while (stretch + 1 < at.size() && at[stretch + 1] <= s) ++stretch;
    std::complex<double> y = ys[stretch], slope = slopes[stretch];
    carry(y, slope, s - at[stretch]);
    out.displacement.push_back(scale * std::abs(y));
    out.envelope.push_back(scale * local(y, slope));
  }
  return out;
}

std::vector<ProfileAttachment> attachments_of(const Span& span) {
  std::vector<ProfileAttachment> out;
  for (const SpanDamper& d : span.dampers()) {
    if (d.in_span()) {
      for (const double x : d.along) out.push_back({x, d.name, false});
      continue;
    }
    out.push_back({d.position, d.name, false});
    if (d.both_ends) out.push_back({span.length() - d.position, d.name, false});
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
    const Sampled s = sample_chain(chain_loads(span, layout, point, wave), wave, point.amplitude, distances);
    for (std::size_t n = 0; n < index.size(); ++n) {
      out.displacement[index[n]] = s.displacement[n];
      out.envelope[index[n]] = s.envelope[n];
    }
  }
  return out;
}

const BalancePoint& governing_point(const Span& span, const SpanBalance& balance) {
  const BalancePoint* best = nullptr;
  for (const BalancePoint& p : balance.points) {
    if (p.converged() && (!best || judged_stress(span, p) > judged_stress(span, *best))) best = &p;
  }
  if (!best) throw InvalidParameter("frequency", ": no point of the balance converged: no governing frequency");
  return *best;
}

}  // namespace stockbridge::span
