#include "stockbridge/span/balance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/tracker.hpp"
#include "../numerics/nonlinear_system.hpp"

namespace stockbridge::span {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// How far (in polish tolerances) the directly solved impedances' own scatter can
/// move the balance's velocity: a step in h that small is round-off, not a jump.
constexpr double kPolishScatter = 10.0;

void require_one_of(const std::optional<double>& a, std::string_view a_name, const std::optional<double>& b,
                    std::string_view b_name) {
  if (a.has_value() == b.has_value()) {
    throw InvalidParameter(std::string(a.has_value() ? a_name : b_name),
                           fmt::format(": give exactly one of {} and {}", a_name, b_name));
  }
}

}  // namespace

void FatigueSpec::validate() const {
  require_one_of(cycles, "cycles", endurance_limit, "endurance_limit");
  if (cycles) require_plausible("cycles", *cycles, "");
  if (endurance_limit) require_plausible("endurance_limit", *endurance_limit, "Pa");
  if (life) life->validate();
}

Span::Span(Conductor conductor, double length, double tension, WindModel wind, SelfDampingModel self_damping,
           std::vector<SpanDamper> dampers, FatigueSpec fatigue)
    : conductor_(std::move(conductor)),
      length_(length),
      tension_(tension),
      wind_(std::move(wind)),
      self_damping_(std::move(self_damping)),
      dampers_(std::move(dampers)),
      fatigue_(std::move(fatigue)) {
  within_field("conductor", [&] { conductor_.validate(); });
  require_plausible("span.length", length_, "m");
  check_tension(conductor_, tension_, "span.tension");
  within_field("wind", [&] { wind_.validate(); });
  within_field("self_damping", [&] { self_damping_.validate(); });
  self_damping_.validate_with(conductor_);  // names conductor.ei_max itself
  for (std::size_t j = 0; j < dampers_.size(); ++j) {
    const double a = dampers_[j].position;
    if (!(a > 0.0 && a < 0.5 * length_)) {
      throw_invalid(fmt::format("damper[{}].position", j), a,
                    fmt::format("a distance from the span end > 0 and < half the span, {} m", 0.5 * length_));
    }
  }
  within_field("fatigue", [&] { fatigue_.validate(); });
}

double Span::endurance_limit() const {
  if (fatigue_.endurance_limit) return *fatigue_.endurance_limit;
  return safe_border_line(conductor_.aluminium_layers).endurance_limit(*fatigue_.cycles);
}

Span Span::with_dampers_at(double position) const {
  std::vector<SpanDamper> moved = dampers_;
  const double shift = dampers_.empty() ? 0.0 : position - dampers_.front().position;
  for (SpanDamper& d : moved) d.position += shift;
  return Span(conductor_, length_, tension_, wind_, self_damping_, std::move(moved), fatigue_);
}

Span Span::without_dampers() const { return Span(conductor_, length_, tension_, wind_, self_damping_, {}, fatigue_); }

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
  require_in_range("max_polish_iterations", max_polish_iterations, 1, 1000);
  require_positive("amplitude_min_over_diameter", amplitude_min_over_diameter, "");
  if (!(amplitude_max_over_diameter > amplitude_min_over_diameter)) {
    throw_invalid("amplitude_max_over_diameter", amplitude_max_over_diameter, "a value > amplitude_min_over_diameter");
  }
}

std::vector<double> band_frequencies(const Span& span, int points) {
  const Interval band = span.wind().frequency_band(span.conductor().diameter);
  return damper::log_spaced(band.lo, band.hi, points);
}

std::vector<ImpedanceTable> impedance_tables(const Span& span, const std::vector<double>& frequencies,
                                             const BalanceOptions& options, const damper::SweepProgress& progress) {
  options.validate();
  std::vector<ImpedanceTable> tables;
  const std::size_t columns = ImpedanceTable::solved_frequencies(frequencies, options.table.column_ratio).size();
  const int total = static_cast<int>(span.dampers().size() * columns * options.table.velocities);
  int done_before = 0;
  for (const SpanDamper& d : span.dampers()) {
    const damper::SweepProgress per_table = [&](int done, int) {
      if (progress) progress(done_before + done, total);
    };
    tables.emplace_back(d.damper, frequencies, options.table, per_table);
    done_before += tables.back().nodes();
  }
  return tables;
}

namespace {

/// The dampers of one end: their positions and which of the span's dampers each is.
struct EndLayout {
  std::vector<double> positions;
  std::vector<std::size_t> damper;
};

/// End 1 holds every damper; end 2 those mounted at both ends.
std::vector<EndLayout> end_layouts(const Span& span) {
  std::vector<EndLayout> ends(2);
  std::vector<std::size_t> order(span.dampers().size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return span.dampers()[a].position < span.dampers()[b].position; });
  for (const std::size_t j : order) {
    for (int e = 0; e < 2; ++e) {
      if (e == 1 && !span.dampers()[j].both_ends) continue;
      ends[e].positions.push_back(span.dampers()[j].position);
      ends[e].damper.push_back(j);
    }
  }
  if (ends[1].positions.empty()) ends.pop_back();
  if (ends[0].positions.empty()) ends.clear();  // no dampers: the string's own standing wave, S = Y
  return ends;
}

/// What the dampers of all ends do at one amplitude.
struct EndsAtAmplitude {
  std::vector<EndSolution> ends;
  double absorbed = 0.0;  ///< P_d of all ends, W
  bool known = true;
  std::string failure;
};

class FrequencyBalance {
 public:
  FrequencyBalance(const Span& span, std::size_t index, double frequency, const std::vector<ImpedanceTable>& tables,
                   const BalanceOptions& options)
      : span_(span), index_(index), frequency_(frequency), tables_(tables), options_(options), layouts_(end_layouts(span)) {
    const Conductor& c = span.conductor();
    wave_.angular_frequency = 2.0 * std::numbers::pi * frequency;
    wave_.wavenumber = wavenumber(c, span.tension(), frequency);
    wave_.wave_impedance = wave_impedance(c, span.tension());
    last_velocities_.resize(layouts_.size());
    fixed_.resize(layouts_.size());
    curvatures_.resize(layouts_.size());
    for (std::size_t e = 0; e < layouts_.size(); ++e) {
      fixed_[e].resize(layouts_[e].positions.size());
      curvatures_[e].assign(layouts_[e].positions.size(), kNaN);
    }
  }

  double wind(double y) const {
    return span_.wind().power(y, frequency_, span_.conductor().diameter, span_.length());
  }
  double self_damping(double y) const {
    return span_.self_damping().power(y, frequency_, span_.conductor(), span_.tension(), span_.length());
  }

  /// The ends' dampers at antinode amplitude y (the fixed point from the last one solved).
  EndsAtAmplitude dampers(double y) {
    EndsAtAmplitude out;
    for (std::size_t e = 0; e < layouts_.size(); ++e) {
      EndSolution s = end(e, y);
      if (!s.converged()) {
        out.known = false;
        out.failure = fmt::format("end {}: {}", e + 1, brief_report(s.summary));
        return out;
      }
      last_velocities_[e] = s.velocities;
      out.absorbed += s.response.absorbed_power;
      out.ends.push_back(std::move(s));
    }
    return out;
  }

  const StringWave& wave() const { return wave_; }
  const std::vector<EndLayout>& layouts() const { return layouts_; }

  /// The ends' fixed points start again from the undamped velocities (not the last
  /// amplitude's): a scan over the amplitudes then gives the same balance each time.
  void restart_fixed_points() {
    for (auto& v : last_velocities_) v.clear();
  }
  /// Back to the tables' impedances (the polish's fixed ones dropped).
  void release() {
    for (auto& end : fixed_) std::fill(end.begin(), end.end(), std::nullopt);
    absorbed_per_square_.reset();
  }

  /// Makes damper j of end e's impedance the directly solved one `direct`, whatever
  /// its clamp velocity (the polish's trial: the balance with these impedances).
  void fix(std::size_t e, std::size_t j, const damper::ImpedancePoint& direct) {
    fixed_[e][j] = direct.impedance;
    curvatures_[e][j] = direct.messenger_curvature_max;
    absorbed_per_square_.reset();
  }

  /// P_d / y^2 while every damper's impedance is fixed (the polish's trials): the
  /// string is linear then, the dampers absorb in proportion to y^2. None otherwise.
  std::optional<double> absorbed_per_square() {
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
  /// d(P_w - P_s)/dY at y (a central difference: the laws are smooth or piecewise linear).
  double net_power_slope(double y) const {
    const double dy = 1e-6 * y;
    return (wind(y + dy) - self_damping(y + dy) - wind(y - dy) + self_damping(y - dy)) / (2.0 * dy);
  }
  /// Z of span damper `damper` at clamp velocity v from its table at this frequency.
  std::optional<std::complex<double>> table_impedance(std::size_t damper, double v) const {
    return tables_[damper].at(index_, v);
  }
  /// Damper j of end e's messenger curvature from its last direct solve (NaN: none).
  double messenger_curvature(std::size_t e, std::size_t j) const { return curvatures_[e][j]; }

 private:
  /// End e's dampers at antinode amplitude y (its fixed point from the last one solved).
  EndSolution end(std::size_t e, double y) const {
    const EndLayout& layout = layouts_[e];
    const ClampImpedance z = [&](std::size_t j, double v) -> std::optional<std::complex<double>> {
      if (fixed_[e][j]) return fixed_[e][j];
      return tables_[layout.damper[j]].at(index_, v);
    };
    if (options_.damper_model == DamperModel::weak) return weak_end(layout, z, y);
    if (all_fixed(e)) return fixed_end(e, y);
    return solve_end(wave_, layout.positions, z, y, options_.fixed_point, last_velocities_[e]);
  }

  bool all_fixed(std::size_t e) const {
    return std::all_of(fixed_[e].begin(), fixed_[e].end(), [](const auto& z) { return z.has_value(); });
  }

  /// An end whose every impedance the polish fixed: the string is linear then, and its
  /// response is the travelling-wave solution with these impedances, whose clamp
  /// velocities w |Y_j| are the fixed point itself (solve_end would find them again
  /// by iterating; the polish's root search asks for some 200 amplitudes a trial).
  EndSolution fixed_end(std::size_t e, double y) const {
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
  EndSolution weak_end(const EndLayout& layout, const ClampImpedance& z, double y) const {
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
      s.velocities.push_back(w * yj);
      s.impedances.push_back(*zj);
      s.response.damper_displacement.emplace_back(yj);
      const double p = 0.5 * zj->real() * w * w * yj * yj;
      s.response.damper_power += p;
      s.response.absorbed_power += p;
    }
    s.summary.termination = Termination::converged;
    return s;
  }

  const Span& span_;
  std::size_t index_;
  double frequency_;
  const std::vector<ImpedanceTable>& tables_;
  const BalanceOptions& options_;
  std::vector<EndLayout> layouts_;
  StringWave wave_;
  std::vector<std::vector<double>> last_velocities_;
  /// Per end and damper: the impedance fixed by the polish (none: the table's at v).
  std::vector<std::vector<std::optional<std::complex<double>>>> fixed_;
  std::vector<std::vector<double>> curvatures_;  ///< per end and damper: the last direct solve's messenger curvature
  std::optional<double> absorbed_per_square_;    ///< cached by absorbed_per_square()
};

void fill_undamped(const Span& span, double f, BalancePoint& p) {
  const auto y = undamped_amplitude(span.wind(), span.self_damping(), span.conductor(), span.tension(), span.length(), f);
  p.undamped_amplitude = y.value_or(kNaN);
  p.undamped_stress_fymax = y ? fymax_stress(span.conductor(), f, *y) : kNaN;
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
  p.stress_poffenberger_swart =
      poffenberger_swart_stress(c, span.tension(), bending_amplitude(c, span.tension(), f, p.clamp_loop_amplitude));
  double sum_dampers = 0.0;
  p.damper_clamp_stress = 0.0;
  for (std::size_t e = 0; e < at.ends.size(); ++e) {
    const EndSolution& s = at.ends[e];
    sum_dampers += s.response.damper_power;
    for (std::size_t j = 0; j < s.velocities.size(); ++j) {
      DamperAtBalance d;
      d.damper = balance.layouts()[e].damper[j];
      d.end = static_cast<int>(e) + 1;
      d.clamp_velocity = s.velocities[j];
      d.impedance = s.impedances[j];
      const double w = balance.wave().angular_frequency;
      d.power = 0.5 * d.impedance.real() * w * w * std::norm(s.response.damper_displacement[j]);
      d.clamp_stress = point_force_stress(c, span.tension(), std::abs(d.impedance) * d.clamp_velocity);
      d.messenger_curvature_max = balance.messenger_curvature(e, j);
      p.damper_clamp_stress = std::max(p.damper_clamp_stress, d.clamp_stress);
      p.dampers.push_back(d);
    }
  }
  // Relative to the power the waves bring to the ends, the scale of P_d's round-off
  // (P_d = Z0 w^2 (|B|^2 - |A|^2) / 2 is a difference: near a node it is tiny).
  double incoming = 0.0;
  for (const EndSolution& s : at.ends) incoming += 0.5 * balance.wave().wave_impedance * std::norm(balance.wave().angular_frequency * s.response.incoming);
  p.identity_error = incoming > 0.0 ? std::abs(p.damper_power - sum_dampers) / incoming : 0.0;
}

void mask(BalancePoint& p) {
  for (double* x : {&p.amplitude, &p.wind_power, &p.self_damping_power, &p.damper_power, &p.clamp_loop_amplitude,
                    &p.stress_fymax, &p.stress_poffenberger_swart, &p.damper_clamp_stress, &p.identity_error}) {
    *x = kNaN;
  }
  p.dampers.clear();
}

/// A point's energy identity must hold to round-off: P_d of the ends (travelling
/// waves) equals what their dampers dissipate.
constexpr double kIdentityTolerance = 1e-8;

/// The net power P_w - P_s - P_d at antinode amplitude y with the dampers' current
/// impedances (NaN where the ends' fixed point fails; `failure` says the first).
std::function<double(double)> net_power(FrequencyBalance& balance, std::string& failure) {
  return [&balance, &failure](double y) {
    if (const std::optional<double> per_square = balance.absorbed_per_square()) {
      return balance.wind(y) - balance.self_damping(y) - *per_square * y * y;
    }
    const EndsAtAmplitude at = balance.dampers(y);
    if (!at.known) {
      if (failure.empty()) failure = fmt::format("at Y = {:.3g} m: {}", y, at.failure);
      return kNaN;
    }
    return balance.wind(y) - balance.self_damping(y) - at.absorbed;
  };
}

/// The smallest stable amplitude with the dampers' current impedances.
std::optional<double> balanced_amplitude(const Span& span, FrequencyBalance& balance, const BalanceOptions& options,
                                         std::string& failure) {
  balance.restart_fixed_points();
  const double d = span.conductor().diameter;
  return smallest_stable_root(net_power(balance, failure), options.amplitude_min_over_diameter * d,
                              options.amplitude_max_over_diameter * d, options.root);
}


/// The polish (BalanceOptions::polish): the balance found on the tables refined with
/// each damper's impedance solved directly, all dampers' clamp velocities as one
/// system. At trial clamp velocities v (u = log v, one unknown per damper of end 1
/// where end 2 mirrors it, else per damper and end), each damper is solved directly
/// there (Z_k = Z(v_k)) and the span balanced with these impedances held fixed: the
/// smallest stable amplitude of P_w - P_s - P_d with constant impedances, whose
/// dampers move at velocities G(v). The root of h(u) = log G(v) - u is found by
/// Newton's method with the Jacobian
///     dh/du = d log G / dZ . diag(dZ_k / du_k) - I,
/// where d log G / dZ is exact (the balance with fixed impedances is smooth in them:
/// end_response_tangent and the root's slope) and dZ_k / du_k, the one costly
/// derivative, a secant through the damper's last two direct solves (a damper's Z
/// depends on its own velocity alone). At the root every damper's Z is the directly
/// solved one at its own clamp velocity.
///
/// Along the band, each damper is followed by harmonic balance solved from its last
/// solution (a DamperTracker; every trial of one frequency from that frequency's
/// first solution, so that Z is a function of v even where two steady states of
/// the damper coexist), the first trial is the line through the last two
/// frequencies' solutions in (log f, log v) and the secants start with the last
/// frequency's slopes: a few direct solves a frequency.
class Polisher {
 public:
  Polisher(const Span& span, const BalanceOptions& options) : span_(span), options_(options) {
    for (const SpanDamper& d : span.dampers()) trackers_.emplace_back(d.damper, options.table.solver);
  }

  /// The balance amplitude with directly solved impedances: from the tables' balance
  /// amplitude y, or without it from the last frequencies' solutions (continues()).
  std::optional<double> run(FrequencyBalance& balance, std::optional<double> y, std::string& failure);
  /// Whether a frequency was polished before (since forget()): run can continue from it.
  bool continues() const { return !history_.empty(); }
  /// Drops what the last frequencies handed on (after a failure: it may mislead).
  void forget() {
    slopes_.clear();
    history_.clear();
  }

  int direct_solves() const {
    int n = 0;
    for (const damper::DamperTracker& t : trackers_) n += t.solves();
    return n;
  }

 private:
  /// One unknown: a damper of the span and the (end, index) slots whose velocity it is.
  struct Unknown {
    std::size_t damper;
    std::vector<std::pair<std::size_t, std::size_t>> slots;
  };
  /// The span at trial velocities: the balance with the directly solved impedances.
  struct Trial {
    Eigen::VectorXd u;                          ///< log v
    std::vector<damper::ImpedancePoint> direct;  ///< per unknown, its damper solved directly
    std::vector<std::complex<double>> z;        ///< per unknown
    double absorbed_per_square = 0.0;           ///< P_d(1): the ends' P_d / Y^2, W/m^2
    double amplitude = 0.0;                     ///< Y with these impedances held fixed
    Eigen::VectorXd h;                          ///< log G - u
    double norm = 0.0;                          ///< max |h|
  };

  std::vector<Unknown> unknowns_of(const FrequencyBalance& balance) const;
  /// Solves every damper directly at exp(u) and balances the span with those impedances.
  std::optional<Trial> evaluate(FrequencyBalance& balance, const Eigen::VectorXd& u, std::string& failure);
  /// dh/du at a trial (the impedances fixed in `balance` are the trial's).
  Eigen::MatrixXd jacobian(FrequencyBalance& balance, const Trial& trial) const;
  /// The first trial velocities (log) of a frequency from the last frequencies'
  /// solutions (the line through the last two, or the last); false without any.
  bool first_trial(double log_f, Eigen::VectorXd& u) const;
  void update_slopes(const Trial& trial);

  const Span& span_;
  const BalanceOptions& options_;
  std::vector<damper::DamperTracker> trackers_;  ///< one per damper of the span
  std::vector<std::optional<damper::DamperTracker::Checkpoint>> anchors_;  ///< per damper: this frequency's first solution
  std::vector<Unknown> unknowns_;
  std::vector<std::complex<double>> slopes_;  ///< dZ/du per unknown, the last secant (NaN: unknown)
  std::optional<Trial> last_solved_;          ///< this frequency's last trial, for the secants
  struct Solution {
    double log_f;
    Eigen::VectorXd u;  ///< log v* per unknown
  };
  std::vector<Solution> history_;  ///< the frequencies polished
};

std::vector<Polisher::Unknown> Polisher::unknowns_of(const FrequencyBalance& balance) const {
  const std::vector<EndLayout>& ends = balance.layouts();
  std::vector<Unknown> unknowns;
  const bool mirrored = ends.size() == 2 && ends[1].damper == ends[0].damper;
  for (std::size_t e = 0; e < ends.size(); ++e) {
    for (std::size_t j = 0; j < ends[e].damper.size(); ++j) {
      if (mirrored && e == 1) {
        unknowns[j].slots.emplace_back(e, j);
      } else {
        unknowns.push_back({ends[e].damper[j], {{e, j}}});
      }
    }
  }
  return unknowns;
}

std::optional<Polisher::Trial> Polisher::evaluate(FrequencyBalance& balance, const Eigen::VectorXd& u,
                                                  std::string& failure) {
  const double f = balance.wave().angular_frequency / (2.0 * std::numbers::pi);
  Trial t;
  t.u = u;
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    const Unknown& unknown = unknowns_[k];
    damper::DamperTracker& tracker = trackers_[unknown.damper];
    if (anchors_[unknown.damper]) tracker.restore(*anchors_[unknown.damper]);
    const double v = std::exp(u[static_cast<Eigen::Index>(k)]);
    const damper::Excitation excitation = damper::Excitation::from_velocity(f, v);
    damper::ImpedancePoint direct = tracker.solve(excitation);
    if (!direct.converged() && !anchors_[unknown.damper]) {
      // Where the path from the last frequency fails (the arm's stick resonance
      // passed between them, say), from a cold start.
      tracker.forget();
      direct = tracker.solve(excitation);
    }
    if (!direct.converged()) {
      failure = fmt::format("end {}, damper {} solved directly at {:.4g} m/s: {}", unknown.slots[0].first + 1,
                            unknown.slots[0].second + 1, v, direct.failure);
      return std::nullopt;
    }
    if (!anchors_[unknown.damper]) anchors_[unknown.damper] = tracker.checkpoint();
    for (const auto& [e, j] : unknown.slots) balance.fix(e, j, direct);
    t.z.push_back(direct.impedance);
    t.direct.push_back(direct);
  }
  t.absorbed_per_square = *balance.absorbed_per_square();
  const auto y = balanced_amplitude(span_, balance, options_, failure);
  if (!y) return std::nullopt;
  t.amplitude = *y;
  t.h = Eigen::VectorXd::Zero(u.size());
  if (*y <= 0.0) return t;  // with these impedances nothing builds up
  const EndsAtAmplitude at = balance.dampers(*y);
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    const auto [e, j] = unknowns_[k].slots[0];
    const auto i = static_cast<Eigen::Index>(k);
    t.h[i] = std::log(at.ends[e].velocities[j]) - u[i];
  }
  t.norm = t.h.cwiseAbs().maxCoeff();
  return t;
}

Eigen::MatrixXd Polisher::jacobian(FrequencyBalance& balance, const Trial& trial) const {
  const auto n = static_cast<Eigen::Index>(unknowns_.size());
  const std::vector<EndLayout>& ends = balance.layouts();
  const double y = trial.amplitude;
  const double per_square = trial.absorbed_per_square;
  // The root of P_w - P_s - P_d(1) Y^2 moves by dY = Y^2 dP_d(1) / N'(Y).
  const double slope = balance.net_power_slope(y) - 2.0 * per_square * y;
  std::vector<std::vector<std::complex<double>>> z(ends.size());
  for (std::size_t e = 0; e < ends.size(); ++e) z[e].resize(ends[e].positions.size());
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    for (const auto& [e, j] : unknowns_[k].slots) z[e][j] = trial.z[k];
  }
  Eigen::MatrixXd jac = -Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index m = 0; m < n; ++m) {
    const std::complex<double> dz = slopes_[static_cast<std::size_t>(m)];
    std::vector<EndResponseTangent> tangents;
    double d_absorbed = 0.0;
    for (std::size_t e = 0; e < ends.size(); ++e) {
      std::vector<std::complex<double>> direction(ends[e].positions.size(), 0.0);
      for (const auto& [se, sj] : unknowns_[static_cast<std::size_t>(m)].slots) {
        if (se == e) direction[sj] = dz;
      }
      tangents.push_back(end_response_tangent(balance.wave(), ends[e].positions, z[e], direction, 1.0));
      d_absorbed += tangents.back().absorbed_power;
    }
    const double d_log_y = y * d_absorbed / slope;
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto [e, j] = unknowns_[static_cast<std::size_t>(k)].slots[0];
      jac(k, m) += d_log_y + tangents[e].log_displacement[j];
    }
  }
  return jac;
}

void Polisher::update_slopes(const Trial& trial) {
  if (last_solved_) {
    for (std::size_t k = 0; k < unknowns_.size(); ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      const double du = trial.u[i] - last_solved_->u[i];
      if (std::abs(du) > 1e-9) slopes_[k] = (trial.z[k] - last_solved_->z[k]) / du;
    }
  }
  last_solved_ = trial;
}

bool Polisher::first_trial(double log_f, Eigen::VectorXd& u) const {
  if (history_.empty() || history_.back().u.size() != u.size()) return false;
  const Solution& b = history_.back();
  if (history_.size() < 2) {
    u = b.u;
    return true;
  }
  const Solution& a = history_[history_.size() - 2];
  const double t = (log_f - b.log_f) / (b.log_f - a.log_f);
  u = b.u + t * (b.u - a.u);
  return true;
}

std::optional<double> Polisher::run(FrequencyBalance& balance, std::optional<double> y, std::string& failure) {
  unknowns_ = unknowns_of(balance);
  const auto n = static_cast<Eigen::Index>(unknowns_.size());
  const double log_f = std::log(balance.wave().angular_frequency);
  Eigen::VectorXd u(n);
  if (y) {
    if (*y <= 0.0) return y;  // nothing builds up: the dampers stand still
    const EndsAtAmplitude first = balance.dampers(*y);
    if (!first.known) {
      failure = first.failure;
      return std::nullopt;
    }
    for (std::size_t k = 0; k < unknowns_.size(); ++k) {
      const auto [e, j] = unknowns_[k].slots[0];
      u[static_cast<Eigen::Index>(k)] = std::log(first.ends[e].velocities[j]);
    }
    slopes_.clear();
  } else if (!first_trial(log_f, u)) {
    failure = "no earlier frequency to continue from";
    return std::nullopt;
  }
  anchors_.assign(trackers_.size(), std::nullopt);
  last_solved_.reset();
  if (slopes_.size() != unknowns_.size()) {
    // The tables' slopes in log v where the last frequency left none.
    slopes_.assign(unknowns_.size(), 0.0);
    for (std::size_t k = 0; k < unknowns_.size(); ++k) {
      const double v = std::exp(u[static_cast<Eigen::Index>(k)]);
      const auto hi = balance.table_impedance(unknowns_[k].damper, v * std::exp(0.05));
      const auto lo = balance.table_impedance(unknowns_[k].damper, v * std::exp(-0.05));
      if (hi && lo) slopes_[k] = (*hi - *lo) / 0.1;
    }
  }
  std::vector<Trial> trials;  // this frequency's, for the Jacobian at the solver's point
  std::optional<double> still;  // an amplitude <= 0: with these impedances nothing builds up
  const numerics::Residual residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    std::optional<Trial> trial = evaluate(balance, x, failure);
    if (!trial) return false;
    if (trial->amplitude <= 0.0) {
      still = trial->amplitude;
      r = Eigen::VectorXd::Zero(n);
      return true;
    }
    update_slopes(*trial);
    r = trial->h;
    trials.push_back(std::move(*trial));
    return true;
  };
  const numerics::ResidualJacobian jacobian_at = [&](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    const auto trial = std::find_if(trials.rbegin(), trials.rend(), [&](const Trial& t) { return t.u == x; });
    if (trial == trials.rend()) return false;
    jac = jacobian(balance, *trial);
    return true;
  };
  numerics::NonlinearSystemOptions system;
  system.tolerance = options_.polish_tolerance;
  system.max_evaluations = options_.max_polish_iterations;
  const numerics::NonlinearSystemResult solved =
      numerics::solve_fixed_point(residual, jacobian_at, u, system, kPolishScatter * options_.polish_tolerance);
  if (still) return *still;
  if (!solved.summary.converged()) {
    if (solved.summary.termination != Termination::inner_failure) {
      failure = fmt::format("the clamp velocities with directly solved impedances: {} (tolerance {:.3g})",
                            brief_report(solved.summary), options_.polish_tolerance);
    } else if (failure.empty()) {
      failure = "the polish's Jacobian could not be evaluated";
    }
    return std::nullopt;
  }
  history_.push_back({log_f, solved.x});
  // The balance ends with the solution's impedances fixed.
  const auto trial = std::find_if(trials.rbegin(), trials.rend(), [&](const Trial& t) { return t.u == solved.x; });
  for (std::size_t k = 0; k < unknowns_.size(); ++k) {
    for (const auto& [e, j] : unknowns_[k].slots) balance.fix(e, j, trial->direct[k]);
  }
  return trial->amplitude;
}

BalancePoint balance_at(const Span& span, std::size_t i, double f, const std::vector<ImpedanceTable>& tables,
                        Polisher* polisher, const BalanceOptions& options) {
  BalancePoint p;
  p.frequency_hz = f;
  p.wind_speed = span.wind().wind_speed(f, span.conductor().diameter);
  p.wavelength = wavelength(span.conductor(), span.tension(), f);
  fill_undamped(span, f, p);
  FrequencyBalance balance(span, i, f, tables, options);
  std::string failure;
  std::optional<double> y;
  if (polisher && polisher->continues()) {
    y = polisher->run(balance, std::nullopt, failure);
    if (!y) {
      // Once more from the tables alone, without what earlier frequencies handed on.
      polisher->forget();
      balance.release();
      failure.clear();
    }
  }
  if (!y) {
    y = balanced_amplitude(span, balance, options, failure);
    if (y && polisher) y = polisher->run(balance, *y, failure);
  }
  if (!y) {
    const double y_max = options.amplitude_max_over_diameter * span.conductor().diameter;
    p.termination = failure.empty() ? Termination::max_iterations : Termination::inner_failure;
    p.failure = failure.empty() ? fmt::format("no balance: the wind's power exceeds the dissipation up to Y = {:.3g} m", y_max)
                                : failure;
    mask(p);
    return p;
  }
  fill_balanced(span, balance, *y, p);
  if (!(p.identity_error <= kIdentityTolerance)) {
    p.termination = Termination::energy_mismatch;
    p.failure = fmt::format("the ends absorb {:.6g} W but their dampers dissipate otherwise: off by {:.3g} of the "
                            "power the waves bring to the ends",
                            p.damper_power, p.identity_error);
    mask(p);
    return p;
  }
  p.termination = Termination::converged;
  return p;
}

BalanceSummary summarise(const Span& span, const std::vector<BalancePoint>& points, const std::vector<ImpedanceTable>& tables) {
  BalanceSummary s;
  s.points = static_cast<int>(points.size());
  s.endurance_limit = span.endurance_limit();
  std::vector<double> frequencies, stresses, undamped;
  for (const BalancePoint& p : points) {
    frequencies.push_back(p.frequency_hz);
    undamped.push_back(std::isfinite(p.undamped_stress_fymax) ? p.undamped_stress_fymax : 0.0);
    if (std::isfinite(p.undamped_stress_fymax) && p.undamped_stress_fymax > s.undamped_max_stress_fymax) {
      s.undamped_max_stress_fymax = p.undamped_stress_fymax;
      s.undamped_max_stress_frequency_hz = p.frequency_hz;
    }
    stresses.push_back(p.converged() ? p.stress_fymax : 0.0);
    if (!p.converged()) continue;
    ++s.converged;
    if (p.stress_fymax > s.max_stress_fymax) {
      s.max_stress_fymax = p.stress_fymax;
      s.max_stress_frequency_hz = p.frequency_hz;
    }
    s.max_damper_clamp_stress = std::max(s.max_damper_clamp_stress, p.damper_clamp_stress);
  }
  s.safe = s.converged == s.points && s.max_stress_fymax <= s.endurance_limit;
  if (span.fatigue().life && !points.empty()) {
    const SafeBorderLine line = safe_border_line(span.conductor().aluminium_layers);
    const double d = span.conductor().diameter;
    s.life = estimate_life(frequencies, stresses, span.wind(), d, *span.fatigue().life, line);
    s.undamped_life = estimate_life(frequencies, undamped, span.wind(), d, *span.fatigue().life, line);
  }
  for (const ImpedanceTable& t : tables) {
    s.impedance_nodes += t.nodes();
    s.failed_impedance_nodes += t.failed_nodes();
  }
  return s;
}

}  // namespace

SpanBalance run_balance(const Span& span, const std::vector<double>& frequencies, const std::vector<ImpedanceTable>& tables,
                        const BalanceOptions& options) {
  options.validate();
  if (tables.size() != span.dampers().size()) {
    throw InvalidParameter("tables", fmt::format(": {} impedance tables for {} dampers", tables.size(), span.dampers().size()));
  }
  for (const ImpedanceTable& t : tables) {
    if (t.frequencies() != frequencies) throw InvalidParameter("tables", ": made for other frequencies");
  }
  SpanBalance out;
  std::optional<Polisher> polisher;
  if (options.polish && !span.dampers().empty()) polisher.emplace(span, options);
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    out.points.push_back(balance_at(span, i, frequencies[i], tables, polisher ? &*polisher : nullptr, options));
  }
  out.summary = summarise(span, out.points, tables);
  if (polisher) out.summary.direct_solves = polisher->direct_solves();
  return out;
}

PositionSearch optimise_position(const Span& span, const std::vector<double>& frequencies,
                                 const std::vector<ImpedanceTable>& tables, const BalanceOptions& options,
                                 double position_min, double position_max, int scan_points) {
  require_positive("position_min", position_min, "m");
  if (!(position_max > position_min)) throw_invalid("position_max", position_max, "a value > position_min (m)");
  require_in_range("scan_points", scan_points, 3, 10000);
  if (span.dampers().empty()) throw InvalidParameter("damper: a position search needs at least one [[damper]]");
  PositionSearch best;
  // The search compares positions on the tables alone (the polish would cost direct
  // solves at every trial); the chosen position is then balanced with the caller's options.
  BalanceOptions scan = options;
  scan.polish = false;
  const auto largest_stress = [&](double a) {
    ++best.balances;
    const SpanBalance b = run_balance(span.with_dampers_at(a), frequencies, tables, scan);
    // A point that did not converge counts as the worst: never chosen for it.
    return b.summary.converged == b.summary.points ? b.summary.max_stress_fymax : std::numeric_limits<double>::infinity();
  };
  // The scan finds the best basin (the stress over position has a local minimum near
  // every node of the shortest waves); golden sections then refine within it.
  const double step = (position_max - position_min) / (scan_points - 1);
  std::vector<double> stress(static_cast<std::size_t>(scan_points));
  std::size_t k_best = 0;
  for (int k = 0; k < scan_points; ++k) {
    stress[static_cast<std::size_t>(k)] = largest_stress(position_min + k * step);
    if (stress[static_cast<std::size_t>(k)] < stress[k_best]) k_best = static_cast<std::size_t>(k);
  }
  double lo = std::max(position_min, position_min + (static_cast<double>(k_best) - 1.0) * step);
  double hi = std::min(position_max, position_min + (static_cast<double>(k_best) + 1.0) * step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = largest_stress(x1), f2 = largest_stress(x2);
  while (hi - lo > 1e-3 * step) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = largest_stress(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = largest_stress(x2);
    }
  }
  best.position = f1 <= f2 ? x1 : x2;
  best.max_stress_fymax = std::min(f1, f2);
  if (stress[k_best] < best.max_stress_fymax) {
    best.position = position_min + static_cast<double>(k_best) * step;
    best.max_stress_fymax = stress[k_best];
  }
  return best;
}

}  // namespace stockbridge::span
