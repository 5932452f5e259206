#include "stockbridge/span/balance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "balance_run.hpp"
#include "balance_summary.hpp"
#include "frequency_balance.hpp"
#include "polish.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::span {

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

/// One damper's figures at the balance.
DamperAtBalance damper_at_balance(const Span& span, const FrequencyBalance& balance, const EndSolution& s,
                                  std::size_t e, std::size_t j) {
  const EndLayout& layout = balance.layouts()[e];
  DamperAtBalance d;
  d.damper = layout.damper[j];
  d.end = layout.end;
  d.position = layout.end == 1 ? layout.positions[j] : span.length() - layout.positions[j];
  d.clamp_velocity = s.velocities[j];
  d.impedance = s.impedances[j];
  const double w = balance.wave().angular_frequency;
  d.power = 0.5 * d.impedance.real() * w * w * std::norm(s.response.damper_displacement[j]);
  d.clamp_stress = point_force_stress(span.conductor(), span.tension(), std::abs(d.impedance) * d.clamp_velocity);
  d.messenger_curvature_max = balance.messenger_curvature(e, j);
  return d;
}

/// The masses of end e's chain at the balance, by their positions from end 1.
void add_masses(const Span& span, const FrequencyBalance& balance, const EndSolution& s, std::size_t e,
                std::vector<MassAtBalance>& masses) {
  const EndLayout& layout = balance.layouts()[e];
  const double w = balance.wave().angular_frequency;
  for (std::size_t i = 0; i < layout.mass.size(); ++i) {
    const SpanMass& mass = span.masses()[layout.mass[i]];
    const double distance = layout.attachments.mass_positions[i];
    MassAtBalance m;
    m.mass = layout.mass[i];
    m.position = layout.end == 1 ? distance : span.length() - distance;
    m.displacement = std::abs(s.response.mass_displacement[i]);
    m.clamp_stress = mass.stress_factor * point_force_stress(span.conductor(), span.tension(), w * w * mass.mass * m.displacement);
    masses.push_back(m);
  }
}

/// The span clamp's figures from its loop amplitude S: fymax, Yb and Poffenberger-Swart.
struct ClampFigures {
  double loop = 0.0, fymax = 0.0, bending = 0.0, poffenberger_swart = 0.0;
};
ClampFigures clamp_figures(const Span& span, double f, double loop) {
  const Conductor& c = span.conductor();
  const double x_b = span.fatigue().yb_distance;
  ClampFigures out;
  out.loop = loop;
  out.fymax = fymax_stress(c, f, loop);
  out.bending = bending_amplitude(c, span.tension(), f, loop, x_b);
  out.poffenberger_swart = poffenberger_swart_stress(c, span.tension(), out.bending, x_b);
  return out;
}

/// The loop amplitude S next to span clamp `end` (1 or 2): its chain's, or the free span's y.
double clamp_loop(const FrequencyBalance& balance, const EndsAtAmplitude& at, int end, double y) {
  for (std::size_t e = 0; e < at.ends.size(); ++e) {
    if (balance.layouts()[e].end == end) return at.ends[e].response.loop_amplitude;
  }
  return y;
}

/// The figures at the balance amplitude y.
void fill_balanced(const Span& span, FrequencyBalance& balance, double y, BalancePoint& p) {
  const double f = p.frequency_hz;
  const EndsAtAmplitude at = balance.dampers(y);
  p.amplitude = y;
  p.wind_power = balance.wind(at.subspans);
  p.self_damping_power = balance.self_damping(at.subspans);
  p.damper_power = at.absorbed;
  const ClampFigures one = clamp_figures(span, f, clamp_loop(balance, at, 1, y));
  p.clamp_loop_amplitude = one.loop;
  p.stress_fymax = one.fymax;
  p.bending_amplitude = one.bending;
  p.stress_poffenberger_swart = one.poffenberger_swart;
  const ClampFigures two = clamp_figures(span, f, clamp_loop(balance, at, 2, y));
  p.clamp_loop_amplitude_end2 = two.loop;
  p.stress_fymax_end2 = two.fymax;
  p.bending_amplitude_end2 = two.bending;
  p.stress_poffenberger_swart_end2 = two.poffenberger_swart;
  const auto largest = std::max_element(at.subspans.begin(), at.subspans.end(),
                                        [](const SubSpan& a, const SubSpan& b) { return a.amplitude < b.amplitude; });
  p.max_subspan_amplitude = largest->amplitude;
  p.max_subspan_from = largest->from;
  p.max_subspan_to = largest->to;
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
    add_masses(span, balance, s, e, p.masses);
  }
  std::sort(p.masses.begin(), p.masses.end(),
            [](const MassAtBalance& a, const MassAtBalance& b) { return a.position < b.position; });
  // Relative to the power the waves bring to the ends, the scale of P_d's round-off
  // (P_d = Z0 w^2 (|B|^2 - |A|^2) / 2 is a difference: near a node it is tiny).
  p.identity_error = incoming > 0.0 ? std::abs(p.damper_power - sum_dampers) / incoming : 0.0;
}

/// The span without its dampers (its masses kept) at every frequency: the undamped
/// figures. Without masses the bare string's balance (undamped.hpp); with them the
/// balance through their chain.
class UndampedSpan {
 public:
  UndampedSpan(const Span& span, const SpanTables& tables, const BalanceOptions& options)
      : span_(span.without_dampers()), tables_(tables.frequencies(), {}), options_(options) {
    options_.damper_model = DamperModel::travelling;
  }

  void fill(std::size_t i, BalancePoint& p) const {
    if (span_.masses().empty()) return fill_bare(p);
    FrequencyBalance balance(span_, tables_, i, options_);
    const StableRoot y = balance.balanced_amplitude();
    if (!y.converged()) return fill_none(p);
    BalancePoint u;
    u.frequency_hz = p.frequency_hz;
    fill_balanced(span_, balance, y.amplitude, u);
    p.undamped_amplitude = u.amplitude;
    p.undamped_stress_fymax = u.stress_fymax;
    p.undamped_bending_amplitude = u.bending_amplitude;
    p.undamped_stress_poffenberger_swart = u.stress_poffenberger_swart;
    p.undamped_judged_stress = governing_place(span_, u).stress;
    p.undamped_life_stress = life_stress(u);
  }

 private:
  void fill_bare(BalancePoint& p) const {
    const double f = p.frequency_hz;
    const auto y = undamped_amplitude(span_.wind(), span_.self_damping(), span_.conductor(), span_.tension(),
                                      span_.length(), f);
    if (!y) return fill_none(p);
    const ClampFigures clamp = clamp_figures(span_, f, *y);
    p.undamped_amplitude = *y;
    p.undamped_stress_fymax = clamp.fymax;
    p.undamped_bending_amplitude = clamp.bending;
    p.undamped_stress_poffenberger_swart = clamp.poffenberger_swart;
    p.undamped_judged_stress = span_.judges_poffenberger_swart() ? clamp.poffenberger_swart : clamp.fymax;
    p.undamped_life_stress = clamp.poffenberger_swart;
  }
  static void fill_none(BalancePoint& p) {
    for (double* x : {&p.undamped_amplitude, &p.undamped_stress_fymax, &p.undamped_bending_amplitude,
                      &p.undamped_stress_poffenberger_swart, &p.undamped_judged_stress, &p.undamped_life_stress}) {
      *x = kNaN;
    }
  }

  Span span_;
  SpanTables tables_;
  BalanceOptions options_;
};

void mask(BalancePoint& p) {
  for (double* x : {&p.amplitude, &p.wind_power, &p.self_damping_power, &p.damper_power, &p.clamp_loop_amplitude,
                    &p.stress_fymax, &p.stress_poffenberger_swart, &p.bending_amplitude, &p.damper_clamp_stress,
                    &p.identity_error, &p.clamp_loop_amplitude_end2, &p.stress_fymax_end2,
                    &p.stress_poffenberger_swart_end2, &p.bending_amplitude_end2, &p.max_subspan_amplitude,
                    &p.max_subspan_from, &p.max_subspan_to}) {
    *x = kNaN;
  }
  p.dampers.clear();
  p.masses.clear();
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
                        const BalanceOptions& options, const UndampedFigures& undamped) {
  BalancePoint p;
  p.frequency_hz = tables.frequencies()[i];
  p.wind_speed = span.wind().wind_speed(p.frequency_hz, span.conductor().diameter);
  p.wavelength = wavelength(span.conductor(), span.tension(), p.frequency_hz);
  undamped.fill(i, p);
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

UndampedFigures::UndampedFigures(const Span& span, const SpanTables& tables, const BalanceOptions& options) {
  const UndampedSpan undamped(span, tables, options);
  figures_.reserve(tables.frequencies().size());
  for (std::size_t i = 0; i < tables.frequencies().size(); ++i) {
    BalancePoint u;
    u.frequency_hz = tables.frequencies()[i];
    undamped.fill(i, u);
    figures_.push_back({u.undamped_amplitude, u.undamped_stress_fymax, u.undamped_bending_amplitude,
                        u.undamped_stress_poffenberger_swart, u.undamped_judged_stress, u.undamped_life_stress});
  }
}

void UndampedFigures::fill(std::size_t i, BalancePoint& p) const {
  const Figures& u = figures_.at(i);
  p.undamped_amplitude = u.amplitude;
  p.undamped_stress_fymax = u.stress_fymax;
  p.undamped_bending_amplitude = u.bending_amplitude;
  p.undamped_stress_poffenberger_swart = u.stress_poffenberger_swart;
  p.undamped_judged_stress = u.judged_stress;
  p.undamped_life_stress = u.life_stress;
}

BalancePoint balance_on_tables(const Span& span, const SpanTables& tables, std::size_t i, const BalanceOptions& options,
                               const UndampedFigures& undamped) {
  return balance_at(span, tables, i, nullptr, options, undamped);
}

BalanceRun::BalanceRun(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                       const UndampedFigures* undamped, std::function<void(BalancePoint&&)> take_point)
    : span_(span), tables_(tables), options_(options), take_point_(std::move(take_point)), summary_(span) {
  options.validate();
  if (tables.tables().size() != span.dampers().size()) {
    throw std::invalid_argument(
        fmt::format("run_balance: {} impedance tables for {} dampers", tables.tables().size(), span.dampers().size()));
  }
  if (options.polish && !span.dampers().empty()) polish_.emplace(span, options);
  undamped_ = undamped ? undamped : &own_undamped_.emplace(span, tables, options);
  if (!take_point_) out_.points.reserve(tables.frequencies().size());
}

const BalancePoint& BalanceRun::next() {
  settle_last();
  last_ = balance_at(span_, tables_, next_++, polish_ ? &*polish_ : nullptr, options_, *undamped_);
  return *last_;
}

void BalanceRun::settle_last() {
  if (!last_) return;
  summary_.add(*last_);
  if (take_point_) {
    take_point_(std::move(*last_));
  } else {
    out_.points.push_back(std::move(*last_));
  }
  last_.reset();
}

SpanBalance BalanceRun::finish() {
  settle_last();
  out_.summary = summary_.result();
  out_.summary.impedance_nodes = tables_.nodes();
  out_.summary.failed_impedance_nodes = tables_.failed_nodes();
  if (polish_) out_.summary.direct_solves = polish_->direct_solves();
  return std::move(out_);
}

SpanBalance run_balance(const Span& span, const SpanTables& tables, const BalanceOptions& options,
                        const UndampedFigures* undamped) {
  BalanceRun run(span, tables, options, undamped);
  while (!run.done()) run.next();
  return run.finish();
}

}  // namespace stockbridge::span
