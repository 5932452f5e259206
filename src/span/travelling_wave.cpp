#include "stockbridge/span/travelling_wave.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

namespace stockbridge::span {

namespace {

/// (Y, Y') of the string carried over a distance d without loads.
void propagate(std::complex<double>& y, std::complex<double>& slope, double k, double d) {
  const double c = std::cos(k * d), s = std::sin(k * d);
  const std::complex<double> y_next = y * c + slope * s / k;
  slope = -y * k * s + slope * c;
  y = y_next;
}

/// The change of |q| when q changes by dq (one-sided where q = 0).
double abs_change(std::complex<double> q, std::complex<double> dq) {
  const double r = std::abs(q);
  return r > 0.0 ? (std::conj(q) * dq).real() / r : std::abs(dq);
}

/// What the chain meets next along the end.
enum class Event { split, mass, damper };

/// Walks an end's chain from its clamp: `visit(event, index, distance)` at every
/// split, mass and damper in the order of their positions (at one position: the
/// split first, the wave just before the loads, then the mass, then the damper),
/// `distance` from the last event.
template <class Visit>
void walk_chain(const std::vector<double>& positions, const EndAttachments& attachments, Visit&& visit) {
  std::size_t j = 0, m = 0, s = 0;
  double x = 0.0;
  for (;;) {
    double next = std::numeric_limits<double>::infinity();
    std::optional<Event> event;
    if (s < attachments.splits.size()) next = attachments.splits[s], event = Event::split;
    if (m < attachments.mass_positions.size() && attachments.mass_positions[m] < next) {
      next = attachments.mass_positions[m], event = Event::mass;
    }
    if (j < positions.size() && positions[j] < next) next = positions[j], event = Event::damper;
    if (!event) return;
    const std::size_t index = *event == Event::split ? s++ : *event == Event::mass ? m++ : j++;
    visit(*event, index, next - x);
    x = next;
  }
}

/// |a| + |b| of the wave (y, slope) as a e^{-jkx} + b e^{jkx}: its local antinode amplitude.
double local_antinode(std::complex<double> y, std::complex<double> slope, std::complex<double> jk) {
  return std::abs(0.5 * (y + slope / jk)) + std::abs(0.5 * (y - slope / jk));
}

/// A mass's Z / Z0 at the wave's frequency: j w M / Z0.
std::complex<double> mass_ratio(const StringWave& wave, double mass) {
  return {0.0, wave.angular_frequency * mass / wave.wave_impedance};
}

}  // namespace

std::vector<double> EndResponse::damper_velocities(double angular_frequency) const {
  std::vector<double> v;
  v.reserve(damper_displacement.size());
  for (const std::complex<double>& y : damper_displacement) v.push_back(angular_frequency * std::abs(y));
  return v;
}

EndResponse end_response(const StringWave& wave, const std::vector<double>& positions,
                         const std::vector<std::complex<double>>& impedances, double antinode,
                         const EndAttachments& attachments) {
  return EndChain(wave, positions, attachments).response(impedances, antinode);
}

EndSamples sample_end(const StringWave& wave, const std::vector<double>& positions,
                      const std::vector<std::complex<double>>& impedances, double antinode,
                      const EndAttachments& attachments, const std::vector<double>& distances) {
  assert(positions.size() == impedances.size());
  const double k = wave.wavenumber;
  const std::complex<double> jk(0.0, k);
  // The wave just past the clamp and past each attachment (unit slope at the clamp).
  std::vector<double> at{0.0};
  std::vector<std::complex<double>> ys{0.0}, slopes{1.0};
  std::complex<double> y = 0.0, slope = 1.0;
  walk_chain(positions, attachments, [&](Event event, std::size_t i, double distance) {
    propagate(y, slope, k, distance);
    if (event == Event::mass) slope += jk * mass_ratio(wave, attachments.masses[i]) * y;
    if (event == Event::damper) slope += jk * (impedances[i] / wave.wave_impedance) * y;
    at.push_back(at.back() + distance);
    ys.push_back(y);
    slopes.push_back(slope);
  });
  const double scale = antinode / local_antinode(y, slope, jk);
  EndSamples out;
  std::size_t stretch = 0;
  for (const double d : distances) {
    while (stretch + 1 < at.size() && at[stretch + 1] <= d) ++stretch;
    std::complex<double> yd = ys[stretch], sd = slopes[stretch];
    propagate(yd, sd, k, d - at[stretch]);
    out.displacement.push_back(scale * std::abs(yd));
    out.antinode.push_back(scale * local_antinode(yd, sd, jk));
  }
  return out;
}

EndResponseTangent end_response_tangent(const StringWave& wave, const std::vector<double>& positions,
                                        const std::vector<std::complex<double>>& impedances,
                                        const std::vector<std::complex<double>>& direction, double antinode,
                                        const EndAttachments& attachments) {
  return EndChain(wave, positions, attachments).tangent(impedances, direction, antinode);
}

EndChain::EndChain(const StringWave& wave, const std::vector<double>& positions, const EndAttachments& attachments)
    : wave_(wave), positions_(positions) {
  const double k = wave.wavenumber;
  const std::complex<double> jk(0.0, k);
  walk_chain(positions, attachments, [&](Event event, std::size_t i, double distance) {
    Step step{Kind::split, i, std::cos(k * distance), std::sin(k * distance), 0.0};
    if (event == Event::mass) step.kind = Kind::mass, step.jk_ratio = jk * mass_ratio(wave, attachments.masses[i]);
    if (event == Event::damper) step.kind = Kind::damper;
    steps_.push_back(step);
  });
}

void EndChain::propagate(const Step& step, std::complex<double>& y, std::complex<double>& slope) const {
  const double k = wave_.wavenumber;
  const std::complex<double> y_next = y * step.cos_kd + slope * step.sin_kd / k;
  slope = -y * k * step.sin_kd + slope * step.cos_kd;
  y = y_next;
}

EndResponse EndChain::response(const std::vector<std::complex<double>>& impedances, double antinode) const {
  assert(impedances.size() == positions_.size());
  const double k = wave_.wavenumber;
  const std::complex<double> jk(0.0, k);
  EndResponse r;
  // Unit slope at the fixed end: Y = sin(k x) / k up to the first attachment.
  std::complex<double> y = 0.0, slope = 1.0;
  for (const Step& step : steps_) {
    propagate(step, y, slope);
    switch (step.kind) {
      case Kind::split: r.segment_amplitude.push_back(local_antinode(y, slope, jk)); break;
      case Kind::mass:
        r.mass_displacement.push_back(y);
        slope += step.jk_ratio * y;
        break;
      case Kind::damper:
        r.damper_displacement.push_back(y);
        slope += jk * (impedances[step.index] / wave_.wave_impedance) * y;
        break;
    }
  }
  const std::complex<double> b = 0.5 * (y + slope / jk), a = 0.5 * (y - slope / jk);
  const double scale = antinode / (std::abs(a) + std::abs(b));
  r.loop_amplitude = scale / k;
  r.outgoing = scale * std::abs(a);
  r.incoming = scale * std::abs(b);
  const double w2 = wave_.angular_frequency * wave_.angular_frequency;
  r.absorbed_power = 0.5 * wave_.wave_impedance * w2 * (r.incoming * r.incoming - r.outgoing * r.outgoing);
  for (std::size_t j = 0; j < r.damper_displacement.size(); ++j) {
    r.damper_displacement[j] *= scale;
    r.damper_power += 0.5 * impedances[j].real() * w2 * std::norm(r.damper_displacement[j]);
  }
  for (std::complex<double>& ym : r.mass_displacement) ym *= scale;
  for (double& segment : r.segment_amplitude) segment *= scale;
  return r;
}

void EndChain::unit_wave(const std::complex<double>* impedances, std::complex<double>* at, std::complex<double>& y,
                         std::complex<double>& slope) const {
  const std::complex<double> jk(0.0, wave_.wavenumber);
  y = 0.0, slope = 1.0;
  for (const Step& step : steps_) {
    propagate(step, y, slope);
    if (step.kind == Kind::mass) slope += step.jk_ratio * y;
    if (step.kind == Kind::damper) {
      at[step.index] = y;
      slope += jk * (impedances[step.index] / wave_.wave_impedance) * y;
    }
  }
}

void EndChain::displacements(const std::complex<double>* impedances, double antinode, std::complex<double>* out) const {
  std::complex<double> y, slope;
  unit_wave(impedances, out, y, slope);
  const double scale = antinode / local_antinode(y, slope, std::complex<double>(0.0, wave_.wavenumber));
  for (std::size_t j = 0; j < positions_.size(); ++j) out[j] *= scale;
}

void EndChain::log_displacement_jacobian(const std::complex<double>* impedances, const std::complex<double>* slopes,
                                         double* out) const {
  const std::size_t n = positions_.size();
  const std::complex<double> jk(0.0, wave_.wavenumber);
  const double z0 = wave_.wave_impedance;
  // The unit-slope wave at each damper (a small buffer for the usual few).
  std::array<std::complex<double>, 8> local{};
  std::vector<std::complex<double>> heap(n > local.size() ? n : 0);
  std::complex<double>* at = n > local.size() ? heap.data() : local.data();
  std::complex<double> y, slope;
  unit_wave(impedances, at, y, slope);
  const std::complex<double> b = 0.5 * (y + slope / jk), a = 0.5 * (y - slope / jk);
  const double sum = std::abs(a) + std::abs(b);
  // Damper m's impedance moves the wave from its own place on: the tangent is zero
  // before it and carried by the same transfers after (the recursion is linear).
  for (std::size_t m = 0; m < n; ++m) {
    std::complex<double> dy = 0.0, dslope = 0.0;
    for (std::size_t j = 0; j < n; ++j) out[j * n + m] = 0.0;
    bool started = false;
    for (const Step& step : steps_) {
      if (started) propagate(step, dy, dslope);
      if (step.kind == Kind::mass && started) dslope += step.jk_ratio * dy;
      if (step.kind != Kind::damper) continue;
      const std::size_t j = step.index;
      if (started) {
        if (std::abs(at[j]) != 0.0) out[j * n + m] = (dy / at[j]).real();
        dslope += jk * (impedances[j] * dy / z0);
      } else if (j == m) {
        started = true;
        dslope = jk * (slopes[m] * at[m] / z0);
      }
    }
    const std::complex<double> db = 0.5 * (dy + dslope / jk), da = 0.5 * (dy - dslope / jk);
    const double d_log_scale = -(abs_change(a, da) + abs_change(b, db)) / sum;
    for (std::size_t j = 0; j < n; ++j) {
      if (std::abs(at[j]) != 0.0) out[j * n + m] += d_log_scale;
    }
  }
}

EndResponseTangent EndChain::tangent(const std::vector<std::complex<double>>& impedances,
                                     const std::vector<std::complex<double>>& direction, double antinode) const {
  assert(impedances.size() == positions_.size() && direction.size() == positions_.size());
  const std::complex<double> jk(0.0, wave_.wavenumber);
  // The recursion of response() (unit slope at the fixed end) and its derivative.
  std::complex<double> y = 0.0, slope = 1.0, dy = 0.0, dslope = 0.0;
  std::vector<std::complex<double>> at_dampers, d_at_dampers;
  for (const Step& step : steps_) {
    propagate(step, y, slope);
    propagate(step, dy, dslope);  // linear: the same transfer
    switch (step.kind) {
      case Kind::split: break;
      case Kind::mass:
        slope += step.jk_ratio * y;
        dslope += step.jk_ratio * dy;
        break;
      case Kind::damper: {
        const std::size_t j = step.index;
        at_dampers.push_back(y);
        d_at_dampers.push_back(dy);
        slope += jk * (impedances[j] / wave_.wave_impedance) * y;
        dslope += jk * ((direction[j] * y + impedances[j] * dy) / wave_.wave_impedance);
        break;
      }
    }
  }
  const std::complex<double> b = 0.5 * (y + slope / jk), a = 0.5 * (y - slope / jk);
  const std::complex<double> db = 0.5 * (dy + dslope / jk), da = 0.5 * (dy - dslope / jk);
  const double sum = std::abs(a) + std::abs(b);
  const double scale = antinode / sum;
  const double d_log_scale = -(abs_change(a, da) + abs_change(b, db)) / sum;
  EndResponseTangent t;
  for (std::size_t j = 0; j < at_dampers.size(); ++j) {
    const bool node = std::abs(at_dampers[j]) == 0.0;
    t.log_displacement.push_back(node ? 0.0 : d_log_scale + (d_at_dampers[j] / at_dampers[j]).real());
  }
  // P_d = Z0 w^2 scale^2 (|b|^2 - |a|^2) / 2
  const double w2 = wave_.angular_frequency * wave_.angular_frequency;
  const double waves = std::norm(b) - std::norm(a);
  const double d_waves = 2.0 * (std::conj(b) * db - std::conj(a) * da).real();
  t.absorbed_power = 0.5 * wave_.wave_impedance * w2 * scale * scale * (2.0 * d_log_scale * waves + d_waves);
  return t;
}

}  // namespace stockbridge::span
