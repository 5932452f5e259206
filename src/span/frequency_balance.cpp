#include "frequency_balance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace stockbridge::span {

std::vector<EndLayout> end_layouts(const Span& span) {
  std::vector<EndLayout> ends(2);
  std::vector<std::size_t> order(span.dampers().size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return span.dampers()[a].position < span.dampers()[b].position; });
  for (const std::size_t j : order) {
    for (std::size_t e = 0; e < 2; ++e) {
      if (e == 1 && !span.dampers()[j].both_ends) continue;
      ends[e].positions.push_back(span.dampers()[j].position);
      ends[e].damper.push_back(j);
    }
  }
  if (ends[1].positions.empty()) ends.pop_back();
  if (ends[0].positions.empty()) ends.clear();  // no dampers: the string's own standing wave, S = Y
  return ends;
}

FrequencyBalance::FrequencyBalance(const Span& span, const SpanTables& tables, std::size_t index,
                                   const BalanceOptions& options)
    : span_(span),
      tables_(tables),
      index_(index),
      frequency_(tables.frequencies().at(index)),
      options_(options),
      layouts_(end_layouts(span)) {
  const Conductor& c = span.conductor();
  wave_.angular_frequency = 2.0 * std::numbers::pi * frequency_;
  wave_.wavenumber = wavenumber(c, span.tension(), frequency_);
  wave_.wave_impedance = wave_impedance(c, span.tension());
  last_velocities_.resize(layouts_.size());
  fixed_.resize(layouts_.size());
  curvatures_.resize(layouts_.size());
  for (std::size_t e = 0; e < layouts_.size(); ++e) {
    fixed_[e].resize(layouts_[e].positions.size());
    curvatures_[e].assign(layouts_[e].positions.size(), std::numeric_limits<double>::quiet_NaN());
  }
}

double FrequencyBalance::wind(double y) const {
  return span_.wind().power(y, frequency_, span_.conductor().diameter, span_.length());
}

double FrequencyBalance::self_damping(double y) const {
  return span_.self_damping().power(y, frequency_, span_.conductor(), span_.tension(), span_.length());
}

double FrequencyBalance::net_power_slope(double y) const {
  const double dy = 1e-6 * y;
  return (wind(y + dy) - self_damping(y + dy) - wind(y - dy) + self_damping(y - dy)) / (2.0 * dy);
}

EndsAtAmplitude FrequencyBalance::dampers(double y) {
  EndsAtAmplitude out;
  for (std::size_t e = 0; e < layouts_.size(); ++e) {
    EndSolution s = end(e, y);
    if (!s.converged()) {
      out.summary.termination = Termination::inner_failure;
      out.summary.where = fmt::format("at Y = {:.3g} m: end {}: {}", y, e + 1, brief_report(s.summary));
      return out;
    }
    last_velocities_[e] = s.velocities;
    out.absorbed += s.response.absorbed_power;
    out.ends.push_back(std::move(s));
  }
  out.summary.termination = Termination::converged;
  return out;
}

StableRoot FrequencyBalance::balanced_amplitude() {
  // The ends' fixed points start again from the undamped velocities (not the last
  // amplitude's): a scan over the amplitudes then gives the same balance each time.
  for (auto& v : last_velocities_) v.clear();
  SolverSummary ends;  // the first end that failed on the way
  const auto net_power = [&](double y) {
    if (const std::optional<double> per_square = absorbed_per_square()) {
      return wind(y) - self_damping(y) - *per_square * y * y;
    }
    const EndsAtAmplitude at = dampers(y);
    if (!at.summary.converged()) {
      if (ends.termination == Termination::not_run) ends = at.summary;
      return std::numeric_limits<double>::quiet_NaN();
    }
    return wind(y) - self_damping(y) - at.absorbed;
  };
  const double d = span_.conductor().diameter;
  StableRoot root = smallest_stable_root(net_power, options_.amplitude_min_over_diameter * d,
                                         options_.amplitude_max_over_diameter * d, options_.root);
  if (root.summary.termination == Termination::non_finite && ends.termination != Termination::not_run) {
    root.summary.termination = Termination::inner_failure;  // an end's fixed point, not the powers
    root.summary.where = ends.where;
  } else if (root.summary.termination == Termination::no_root) {
    root.summary.where = fmt::format("(the wind's power exceeds the dissipation {})", root.summary.where);
  }
  return root;
}

std::optional<std::complex<double>> FrequencyBalance::table_impedance(std::size_t damper, double v) const {
  return tables_.tables()[damper].at(index_, v);
}

void FrequencyBalance::fix(std::size_t e, std::size_t j, const damper::ImpedancePoint& direct) {
  fixed_[e][j] = direct.impedance;
  curvatures_[e][j] = direct.messenger_curvature_max;
  absorbed_per_square_.reset();
}

void FrequencyBalance::release() {
  for (auto& end : fixed_) std::fill(end.begin(), end.end(), std::nullopt);
  absorbed_per_square_.reset();
}

std::optional<double> FrequencyBalance::absorbed_per_square() {
  if (!absorbed_per_square_) {
    for (std::size_t e = 0; e < layouts_.size(); ++e) {
      if (!all_fixed(e)) return std::nullopt;
    }
    double absorbed = 0.0;
    for (std::size_t e = 0; e < layouts_.size(); ++e) absorbed += end(e, 1.0).response.absorbed_power;
    absorbed_per_square_ = absorbed;
  }
  return absorbed_per_square_;
}

EndResponseTangent FrequencyBalance::end_tangent(std::size_t e, const std::vector<std::complex<double>>& z,
                                                 const std::vector<std::complex<double>>& direction) const {
  const std::vector<double>& positions = layouts_[e].positions;
  if (options_.damper_model == DamperModel::travelling) {
    return end_response_tangent(wave_, positions, z, direction, 1.0);
  }
  // The weak form: Y_j = sin(k a_j) whatever the impedances, P_d = sum Re Z_j w^2 Y_j^2 / 2.
  EndResponseTangent t;
  t.log_displacement.assign(positions.size(), 0.0);
  const double w = wave_.angular_frequency;
  for (std::size_t j = 0; j < positions.size(); ++j) {
    const double yj = std::sin(wave_.wavenumber * positions[j]);
    t.absorbed_power += 0.5 * direction[j].real() * w * w * yj * yj;
  }
  return t;
}

/// End e's dampers at antinode amplitude y (its fixed point from the last one solved).
EndSolution FrequencyBalance::end(std::size_t e, double y) const {
  const EndLayout& layout = layouts_[e];
  const ClampImpedance z = [&](std::size_t j, double v) -> std::optional<std::complex<double>> {
    if (fixed_[e][j]) return fixed_[e][j];
    return tables_.tables()[layout.damper[j]].at(index_, v);
  };
  if (options_.damper_model == DamperModel::weak) return weak_end(layout, z, y);
  if (all_fixed(e)) return fixed_end(e, y);
  return solve_end(wave_, layout.positions, z, y, options_.fixed_point, last_velocities_[e]);
}

bool FrequencyBalance::all_fixed(std::size_t e) const {
  return std::all_of(fixed_[e].begin(), fixed_[e].end(), [](const auto& z) { return z.has_value(); });
}

/// An end whose every impedance the polish fixed: the string is linear then, and its
/// response is the travelling-wave solution with these impedances, whose clamp
/// velocities w |Y_j| are the fixed point itself (solve_end would find them again
/// by iterating; the polish's root search asks for some 200 amplitudes a trial).
EndSolution FrequencyBalance::fixed_end(std::size_t e, double y) const {
  EndSolution s;
  for (const auto& z : fixed_[e]) s.impedances.push_back(*z);
  s.response = end_response(wave_, layouts_[e].positions, s.impedances, y);
  for (const std::complex<double>& yj : s.response.damper_displacement) {
    s.velocities.push_back(std::max(wave_.angular_frequency * std::abs(yj), options_.fixed_point.velocity_floor));
  }
  s.summary.termination = Termination::converged;
  return s;
}

/// The weak-damper form: the string's own standing wave, Y_j = Y sin(k a_j), each
/// damper absorbing Re Z w^2 |Y_j|^2 / 2 at v_j = w |Y_j|; no fixed point.
EndSolution FrequencyBalance::weak_end(const EndLayout& layout, const ClampImpedance& z, double y) const {
  EndSolution s;
  s.response.loop_amplitude = y;
  const double w = wave_.angular_frequency;
  for (std::size_t j = 0; j < layout.positions.size(); ++j) {
    const double yj = y * std::abs(std::sin(wave_.wavenumber * layout.positions[j]));
    const auto zj = z(j, w * yj);
    if (!zj) {
      s.summary.termination = Termination::inner_failure;
      s.summary.where = fmt::format("damper {}: its impedance is not known near {:.3g} m/s", j + 1, w * yj);
      return s;
    }
    s.velocities.push_back(std::max(w * yj, options_.fixed_point.velocity_floor));
    s.impedances.push_back(*zj);
    s.response.damper_displacement.emplace_back(yj);
    const double p = 0.5 * zj->real() * w * w * yj * yj;
    s.response.damper_power += p;
    s.response.absorbed_power += p;
  }
  s.summary.termination = Termination::converged;
  return s;
}

}  // namespace stockbridge::span
