#include "stockbridge/span/balance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "balance_summary.hpp"
#include "frequency_balance.hpp"
#include "polish.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::span {

DamperModel parse_damper_model(std::string_view name) {
  if (name == "travelling") return DamperModel::travelling;
  if (name == "weak") return DamperModel::weak;
  throw InvalidParameter("damper_model", fmt::format(" = '{}': expected travelling or weak", name));
}

std::string_view damper_model_name(DamperModel model) { return model == DamperModel::weak ? "weak" : "travelling"; }

void BalanceOptions::validate() const {
  within_field("table", [&] { table.validate(); });
  within_field("fixed_point", [&] { fixed_point.validate(); });
  within_field("root", [&] { root.validate(); });
  require_positive("polish_tolerance", polish_tolerance, "");
  require_in_range("max_polish_evaluations", max_polish_evaluations, 1, 1000);
  require_positive("amplitude_min_over_diameter", amplitude_min_over_diameter, "");
  if (!(amplitude_max_over_diameter > amplitude_min_over_diameter)) {
    throw_invalid("amplitude_max_over_diameter", amplitude_max_over_diameter, "a value > amplitude_min_over_diameter");
  }
}

std::vector<double> band_frequencies(const Span& span, int points) {
  const Interval band = span.wind().frequency_band(span.conductor().diameter);
  return damper::log_spaced(band.lo, band.hi, points);
}

SpanTables::SpanTables(const Span& span, std::vector<double> frequencies, const ImpedanceTableOptions& options,
                       const damper::SweepProgress& progress)
    : frequencies_(std::move(frequencies)) {
  options.validate();
  // Dampers of the same mechanics (several [[damper]] of one file) share a table, as
  // do dampers of one sheet.
  const std::vector<SpanDamper>& dampers = span.dampers();
  const auto alike = [](const SpanDamper& a, const SpanDamper& b) {
    if (a.measured() || b.measured()) return a.sheet == b.sheet;
    return a.damper->description().same_mechanics(b.damper->description());
  };
  const auto same_as_earlier = [&](std::size_t j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (alike(dampers[i], dampers[j])) return i;
    }
    return j;
  };
  std::size_t distinct = 0;
  for (std::size_t j = 0; j < dampers.size(); ++j) distinct += same_as_earlier(j) == j && !dampers[j].measured() ? 1 : 0;
  const std::size_t columns = ImpedanceTable::solved_frequencies(frequencies_, options.column_ratio).size();
  const int total = static_cast<int>(distinct * columns * static_cast<std::size_t>(options.velocities));
  int done_before = 0;
  for (std::size_t j = 0; j < dampers.size(); ++j) {
    if (const std::size_t i = same_as_earlier(j); i != j) {
      tables_.push_back(tables_[i]);
      continue;
    }
    if (dampers[j].measured()) {
      tables_.emplace_back(*dampers[j].sheet, frequencies_);
      continue;
    }
    const damper::SweepProgress per_table = [&](int done, int) {
      if (progress) progress(done_before + done, total);
    };
    tables_.emplace_back(*dampers[j].damper, frequencies_, options, per_table);
    done_before += tables_.back().nodes();
    failed_nodes_ += tables_.back().failed_nodes();
  }
  nodes_ = done_before;
}

SpanTables::SpanTables(std::vector<double> frequencies, std::vector<ImpedanceTable> tables)
    : frequencies_(std::move(frequencies)), tables_(std::move(tables)) {
  for (const ImpedanceTable& t : tables_) {
    if (t.frequencies() != frequencies_) throw std::invalid_argument("SpanTables: a table made for other frequencies");
  }
}

SpanTables::SpanTables(const SpanTables& solved, const Span& span) : SpanTables(solved) {
  if (tables_.size() != span.dampers().size()) {
    throw std::invalid_argument(fmt::format("SpanTables: {} tables for {} dampers", tables_.size(), span.dampers().size()));
  }
  for (std::size_t j = 0; j < tables_.size(); ++j) {
    if (span.dampers()[j].measured()) tables_[j] = ImpedanceTable(*span.dampers()[j].sheet, frequencies_);
  }
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A point's energy identity must hold to round-off: P_d of the ends (travelling
/// waves) equals what their dampers dissipate.
constexpr double kIdentityTolerance = 1e-8;

void fill_undamped(const Span& span, double f, BalancePoint& p) {
  const Conductor& c = span.conductor();
  const auto y = undamped_amplitude(span.wind(), span.self_damping(), c, span.tension(), span.length(), f);
  p.undamped_amplitude = y.value_or(kNaN);
  p.undamped_stress_fymax = y ? fymax_stress(c, f, *y) : kNaN;
  const double x_b = span.fatigue().yb_distance;
  p.undamped_bending_amplitude = y ? bending_amplitude(c, span.tension(), f, *y, x_b) : kNaN;
  p.undamped_stress_poffenberger_swart =
      y ? poffenberger_swart_stress(c, span.tension(), p.undamped_bending_amplitude, x_b) : kNaN;
}

/// One damper's figures at the balance.
DamperAtBalance damper_at_balance(const Span& span, const FrequencyBalance& balance, const EndSolution& s,
                                  std::size_t e, std::size_t j) {
  DamperAtBalance d;
  d.damper = balance.layouts()[e].damper[j];
  d.end = static_cast<int>(e) + 1;
  d.clamp_velocity = s.velocities[j];
  d.impedance = s.impedances[j];
  const double w = balance.wave().angular_frequency;
  d.power = 0.5 * d.impedance.real() * w * w * std::norm(s.response.damper_displacement[j]);
  d.clamp_stress = point_force_stress(span.conductor(), span.tension(), std::abs(d.impedance) * d.clamp_velocity);
  d.messenger_curvature_max = balance.messenger_curvature(e, j);
  return d;
}

/// The figures at the balance amplitude y.
void fill_balanced(const Span& span, FrequencyBalance& balance, double y, BalancePoint& p) {
  const Conductor& c = span.conductor();
  const double f = p.frequency_hz;
  const EndsAtAmplitude at = balance.dampers(y);
  p.amplitude = y;
  p.wind_power = balance.wind(y);
  p.self_damping_power = balance.self_damping(y);
  p.damper_power = at.absorbed;
  p.clamp_loop_amplitude = at.ends.empty() ? y : at.ends.front().response.loop_amplitude;
  p.stress_fymax = fymax_stress(c, f, p.clamp_loop_amplitude);
  const double x_b = span.fatigue().yb_distance;
  p.bending_amplitude = bending_amplitude(c, span.tension(), f, p.clamp_loop_amplitude, x_b);
  p.stress_poffenberger_swart = poffenberger_swart_stress(c, span.tension(), p.bending_amplitude, x_b);
  double sum_dampers = 0.0, incoming = 0.0;
  p.damper_clamp_stress = 0.0;
  const StringWave& wave = balance.wave();
  for (std::size_t e = 0; e < at.ends.size(); ++e) {
    const EndSolution& s = at.ends[e];
    sum_dampers += s.response.damper_power;
    incoming += 0.5 * wave.wave_impedance * std::norm(wave.angular_frequency * s.response.incoming);
    for (std::size_t j = 0; j < s.velocities.size(); ++j) {
      p.dampers.push_back(damper_at_balance(span, balance, s, e, j));
      p.damper_clamp_stress = std::max(p.damper_clamp_stress, p.dampers.back().clamp_stress);
    }
  }
  // Relative to the power the waves bring to the ends, the scale of P_d's round-off
  // (P_d = Z0 w^2 (|B|^2 - |A|^2) / 2 is a difference: near a node it is tiny).
  p.identity_error = incoming > 0.0 ? std::abs(p.damper_power - sum_dampers) / incoming : 0.0;
}

void mask(BalancePoint& p) {
  for (double* x : {&p.amplitude, &p.wind_power, &p.self_damping_power, &p.damper_power, &p.clamp_loop_amplitude,
                    &p.stress_fymax, &p.stress_poffenberger_swart, &p.bending_amplitude, &p.damper_clamp_stress,
                    &p.identity_error}) {
    *x = kNaN;
  }
  p.dampers.clear();
}

/// The balance amplitude at one frequency: by continuation from the last frequencies
/// (the polish), else from the tables' balance (polished, where asked).
StableRoot balanced_amplitude(FrequencyBalance& balance, Polish* polish) {
  StableRoot continued;
  if (polish && polish->continues()) {
    continued = polish->run(balance, std::nullopt);
    if (continued.converged()) return continued;
    // Once more from the tables alone, without what earlier frequencies handed on.
    polish->forget();
    balance.release();
  }
  StableRoot y = balance.balanced_amplitude();
  if (y.converged() && polish) y = polish->run(balance, y.amplitude);
  if (!y.converged() && continued.summary.termination != Termination::not_run) {
    y.summary.where = fmt::format("{} (continued from the last frequency: {})", y.summary.where,
                                  brief_report(continued.summary));
  }
  return y;
}

/// Why a measured damper's sheet cannot give Z at frequency i (empty if every sheet can).
std::string outside_sheets(const Span& span, const SpanTables& tables, std::size_t i) {
  for (std::size_t j = 0; j < span.dampers().size(); ++j) {
    const SpanDamper& d = span.dampers()[j];
    if (!d.measured() || tables.tables()[j].velocity_range(i)) continue;
    const Interval f = d.sheet->frequency_range();
    return fmt::format("damper {}: its measured sheet gives Z from {:.4g} to {:.4g} Hz (where two curves or more were "
                       "measured), not at {:.4g} Hz: no extrapolation in frequency",
                       d.name, f.lo, f.hi, tables.frequencies()[i]);
  }
  return {};
}

/// A measured damper's clamp velocity against its sheet's curves at frequency i: above
/// the highest, the point is not trusted (the reason; the sheet says nothing there);
/// below the lowest, Z was held at the lowest curve's (a note).
std::string check_sheet_velocities(const Span& span, const SpanTables& tables, std::size_t i, BalancePoint& p) {
  for (const DamperAtBalance& d : p.dampers) {
    const SpanDamper& sd = span.dampers()[d.damper];
    if (!sd.measured()) continue;
    const Interval v = *tables.tables()[d.damper].velocity_range(i);
    if (d.clamp_velocity > v.hi * (1.0 + 1e-9)) {
      return fmt::format("damper {} at end {}: its clamp velocity {:.4g} m/s is above the highest its measured sheet "
                         "gives at {:.4g} Hz, {:.4g} m/s: no extrapolation in velocity",
                         sd.name, d.end, d.clamp_velocity, p.frequency_hz, v.hi);
    }
    if (d.clamp_velocity < v.lo * (1.0 - 1e-9)) {
      p.below_sheet = true;
      p.note += fmt::format("{}damper {} at end {}: {:.3g} m/s is below its sheet's lowest curve, {:.3g} m/s: Z held at "
                            "that curve's (small amplitudes stick)",
                            p.note.empty() ? "" : "; ", sd.name, d.end, d.clamp_velocity, v.lo);
    }
  }
  return {};
}

BalancePoint balance_at(const Span& span, const SpanTables& tables, std::size_t i, Polish* polish,
                        const BalanceOptions& options) {
  BalancePoint p;
  p.frequency_hz = tables.frequencies()[i];
  p.wind_speed = span.wind().wind_speed(p.frequency_hz, span.conductor().diameter);
  p.wavelength = wavelength(span.conductor(), span.tension(), p.frequency_hz);
  fill_undamped(span, p.frequency_hz, p);
  if (std::string outside = outside_sheets(span, tables, i); !outside.empty()) {
    if (polish) polish->forget();  // the next frequency starts afresh
    p.summary.termination = Termination::inner_failure;
    p.summary.where = std::move(outside);
    mask(p);
    return p;
  }
  FrequencyBalance balance(span, tables, i, options);
  const StableRoot y = balanced_amplitude(balance, polish);
  p.summary = y.summary;
  if (!y.converged()) {
    mask(p);
    return p;
  }
  fill_balanced(span, balance, y.amplitude, p);
  if (!(p.identity_error <= kIdentityTolerance)) {
    p.summary.termination = Termination::energy_mismatch;
    p.summary.residual = p.identity_error;
    p.summary.where = fmt::format("(the ends absorb {:.6g} W but their dampers dissipate otherwise: off by {:.3g} of the "
                                  "power the waves bring to the ends)",
                                  p.damper_power, p.identity_error);
    mask(p);
    return p;
  }
  if (std::string above = check_sheet_velocities(span, tables, i, p); !above.empty()) {
    p.summary.termination = Termination::inner_failure;
    p.summary.where = std::move(above);
    mask(p);
    return p;
  }
  if (polish && polish->passed_fold()) {
    p.several_states = true;
    p.note += std::string(p.note.empty() ? "" : "; ") + "several self-consistent states near here: the dampers' clamp velocities passed a fold since the "
             "frequency before; the state continued from the band's low end is the one reported";
  }
  return p;
}

}  // namespace

SpanBalance run_balance(const Span& span, const SpanTables& tables, const BalanceOptions& options) {
  options.validate();
  if (tables.tables().size() != span.dampers().size()) {
    throw std::invalid_argument(
        fmt::format("run_balance: {} impedance tables for {} dampers", tables.tables().size(), span.dampers().size()));
  }
  SpanBalance out;
  std::optional<Polish> polish;
  if (options.polish && !span.dampers().empty()) polish.emplace(span, options);
  for (std::size_t i = 0; i < tables.frequencies().size(); ++i) {
    out.points.push_back(balance_at(span, tables, i, polish ? &*polish : nullptr, options));
  }
  out.summary = summarise(span, out.points);
  out.summary.impedance_nodes = tables.nodes();
  out.summary.failed_impedance_nodes = tables.failed_nodes();
  if (polish) out.summary.direct_solves = polish->direct_solves();
  return out;
}

}  // namespace stockbridge::span
