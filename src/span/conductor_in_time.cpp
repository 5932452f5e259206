#include "stockbridge/span/conductor_in_time.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <Eigen/SparseLU>
#include <fmt/format.h>

#include "hermite_element.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/span/self_damping.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

std::string_view settled_by_name(SettledBy rule) {
  switch (rule) {
    case SettledBy::envelope: return "envelope";
    case SettledBy::mean: return "mean";
    case SettledBy::not_settled: break;
  }
  return "not_settled";
}

using namespace hermite;

namespace {

/// The wavenumber of the beam-string at angular frequency w: T k^2 + EI k^4 = m w^2.
double wavenumber(const BeamProperties& p, double w) {
  if (p.ei == 0.0) return w * std::sqrt(p.mass_per_length / p.tension);
  const double k2 = (-p.tension + std::sqrt(p.tension * p.tension + 4.0 * p.ei * p.mass_per_length * w * w)) / (2.0 * p.ei);
  return std::sqrt(k2);
}

/// The local antinode amplitude of the standing wave y^ at x: sqrt(|y^|^2 + |y^'/k|^2).
double local_antinode(const BeamModel& model, const Eigen::VectorXcd& y, double x, double k) {
  const auto [w, slope] = model.at(y, x);
  return std::sqrt(std::norm(w) + std::norm(slope / k));
}

/// Whether the envelope has settled: the distance to where it is going, below
/// `tolerance` of it. The envelope approaches its steady value geometrically (the
/// net power is linear in the amplitude's distance from it), so the value it goes
/// to is extrapolated from three envelopes `apart` periods apart (Aitken's delta^2);
/// where the last two changes are not such an approach (growing, or changing
/// sign), it has settled only if it no longer changes.
bool settled(const std::vector<double>& envelope, double tolerance, std::size_t apart) {
  const std::size_t n = envelope.size();
  if (n <= 2 * apart) return false;
  const double y0 = envelope[n - 1 - 2 * apart], y1 = envelope[n - 1 - apart], y2 = envelope[n - 1];
  const double d1 = y1 - y0, d2 = y2 - y1;
  double remaining = std::abs(d2);
  if (d1 != 0.0 && d2 / d1 > 0.0 && d2 / d1 < 1.0) remaining = std::abs(d2 * d2 / (d1 - d2));
  return remaining <= tolerance * y2;
}

}  // namespace
void check_in_time(const Span& span) {
  if (!span.masses().empty()) {
    throw InvalidParameter("mass[0]", ": masses along the span are not modelled in time yet; take them out of the span file "
                                      "(the balance, `stockbridge span`, models them)");
  }
  for (std::size_t j = 0; j < span.dampers().size(); ++j) {
    if (!span.dampers()[j].damper) {
      throw InvalidParameter(fmt::format("damper[{}]", j),
                             " is a measured impedance sheet, which has no form in time: give the damper's own file");
    }
  }
}

namespace {

/// The span's dampers at their positions from end 1, each stepped by `dt`, in the
/// file's order (a damper at both ends: end 1's first).
std::vector<BeamDamper> dampers_in_time(const Span& span, double dt, const damper::TimeDomainOptions& options,
                                        std::vector<std::string>& names) {
  check_in_time(span);
  std::vector<BeamDamper> out;
  for (std::size_t j = 0; j < span.dampers().size(); ++j) {
    const SpanDamper& d = span.dampers()[j];
    for (const double position : d.positions_from_end1(span.length())) {
      out.push_back({position, damper::DamperInTime(*d.damper, dt, options)});
      names.push_back(d.name);
    }
  }
  return out;
}

/// Nodes about `spacing` apart with one at each of `fixed` (m from end 1).
std::vector<double> mesh_nodes(double length, double spacing, std::vector<double> fixed) {
  fixed.push_back(0.0);
  fixed.push_back(length);
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  std::vector<double> nodes{0.0};
  for (std::size_t i = 1; i < fixed.size(); ++i) {
    const double a = fixed[i - 1], b = fixed[i];
    const int parts = std::max(1, static_cast<int>(std::ceil((b - a) / spacing)));
    for (int j = 1; j < parts; ++j) nodes.push_back(a + (b - a) * j / parts);
    nodes.push_back(b);
  }
  if (nodes.size() == 2) nodes.insert(nodes.begin() + 1, 0.5 * length);
  return nodes;
}

/// The beam's natural mode nearest w_asked (shift-invert about it: one mode by
/// inverse iteration, a dense solve of the pencil being too large), mass-normalised,
/// with its w^2.
std::pair<Eigen::VectorXd, double> drive_mode(const BeamModel& model, double w_asked, double frequency_hz) {
  const Eigen::SparseMatrix<double> shifted = model.stiffness() - (w_asked * w_asked) * model.mass();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> shift_invert(shifted);
  if (shift_invert.info() != Eigen::Success) throw NumericalError("the drive frequency is a natural frequency to round-off");
  Eigen::VectorXd mode = Eigen::VectorXd::Ones(model.size());
  double w2 = w_asked * w_asked, change = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    mode = shift_invert.solve(model.mass() * mode);
    mode /= std::sqrt(mode.dot(model.mass() * mode));
    const double next = mode.dot(model.stiffness() * mode);
    change = std::abs(next - w2) / w2;
    w2 = next;
    if (change <= 1e-14) return {mode, w2};
  }
  // Two modes about equally near the drive: the iteration cannot pick one.
  throw NumericalError(fmt::format("the span's natural mode nearest {} Hz: inverse iteration did not converge in 200 "
                                   "iterations (w^2 still changing by {:.2g} relative); two modes lie about equally "
                                   "near: ask for a frequency nearer one of them",
                                   frequency_hz, change));
}

/// The EBM's wind (a) as a distributed force c_w(x) y_t on the velocity's component
/// at the drive, and its self-damping as a distributed damper c_s(x) on the whole
/// velocity: c from element e's local antinode amplitude, so that over a loop
/// mean(c v^2) = c w^2 Y^2 / 4 is the EBM's power per length there (P_w / L, P_s / L).
class EbmWindLoad {
 public:
  EbmWindLoad(const Span& span, const BeamModel& model, double w, double k) : span_(span), model_(model), w_(w), k_(k) {}

  /// The complex amplitude of q = c_w v at the drive, for the standing wave y^.
  Eigen::VectorXcd operator()(const Eigen::VectorXcd& y) const {
    const Conductor& conductor = span_.conductor();
    const double f = w_ / (2.0 * std::numbers::pi), length = span_.length();
    Eigen::VectorXcd load = Eigen::VectorXcd::Zero(model_.size());
    for (int e = 0; e < model_.elements(); ++e) {
      const double amplitude = local_antinode(model_, y, 0.5 * (model_.nodes()[e] + model_.nodes()[e + 1]), k_);
      if (!(amplitude > 0.0)) continue;
      const double wind = span_.wind().power(amplitude, f, conductor.diameter, length) / length;
      const std::complex<double> c(0.0, 4.0 * wind / (w_ * amplitude * amplitude));  // j w c_w
      const std::array<Eigen::Index, 4> dofs = element_dofs(model_, e);
      const Eigen::Vector4cd part = c * (unit_mass(model_.element_length(e)) * gather(model_, e, y));
      for (int i = 0; i < 4; ++i) {
        if (dofs[i] >= 0) load(dofs[i]) += part(i);
      }
    }
    return load;
  }

  /// The self-damping as a damping matrix on the whole velocity, sum_e c_e int N^T N
  /// over element e, c_e = 4 p_s(Y_e) / (w^2 Y_e^2) from the drive's local amplitude.
  Eigen::SparseMatrix<double> self_damping(const Eigen::VectorXcd& y) const {
    const Conductor& conductor = span_.conductor();
    const double f = w_ / (2.0 * std::numbers::pi), length = span_.length();
    std::vector<Eigen::Triplet<double>> triplets;
    for (int e = 0; e < model_.elements(); ++e) {
      const double amplitude = local_antinode(model_, y, 0.5 * (model_.nodes()[e] + model_.nodes()[e + 1]), k_);
      // Every element's entries, zero or not: the pattern the factorisation was analysed for.
      const double c = amplitude > 0.0 ? 4.0 * span_.self_damping().power(amplitude, f, conductor, span_.tension(), length) /
                                             length / (w_ * w_ * amplitude * amplitude)
                                       : 0.0;
      add_element(triplets, element_dofs(model_, e), c * unit_mass(model_.element_length(e)));
    }
    Eigen::SparseMatrix<double> out(model_.size(), model_.size());
    out.setFromTriplets(triplets.begin(), triplets.end());
    return out;
  }

 private:
  const Span& span_;
  const BeamModel& model_;
  double w_, k_;
};

/// The wake oscillators on the beam: each element's oscillator driven by the beam's
/// acceleration at the element's middle, its lift (1/4) rho U^2 D C_L0 q uniform over
/// the element, as the consistent load int N^T dx.
class WakeLoad {
 public:
  WakeLoad(const Span& span, const BeamModel& model, const WakeParameters& parameters, double shedding_hz, double dt)
      : wind_speed_(shedding_hz * span.conductor().diameter / span.wind().strouhal),
        lift_scale_(0.25 * parameters.air_density * wind_speed_ * wind_speed_ * span.conductor().diameter *
                    parameters.lift_coefficient),
        oscillators_(model.elements(), parameters, 2.0 * std::numbers::pi * shedding_hz, span.conductor().diameter, dt),
        middles_(model.elements(), model.size()), loads_(model.size(), model.elements()),
        middle_acceleration_(model.elements()), load_(Eigen::VectorXd::Zero(model.size())) {
    std::vector<Eigen::Triplet<double>> middle, load;
    for (int e = 0; e < model.elements(); ++e) {
      const double h = model.element_length(e);
      const std::array<double, 4> at_middle{0.5, h / 8.0, 0.5, -h / 8.0};  // the Hermite functions at the middle
      const std::array<double, 4> integral{0.5 * h, h * h / 12.0, 0.5 * h, -h * h / 12.0};  // int N dx
      const std::array<Eigen::Index, 4> dofs = element_dofs(model, e);
      for (int i = 0; i < 4; ++i) {
        if (dofs[i] < 0) continue;
        middle.emplace_back(e, dofs[i], at_middle[i]);
        load.emplace_back(dofs[i], e, integral[i]);
      }
    }
    middles_.setFromTriplets(middle.begin(), middle.end());
    loads_.setFromTriplets(load.begin(), load.end());
  }

  double wind_speed() const { return wind_speed_; }
  /// The lift at the step's end, from the beam's acceleration at its start.
  const Eigen::VectorXd& step(const Eigen::VectorXd& beam_acceleration) {
    middle_acceleration_.noalias() = middles_ * beam_acceleration;
    oscillators_.step(middle_acceleration_);
    load_.noalias() = loads_ * oscillators_.q();
    load_ *= lift_scale_;
    return load_;
  }
  const Eigen::VectorXd& load() const { return load_; }

 private:
  double wind_speed_, lift_scale_;
  WakeOscillators oscillators_;
  Eigen::SparseMatrix<double> middles_, loads_;
  Eigen::VectorXd middle_acceleration_, load_;  ///< a step's workspace
};

/// A damper's samples over one period: the clamp's force and velocity at each step,
/// the work and dissipation at the period's start.
struct DamperPeriod {
  std::vector<double> force, velocity;
  double work_start = 0.0, dissipated_start = 0.0;
};

/// What one period gave: the envelope, the loop amplitudes next to the clamps, the dampers' figures.
struct PeriodFigures {
  double envelope = 0.0;
  double wind_power = 0.0, damping_power = 0.0;
  std::array<double, 2> end_loop{};
  std::vector<DamperInTimeFigures> dampers;
};

/// Whether the envelope's means over consecutive windows have settled (as settled()
/// does on the envelope itself, on three windows' means).
bool settled_in_the_mean(const std::vector<double>& envelope, int window, double tolerance) {
  const std::size_t n = envelope.size(), w = static_cast<std::size_t>(window);
  if (n < 3 * w || n % w != 0) return false;  // judged once a window
  auto mean = [&](std::size_t end) {
    double sum = 0.0;
    for (std::size_t i = end - w; i < end; ++i) sum += envelope[i];
    return sum / static_cast<double>(w);
  };
  const double m0 = mean(n - 2 * w), m1 = mean(n - w), m2 = mean(n);
  const double d1 = m1 - m0, d2 = m2 - m1;
  double remaining = std::abs(d2);
  if (d1 != 0.0 && d2 / d1 > 0.0 && d2 / d1 < 1.0) remaining = std::abs(d2 * d2 / (d1 - d2));
  return remaining <= tolerance * m2;
}

constexpr int kForceHarmonics = 5;

DamperInTimeFigures damper_figures(const DamperPeriod& period, const BeamDamper& d, double work_now, double period_s,
                                   int steps, std::string name) {
  DamperInTimeFigures out;
  out.name = std::move(name);
  out.position_m = d.position_m;
  out.power_w = -(work_now - period.work_start) / period_s;
  out.dissipated_w = (d.damper.dissipated() - period.dissipated_start) / period_s;
  std::complex<double> velocity = 0.0;
  for (int h = 1; h <= kForceHarmonics; ++h) {
    std::complex<double> force = 0.0;
    for (int j = 0; j < steps; ++j) {
      const std::complex<double> phasor = std::polar(2.0 / steps, -2.0 * std::numbers::pi * h * (j + 1) / steps);
      force += period.force[j] * phasor;
      if (h == 1) velocity += period.velocity[j] * phasor;
    }
    out.force_harmonics_n.push_back(std::abs(force));
  }
  out.velocity_amplitude_m_s = std::abs(velocity);
  return out;
}

/// The steady figures of `out`: means over the last `count` periods of `records`.
void take_means(const std::vector<PeriodFigures>& records, int count, EbmWindHistory& out) {
  out.figure_periods = static_cast<int>(std::min<std::size_t>(records.size(), static_cast<std::size_t>(count)));
  if (out.figure_periods == 0) return;
  const auto first = records.end() - out.figure_periods;
  const double n = out.figure_periods;
  double sum = 0.0, squares = 0.0;
  out.dampers = first->dampers;
  for (DamperInTimeFigures& d : out.dampers) {
    d.power_w = d.dissipated_w = d.velocity_amplitude_m_s = 0.0;
    std::fill(d.force_harmonics_n.begin(), d.force_harmonics_n.end(), 0.0);
  }
  for (auto r = first; r != records.end(); ++r) {
    out.wind_power_w += r->wind_power / n;
    out.damping_power_w += r->damping_power / n;
    sum += r->envelope;
    squares += r->envelope * r->envelope;
    for (int e = 0; e < 2; ++e) out.end_loop_amplitude_m[e] += r->end_loop[e] / n;
    for (std::size_t d = 0; d < out.dampers.size(); ++d) {
      DamperInTimeFigures& to = out.dampers[d];
      const DamperInTimeFigures& from = r->dampers[d];
      to.power_w += from.power_w / n;
      to.dissipated_w += from.dissipated_w / n;
      to.velocity_amplitude_m_s += from.velocity_amplitude_m_s / n;
      for (std::size_t h = 0; h < to.force_harmonics_n.size(); ++h) to.force_harmonics_n[h] += from.force_harmonics_n[h] / n;
    }
  }
  out.antinode_amplitude_m = sum / n;
  out.envelope_fluctuation = std::sqrt(std::max(0.0, squares / n - out.antinode_amplitude_m * out.antinode_amplitude_m)) /
                             out.antinode_amplitude_m;
}


/// The drive's complex amplitude y^ of the displacement: each period's quadrature,
/// `(2 / N) sum u(t_i) e^(-j w t_i)`, and their mean over the last round trip of a
/// wave along the span, whose neighbouring modes (c / 2L apart) it cancels.
class DrivePhasor {
 public:
  DrivePhasor(Eigen::Index size, double w, int steps, int round_trip)
      : w_(w), steps_(steps), round_trip_(static_cast<std::size_t>(round_trip)), re_(size), im_(size),
        period_(size), sum_(Eigen::VectorXcd::Zero(size)) {}

  void start_period() {
    re_.setZero();
    im_.setZero();
  }
  void add(double t, const Eigen::VectorXd& u) {
    re_.noalias() += (2.0 / steps_ * std::cos(w_ * t)) * u;
    im_.noalias() -= (2.0 / steps_ * std::sin(w_ * t)) * u;
  }
  /// y^ once a period is done: y(t) = Re(y^ e^{jwt}).
  Eigen::VectorXcd close_period() {
    period_.real() = re_;
    period_.imag() = im_;
    phasors_.push_back(period_);
    sum_ += period_;
    if (phasors_.size() > round_trip_) {
      sum_ -= phasors_.front();
      phasors_.pop_front();
    }
    return sum_ / static_cast<double>(phasors_.size());
  }

 private:
  double w_;
  int steps_;
  std::size_t round_trip_;
  Eigen::VectorXd re_, im_;
  Eigen::VectorXcd period_, sum_;
  std::deque<Eigen::VectorXcd> phasors_;
};

/// The wind's force Re(A e^{jwt}) = Re A cos(wt) - Im A sin(wt), into one vector a step.
class DriveLoad {
 public:
  explicit DriveLoad(const Eigen::VectorXcd& amplitude, double w) : w_(w) { set(amplitude); }
  void set(const Eigen::VectorXcd& amplitude) {
    re_ = amplitude.real();
    im_ = amplitude.imag();
  }
  const Eigen::VectorXd& at(double t) {
    load_ = std::cos(w_ * t) * re_;
    load_.noalias() -= std::sin(w_ * t) * im_;
    return load_;
  }

 private:
  double w_;
  Eigen::VectorXd re_, im_, load_;
};

/// Each damper's force and clamp velocity at every step of a period, and its work and
/// dissipation at the period's start: its figures once the period is done.
class DamperRecorder {
 public:
  DamperRecorder(std::size_t dampers, int steps, std::vector<std::string> names)
      : periods_(dampers), steps_(steps), names_(std::move(names)) {
    for (DamperPeriod& p : periods_) p.force.resize(steps), p.velocity.resize(steps);
  }
  void start_period(const NewmarkStepper& stepper) {
    for (std::size_t d = 0; d < periods_.size(); ++d) {
      periods_[d].work_start = stepper.dampers_work_of(d);
      periods_[d].dissipated_start = stepper.dampers()[d].damper.dissipated();
    }
  }
  void record(int step, const NewmarkStepper& stepper) {
    for (std::size_t d = 0; d < periods_.size(); ++d) {
      periods_[d].force[step] = stepper.dampers()[d].damper.force();
      periods_[d].velocity[step] = stepper.clamp_velocity(d);
    }
  }
  std::vector<DamperInTimeFigures> figures(const NewmarkStepper& stepper) const {
    std::vector<DamperInTimeFigures> out;
    for (std::size_t d = 0; d < periods_.size(); ++d) {
      out.push_back(damper_figures(periods_[d], stepper.dampers()[d], stepper.dampers_work_of(d), steps_ * stepper.dt(),
                                   steps_, names_[d]));
    }
    return out;
  }

 private:
  std::vector<DamperPeriod> periods_;
  int steps_;
  std::vector<std::string> names_;
};

/// The two rules that judge the envelope settled, period by period.
class Settling {
 public:
  Settling(const EbmWindOptions& options, int round_trip, int window)
      : change_(options.settled_change), mean_change_(options.settled_mean_change),
        apart_(static_cast<std::size_t>(std::max(10, round_trip))), window_(window) {}

  SettledBy judge(const std::vector<double>& envelope) {
    // Settled for 20 periods in a row (a start's transient, the drive mode reshaped by
    // the dampers, can look settled for a moment), from envelopes a round trip apart at
    // least: y^ is a mean over one.
    quiet_periods_ = settled(envelope, change_, apart_) ? quiet_periods_ + 1 : 0;
    if (quiet_periods_ >= 20) return SettledBy::envelope;
    if (settled_in_the_mean(envelope, window_, mean_change_)) return SettledBy::mean;
    return SettledBy::not_settled;
  }

 private:
  double change_, mean_change_;
  std::size_t apart_;
  int window_;
  int quiet_periods_ = 0;
};

}  // namespace

EbmWindHistory settle_on_ebm_wind(const Span& span, BeamEnds ends, const EbmWindOptions& options,
                                  const std::vector<PointDashpot>& dashpots) {
  require_positive("frequency", options.frequency_hz, "Hz");
  require_positive("duration", options.duration_s, "s");
  require_in_range("elements_per_wavelength", options.elements_per_wavelength, 4, 1000);
  require_in_range("steps_per_period", options.steps_per_period, 8, 100000);
  require_positive("start_amplitude", options.start_amplitude_m, "m");
  require_positive("settled_change", options.settled_change, "");
  require_positive("settled_mean_change", options.settled_mean_change, "");
  within_field("damper", [&] { options.damper.validate(); });
  within_field("wake", [&] { options.wake.validate(); });
  const Conductor& conductor = span.conductor();
  const BeamProperties beam{span.length(), conductor.mass_per_length, span.tension(), conductor.ei_min, ends};
  const double w_asked = 2.0 * std::numbers::pi * options.frequency_hz;
  const double wavelength = 2.0 * std::numbers::pi / wavenumber(beam, w_asked);

  // The dampers' positions are the mesh's nodes; their steppers need dt, which
  // follows from the mesh's drive mode: placed first, stepped once dt is known.
  std::vector<std::string> names;
  std::vector<double> fixed;
  for (const BeamDamper& d : dampers_in_time(span, 1.0, options.damper, names)) fixed.push_back(d.position_m);
  for (const PointDashpot& d : dashpots) {
    if (d.position_m > 0.0 && d.position_m < beam.length) fixed.push_back(d.position_m);  // else refused below
  }
  const BeamModel model(beam, mesh_nodes(beam.length, wavelength / options.elements_per_wavelength, fixed));
  const int elements = model.elements();
  const auto [mode, w2] = drive_mode(model, w_asked, options.frequency_hz);
  const double wn = std::sqrt(w2);
  // Newmark's average acceleration lengthens the period: tan(w dt / 2) = wn dt / 2.
  // dt is chosen so that the stepped mode's period is exactly steps_per_period steps.
  const int steps = options.steps_per_period;
  const double dt = 2.0 * std::tan(std::numbers::pi / steps) / wn;
  const double w = 2.0 * std::numbers::pi / (steps * dt);
  const double f = w / (2.0 * std::numbers::pi);
  const double k = wavenumber(beam, w);
  names.clear();
  std::vector<BeamDamper> dampers = dampers_in_time(span, dt, options.damper, names);

  // The start: the mode at its displacement peak, its largest local antinode amplitude as asked.
  const Eigen::VectorXcd mode_c = mode.cast<std::complex<double>>();
  double largest = 0.0;
  for (const double x : model.nodes()) largest = std::max(largest, local_antinode(model, mode_c, x, k));
  const Eigen::VectorXd u0 = mode * (options.start_amplitude_m / largest);

  const double length = beam.length;
  const EbmWindLoad wind_load(span, model, w, k);
  EbmWindHistory out;
  out.frequency_hz = f;
  out.elements = elements;
  out.dt_s = dt;
  Eigen::VectorXcd y = u0.cast<std::complex<double>>();  // the standing wave at t = 0
  const bool wake = options.wind == WindInTime::wake;
  DriveLoad load(wake ? Eigen::VectorXcd::Zero(model.size()) : wind_load(y), w);
  std::optional<WakeLoad> wake_load;  // q = 0: no lift at t = 0
  if (wake) {
    wake_load.emplace(span, model, options.wake, options.frequency_hz, dt);
    out.wind_speed_m_s = wake_load->wind_speed();
  }
  const Eigen::SparseMatrix<double> dashpot_damping = model.damping(dashpots);
  Eigen::VectorXd load_now = load.at(0.0), u_now = u0;
  NewmarkStepper stepper(model, dt, u0, Eigen::VectorXd::Zero(model.size()), load_now,
                         dashpot_damping + wind_load.self_damping(y), std::move(dampers));
  const int round_trip = std::max(1, static_cast<int>(std::lround(2.0 * length / (w / k) * f)));
  const int window = std::max(20, 2 * round_trip);  // the means' window: two round trips
  DrivePhasor phasor(model.size(), w, steps, round_trip);
  DamperRecorder recorder(stepper.dampers().size(), steps, std::move(names));
  Settling settling(options, round_trip, window);
  std::vector<PeriodFigures> records;
  const int periods = static_cast<int>(std::ceil(options.duration_s * f));
  for (int period = 0; period < periods && out.settled_by == SettledBy::not_settled; ++period) {
    phasor.start_period();
    recorder.start_period(stepper);
    const double dissipated_start = stepper.dissipated();
    double wind_work = 0.0;
    for (int s = 0; s < steps && !out.interrupted; ++s) {
      const double t = stepper.time() + dt;
      const Eigen::VectorXd& load_next = wake ? wake_load->step(stepper.acceleration()) : load.at(t);
      stepper.step(load_next);
      wind_work += 0.5 * (stepper.displacement() - u_now).dot(load_now + load_next);  // the rule's own work
      u_now = stepper.displacement();
      load_now = load_next;
      phasor.add(t, stepper.displacement());
      recorder.record(s, stepper);
      if (options.observer) options.observer(stepper);
      out.interrupted = options.stop && options.stop->load();
    }
    if (out.interrupted) break;  // a part period: the figures stay the whole periods'
    y = phasor.close_period();
    if (!wake) load.set(wind_load(y));
    stepper.set_damping(dashpot_damping + wind_load.self_damping(y));
    PeriodFigures& record = records.emplace_back();
    record.wind_power = wind_work / (steps * dt);
    record.damping_power = (stepper.dissipated() - dissipated_start) / (steps * dt);
    record.envelope = local_antinode(model, y, 0.5 * length, k);
    record.end_loop = {local_antinode(model, y, 0.5 * model.element_length(0), k),
                       local_antinode(model, y, length - 0.5 * model.element_length(elements - 1), k)};
    record.dampers = recorder.figures(stepper);
    out.envelope_m.push_back(record.envelope);
    out.settled_by = settling.judge(out.envelope_m);
  }
  out.settled = out.settled_by != SettledBy::not_settled;
  out.time_s = stepper.time();
  for (const PointDashpot& d : dashpots) {  // c w^2 |y^(x)|^2 / 2 over the last period
    out.dashpot_power_w.push_back(0.5 * d.coefficient_n_s_m * w * w * std::norm(model.at(y, d.position_m).first));
  }
  const int taken = out.settled_by == SettledBy::mean ? window : out.settled_by == SettledBy::envelope ? 20 : 1;
  take_means(records, taken, out);
  for (const double x : model.nodes()) {
    out.x_m.push_back(x);
    out.amplitude_m.push_back(std::abs(model.at(y, x).first));
    out.antinode_along_m.push_back(local_antinode(model, y, x, k));
  }
  return out;
}

}  // namespace stockbridge::span
