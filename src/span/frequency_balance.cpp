#include "frequency_balance.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

/// A damper's or mass's place on one end's chain.
struct ChainEntry {
  double distance = 0.0;  ///< from the end's clamp, m
  std::size_t index = 0;  ///< the span's damper, or the mass's value's slot
};

/// The end (0: end 1, 1: end 2) a point x from end 1 belongs to, and its distance from that clamp.
std::pair<std::size_t, double> nearer_end(double x, double length) {
  return x <= 0.5 * length ? std::pair{std::size_t{0}, x} : std::pair{std::size_t{1}, length - x};
}

void sort_by_distance(std::vector<ChainEntry>& entries) {
  std::stable_sort(entries.begin(), entries.end(),
                   [](const ChainEntry& a, const ChainEntry& b) { return a.distance < b.distance; });
}

}  // namespace

std::vector<EndLayout> end_layouts(const Span& span) {
  const double length = span.length();
  std::array<std::vector<ChainEntry>, 2> dampers, masses;
  std::array<std::vector<double>, 2> splits;
  std::vector<double> mass_values;
  std::vector<std::size_t> mass_owner;  ///< per mass value: its SpanMass
  for (std::size_t j = 0; j < span.dampers().size(); ++j) {
    const SpanDamper& d = span.dampers()[j];
    if (!d.in_span()) {
      dampers[0].push_back({d.position, j});
      if (d.both_ends) dampers[1].push_back({d.position, j});
      continue;
    }
    for (const double x : d.along) {
      const auto [e, distance] = nearer_end(x, length);
      dampers[e].push_back({distance, j});
      splits[e].push_back(distance);
    }
  }
  for (const SpanMass& m : span.masses()) {
    for (const double x : m.positions) {
      const auto [e, distance] = nearer_end(x, length);
      masses[e].push_back({distance, mass_values.size()});
      mass_values.push_back(m.mass);
      mass_owner.push_back(static_cast<std::size_t>(&m - span.masses().data()));
      splits[e].push_back(distance);
    }
  }
  std::vector<EndLayout> ends;
  for (std::size_t e = 0; e < 2; ++e) {
    EndLayout layout;
    layout.end = static_cast<int>(e) + 1;
    sort_by_distance(dampers[e]);
    sort_by_distance(masses[e]);
    for (const ChainEntry& d : dampers[e]) layout.positions.push_back(d.distance), layout.damper.push_back(d.index);
    for (const ChainEntry& m : masses[e]) {
      layout.attachments.mass_positions.push_back(m.distance);
      layout.attachments.masses.push_back(mass_values[m.index]);
      layout.mass.push_back(mass_owner[m.index]);
    }
    // The end zone, from the clamp to the end's last damper at `position`, counts with
    // the stretch past it (the energy balance's end convention): no split inside it.
    double zone = 0.0;
    for (const ChainEntry& d : dampers[e]) {
      if (!span.dampers()[d.index].in_span()) zone = std::max(zone, d.distance);
    }
    std::erase_if(splits[e], [zone](double x) { return x < zone; });
    std::sort(splits[e].begin(), splits[e].end());
    splits[e].erase(std::unique(splits[e].begin(), splits[e].end()), splits[e].end());
    layout.attachments.splits = std::move(splits[e]);
    if (!layout.positions.empty() || !layout.attachments.empty()) ends.push_back(std::move(layout));
  }
  return ends;  // nothing on the span: the string's own standing wave, S = Y
}

std::vector<SubSpan> FrequencyBalance::subspans(const std::vector<EndSolution>& ends, double y) const {
  const double length = span_.length();
  std::vector<SubSpan> out;
  double lo = 0.0, hi = length;  // the free span in the middle
  for (std::size_t e = 0; e < ends.size(); ++e) {
    const std::vector<double>& splits = layouts_[e].attachments.splits;
    const std::vector<double>& amplitudes = ends[e].response.segment_amplitude;
    double previous = 0.0;
    for (std::size_t i = 0; i < splits.size(); ++i) {
      if (layouts_[e].end == 1) {
        out.push_back({previous, splits[i], amplitudes[i]});
        lo = splits[i];
      } else {
        out.push_back({length - splits[i], length - previous, amplitudes[i]});
        hi = length - splits[i];
      }
      previous = splits[i];
    }
  }
  out.push_back({lo, hi, y});
  std::sort(out.begin(), out.end(), [](const SubSpan& a, const SubSpan& b) { return a.from < b.from; });
  return out;
}

FrequencyBalance::FrequencyBalance(const Span& span, const SpanTables& tables, std::size_t index,
                                   const BalanceOptions& options)
    : span_(span),
      tables_(tables),
      index_(index),
      frequency_(tables.frequencies().at(index)),
      options_(options),
      layouts_(end_layouts(span)) {
  if (options.damper_model == DamperModel::weak && span.has_attachments()) {
    throw InvalidParameter("damper_model", " = \"weak\": the weak-damper form takes the string's own wave; a span "
                                           "with masses or dampers along it needs \"travelling\"");
  }
  const Conductor& c = span.conductor();
  wave_.angular_frequency = 2.0 * std::numbers::pi * frequency_;
  wave_.wavenumber = wavenumber(c, span.tension(), frequency_);
  wave_.wave_impedance = wave_impedance(c, span.tension());
  for (const EndLayout& layout : layouts_) chains_.emplace_back(wave_, layout.positions, layout.attachments);
  mirrored_ = layouts_.size() == 2 && layouts_[1].mirrors(layouts_[0]);
  last_velocities_.resize(layouts_.size());
  last_amplitude_.assign(layouts_.size(), 0.0);
  fixed_.resize(layouts_.size());
  curvatures_.resize(layouts_.size());
  lowest_node_.resize(layouts_.size());
  for (std::size_t e = 0; e < layouts_.size(); ++e) {
    for (const std::size_t j : layouts_[e].damper) {
      const std::optional<Interval> range = tables.tables()[j].velocity_range(index);
      lowest_node_[e].push_back(range ? range->lo : 0.0);
    }
    fixed_[e].resize(layouts_[e].positions.size());
    curvatures_[e].assign(layouts_[e].positions.size(), std::numeric_limits<double>::quiet_NaN());
  }
}

double FrequencyBalance::wind(const std::vector<SubSpan>& subspans, double scale) const {
  double p = 0.0;
  for (const SubSpan& s : subspans) {
    p += span_.wind().power(scale * s.amplitude, frequency_, span_.conductor().diameter, s.length());
  }
  return p;
}

double FrequencyBalance::self_damping(const std::vector<SubSpan>& subspans, double scale) const {
  double p = 0.0;
  for (const SubSpan& s : subspans) {
    p += span_.self_damping().power(scale * s.amplitude, frequency_, span_.conductor(), span_.tension(), s.length());
  }
  return p;
}

double FrequencyBalance::net_power_in_proportion(double y) const {
  return wind(unit_subspans_, y) - self_damping(unit_subspans_, y);
}

double FrequencyBalance::net_power_slope(double y) {
  const double dy = 1e-6 * y;
  if (!absorbed_per_square()) {
    const std::vector<SubSpan> whole{{0.0, span_.length(), 1.0}};
    const auto net = [&](double a) { return wind(whole, a) - self_damping(whole, a); };
    return (net(y + dy) - net(y - dy)) / (2.0 * dy);
  }
  return (net_power_in_proportion(y + dy) - net_power_in_proportion(y - dy)) / (2.0 * dy);
}

EndsAtAmplitude FrequencyBalance::dampers(double y) {
  EndsAtAmplitude out;
  for (std::size_t e = 0; e < layouts_.size(); ++e) {
    // A mirror image of end 1 (the same dampers, masses and impedances held): its solution.
    if (e == 1 && mirrored_ && fixed_[1] == fixed_[0]) {
      last_velocities_[1] = last_velocities_[0];
      last_amplitude_[1] = last_amplitude_[0];
      out.absorbed += out.ends[0].response.absorbed_power;
      out.ends.push_back(out.ends[0]);
      continue;
    }
    EndSolution s = end(e, y);
    if (!s.converged()) {
      out.summary.termination = Termination::inner_failure;
      out.summary.where = fmt::format("at Y = {:.3g} m: end {}: {}", y, layouts_[e].end, brief_report(s.summary));
      return out;
    }
    last_velocities_[e] = s.velocities;
    last_amplitude_[e] = y;
    out.absorbed += s.response.absorbed_power;
    out.ends.push_back(std::move(s));
  }
  out.subspans = subspans(out.ends, y);
  out.summary.termination = Termination::converged;
  return out;
}

StableRoot FrequencyBalance::balanced_amplitude() {
  // The ends' fixed points start again from the undamped velocities (not the last
  // amplitude's): a scan over the amplitudes then gives the same balance each time.
  for (auto& v : last_velocities_) v.clear();
  std::fill(last_amplitude_.begin(), last_amplitude_.end(), 0.0);
  held_ = Held{};
  SolverSummary ends;  // the first end that failed on the way
  const auto net_power = [&](double y) {
    if (const std::optional<double> per_square = absorbed_per_square()) {
      return net_power_in_proportion(y) - *per_square * y * y;
    }
    if (y <= held_.until) return wind(held_.unit, y) - self_damping(held_.unit, y) - held_.per_square * y * y;
    const EndsAtAmplitude at = dampers(y);
    if (!at.summary.converged()) {
      if (ends.termination == Termination::not_run) ends = at.summary;
      return std::numeric_limits<double>::quiet_NaN();
    }
    note_held(at, y);
    return wind(at.subspans) - self_damping(at.subspans) - at.absorbed;
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

void FrequencyBalance::note_held(const EndsAtAmplitude& at, double y) {
  if (y <= held_.until) return;
  double until = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < at.ends.size(); ++e) {
    for (std::size_t j = 0; j < at.ends[e].velocities.size(); ++j) {
      if (fixed_[e][j]) continue;
      const double v = at.ends[e].velocities[j], lowest = lowest_node_[e][j];
      if (!(v < lowest)) return;  // on the table's slope: not held
      until = std::min(until, y * lowest / v);
    }
  }
  if (!std::isfinite(until)) return;
  held_.until = until;
  held_.per_square = at.absorbed / (y * y);
  held_.unit = at.subspans;
  for (SubSpan& s : held_.unit) s.amplitude /= y;
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
    std::vector<EndSolution> ends;
    for (std::size_t e = 0; e < layouts_.size(); ++e) {
      ends.push_back(end(e, 1.0));
      absorbed += ends.back().response.absorbed_power;
    }
    unit_subspans_ = subspans(ends, 1.0);
    absorbed_per_square_ = absorbed;
  }
  return absorbed_per_square_;
}

EndResponseTangent FrequencyBalance::end_tangent(std::size_t e, const std::vector<std::complex<double>>& z,
                                                 const std::vector<std::complex<double>>& direction) const {
  const std::vector<double>& positions = layouts_[e].positions;
  if (options_.damper_model == DamperModel::travelling) return chains_[e].tangent(z, direction, 1.0);
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
  const ClampImpedanceSlope with_slope = [&](std::size_t j, double v) -> std::optional<TableImpedance> {
    if (fixed_[e][j]) return TableImpedance{*fixed_[e][j], 0.0};
    return tables_.tables()[layout.damper[j]].at_with_slope(index_, v);
  };
  // From the last amplitude's velocities in proportion (where the impedances hold
  // still, the fixed point itself); where that finds none (past a fold of the
  // dampers' velocities), from the last amplitude's velocities themselves.
  const std::vector<double>& last = last_velocities_[e];
  if (last_amplitude_[e] > 0.0) {
    std::vector<double> scaled = last;
    for (double& v : scaled) v *= y / last_amplitude_[e];
    EndSolution s = solve_end(chains_[e], z, with_slope, y, options_.fixed_point, std::move(scaled));
    if (s.converged()) return s;
  }
  return solve_end(chains_[e], z, with_slope, y, options_.fixed_point, last);
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
  s.response = chains_[e].response(s.impedances, y);
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
