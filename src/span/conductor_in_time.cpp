#include "stockbridge/span/conductor_in_time.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>
#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/self_damping.hpp"
#include "stockbridge/span/wind.hpp"

namespace stockbridge::span {

std::string_view beam_ends_name(BeamEnds ends) { return ends == BeamEnds::pinned ? "pinned" : "clamped"; }

BeamEnds parse_beam_ends(std::string_view name) {
  if (name == "pinned") return BeamEnds::pinned;
  if (name == "clamped") return BeamEnds::clamped;
  throw InvalidParameter(fmt::format("ends = '{}': expected \"pinned\" or \"clamped\"", name));
}

double BeamProperties::pinned_frequency(int n) const {
  const double kn = n * std::numbers::pi / length;
  return n / (2.0 * length) * std::sqrt(tension / mass_per_length) * std::sqrt(1.0 + kn * kn * ei / tension);
}

namespace {

using Matrix4 = Eigen::Matrix4d;

/// The Hermite element's matrices (degrees of freedom w1, theta1, w2, theta2), length h.
Matrix4 unit_mass(double h) {  // ∫ N^T N dx
  Matrix4 m;
  m << 156, 22 * h, 54, -13 * h,  //
      22 * h, 4 * h * h, 13 * h, -3 * h * h,  //
      54, 13 * h, 156, -22 * h,  //
      -13 * h, -3 * h * h, -22 * h, 4 * h * h;
  return m * (h / 420.0);
}
Matrix4 bending(double h) {  // ∫ N''^T N'' dx
  Matrix4 k;
  k << 12, 6 * h, -12, 6 * h,  //
      6 * h, 4 * h * h, -6 * h, 2 * h * h,  //
      -12, -6 * h, 12, -6 * h,  //
      6 * h, 2 * h * h, -6 * h, 4 * h * h;
  return k / (h * h * h);
}
Matrix4 geometric(double h) {  // ∫ N'^T N' dx
  Matrix4 g;
  g << 36, 3 * h, -36, 3 * h,  //
      3 * h, 4 * h * h, -3 * h, -h * h,  //
      -36, -3 * h, 36, -3 * h,  //
      3 * h, -h * h, -3 * h, 4 * h * h;
  return g / (30.0 * h);
}

/// The free indices of element e's four degrees of freedom (-1 where held).
std::array<Eigen::Index, 4> element_dofs(const BeamModel& model, int e) {
  return {model.index(e, 0), model.index(e, 1), model.index(e + 1, 0), model.index(e + 1, 1)};
}

void add_element(std::vector<Eigen::Triplet<double>>& triplets, const std::array<Eigen::Index, 4>& dofs,
                 const Matrix4& matrix) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (dofs[r] >= 0 && dofs[c] >= 0) triplets.emplace_back(dofs[r], dofs[c], matrix(r, c));
    }
  }
}

/// The element's shape functions N(s) and their slopes N'(s) at s = (x - x_e) / h in [0, 1].
Eigen::Vector4d shape(double s, double h) {
  return {1 - 3 * s * s + 2 * s * s * s, h * (s - 2 * s * s + s * s * s), 3 * s * s - 2 * s * s * s, h * (s * s * s - s * s)};
}
Eigen::Vector4d shape_slope(double s, double h) {
  return {(-6 * s + 6 * s * s) / h, 1 - 4 * s + 3 * s * s, (6 * s - 6 * s * s) / h, 3 * s * s - 2 * s};
}

/// The element of x and where in it (s in [0, 1]).
std::pair<int, double> element_at(const BeamModel& model, double x) {
  const double h = model.element_length();
  const int e = std::clamp(static_cast<int>(x / h), 0, model.elements() - 1);
  return {e, std::clamp(x / h - e, 0.0, 1.0)};
}

/// Element e's four values of the free vector u (0 where held).
template <class Scalar>
Eigen::Matrix<Scalar, 4, 1> gather(const BeamModel& model, int e, const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& u) {
  const std::array<Eigen::Index, 4> dofs = element_dofs(model, e);
  Eigen::Matrix<Scalar, 4, 1> q;
  for (int i = 0; i < 4; ++i) q(i) = dofs[i] >= 0 ? u(dofs[i]) : Scalar(0);
  return q;
}

}  // namespace

BeamModel::BeamModel(const BeamProperties& properties, int elements) : properties_(properties), elements_(elements) {
  require_positive("length", properties.length, "m");
  require_positive("mass_per_length", properties.mass_per_length, "kg/m");
  require_positive("tension", properties.tension, "N");
  if (!(properties.ei >= 0.0) || !std::isfinite(properties.ei)) throw_invalid("ei", properties.ei, "a finite value >= 0 (N m^2)");
  require_in_range("elements", elements, 2, 1000000);
  const int nodes = elements + 1;
  dof_.assign(2 * nodes, -1);
  Eigen::Index next = 0;
  for (int i = 0; i < nodes; ++i) {
    const bool end = i == 0 || i == elements;
    if (!end) dof_[2 * i] = next++;
    if (!end || properties.ends == BeamEnds::pinned) dof_[2 * i + 1] = next++;
  }
  const double h = element_length();
  const Matrix4 m = properties.mass_per_length * unit_mass(h);
  const Matrix4 k = properties.ei * bending(h) + properties.tension * geometric(h);
  std::vector<Eigen::Triplet<double>> mass, stiffness;
  for (int e = 0; e < elements; ++e) {
    add_element(mass, element_dofs(*this, e), m);
    add_element(stiffness, element_dofs(*this, e), k);
  }
  mass_.resize(next, next);
  stiffness_.resize(next, next);
  mass_.setFromTriplets(mass.begin(), mass.end());
  stiffness_.setFromTriplets(stiffness.begin(), stiffness.end());
}

Eigen::SparseMatrix<double> BeamModel::damping(const std::vector<PointDashpot>& dashpots) const {
  std::vector<Eigen::Triplet<double>> triplets;
  const double h = element_length();
  for (std::size_t i = 0; i < dashpots.size(); ++i) {
    const PointDashpot& d = dashpots[i];
    if (!(d.position_m > 0.0 && d.position_m < properties_.length)) {
      throw_invalid(fmt::format("dashpots[{}].position", i), d.position_m,
                    fmt::format("a distance from end 1 > 0 and < the span's length, {} m", properties_.length));
    }
    require_positive(fmt::format("dashpots[{}].coefficient", i), d.coefficient_n_s_m, "N s/m");
    const auto [e, s] = element_at(*this, d.position_m);
    const Eigen::Vector4d n = shape(s, h);
    add_element(triplets, element_dofs(*this, e), d.coefficient_n_s_m * n * n.transpose());
  }
  Eigen::SparseMatrix<double> out(size(), size());
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

std::vector<double> BeamModel::natural_frequencies(int count) const {
  require_in_range("count", count, 1, size());
  const Eigen::MatrixXd k(stiffness_), m(mass_);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, m, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success) throw NumericalError("the beam's eigenproblem did not converge");
  std::vector<double> f(count);
  for (int n = 0; n < count; ++n) f[n] = std::sqrt(std::max(solver.eigenvalues()(n), 0.0)) / (2.0 * std::numbers::pi);
  return f;
}

template <class Scalar>
std::pair<Scalar, Scalar> BeamModel::at(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& u, double x) const {
  const auto [e, s] = element_at(*this, x);
  const Eigen::Matrix<Scalar, 4, 1> q = gather(*this, e, u);
  return {shape(s, element_length()).template cast<Scalar>().dot(q),
          shape_slope(s, element_length()).template cast<Scalar>().dot(q)};
}
template std::pair<double, double> BeamModel::at(const Eigen::VectorXd&, double) const;
template std::pair<std::complex<double>, std::complex<double>> BeamModel::at(const Eigen::VectorXcd&, double) const;

NewmarkStepper::NewmarkStepper(const BeamModel& model, double dt, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                               const Eigen::VectorXd& load0, Eigen::SparseMatrix<double> damping)
    : model_(model), damping_(std::move(damping)), dt_(dt), u_(u0), v_(v0) {
  require_positive("dt", dt, "s");
  if (u0.size() != model.size() || v0.size() != model.size() || load0.size() != model.size()) {
    throw InvalidParameter("initial state", fmt::format(": expected {} values (the free degrees of freedom)", model.size()));
  }
  if (damping_.size() == 0) damping_.resize(model.size(), model.size());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> mass(model.mass());
  a_ = mass.solve(load0 - model.stiffness() * u0 - damping_ * v0);
  const Eigen::SparseMatrix<double> effective =
      model.mass() + (0.5 * dt) * damping_ + (0.25 * dt * dt) * model.stiffness();
  effective_.compute(effective);
  if (effective_.info() != Eigen::Success) throw NumericalError("Newmark: M + dt C / 2 + dt^2 K / 4 is not positive definite");
}

// With beta = 1/4, gamma = 1/2: u+ = u + dt v + dt^2 (a + a+) / 4 and v+ = v + dt (a + a+) / 2,
// so (M + dt C / 2 + dt^2 K / 4) a+ = F+ - C (v + dt a / 2) - K (u + dt v + dt^2 a / 4).
void NewmarkStepper::step(const Eigen::VectorXd& load_next) {
  const Eigen::VectorXd predicted_u = u_ + dt_ * v_ + (0.25 * dt_ * dt_) * a_;
  const Eigen::VectorXd predicted_v = v_ + (0.5 * dt_) * a_;
  rhs_ = load_next - model_.stiffness() * predicted_u - damping_ * predicted_v;
  const Eigen::VectorXd a_next = effective_.solve(rhs_);
  const Eigen::VectorXd v_before = v_;
  u_ = predicted_u + (0.25 * dt_ * dt_) * a_next;
  v_ = predicted_v + (0.5 * dt_) * a_next;
  a_ = a_next;
  const Eigen::VectorXd v_sum = v_before + v_;
  dissipated_ += 0.25 * dt_ * v_sum.dot(damping_ * v_sum);
  time_ += dt_;
}

double NewmarkStepper::energy() const {
  return 0.5 * (v_.dot(model_.mass() * v_) + u_.dot(model_.stiffness() * u_));
}

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
/// to is extrapolated from three envelopes 10 periods apart (Aitken's delta^2);
/// where the last two changes are not such an approach (growing, or changing
/// sign), it has settled only if it no longer changes.
bool settled(const std::vector<double>& envelope, double tolerance) {
  constexpr std::size_t kApart = 10;
  const std::size_t n = envelope.size();
  if (n <= 2 * kApart) return false;
  const double y0 = envelope[n - 1 - 2 * kApart], y1 = envelope[n - 1 - kApart], y2 = envelope[n - 1];
  const double d1 = y1 - y0, d2 = y2 - y1;
  double remaining = std::abs(d2);
  if (d1 != 0.0 && d2 / d1 > 0.0 && d2 / d1 < 1.0) remaining = std::abs(d2 * d2 / (d1 - d2));
  return remaining <= tolerance * y2;
}

}  // namespace

EbmWindHistory settle_on_ebm_wind(const Span& span, BeamEnds ends, const EbmWindOptions& options,
                                  const std::vector<PointDashpot>& dashpots) {
  require_positive("frequency", options.frequency_hz, "Hz");
  require_positive("duration", options.duration_s, "s");
  require_in_range("elements_per_wavelength", options.elements_per_wavelength, 4, 1000);
  require_in_range("steps_per_period", options.steps_per_period, 8, 100000);
  require_positive("start_amplitude", options.start_amplitude_m, "m");
  require_positive("settled_change", options.settled_change, "");
  const Conductor& conductor = span.conductor();
  const BeamProperties beam{span.length(), conductor.mass_per_length, span.tension(), conductor.ei_min, ends};
  const double w_asked = 2.0 * std::numbers::pi * options.frequency_hz;
  const double wavelength = 2.0 * std::numbers::pi / wavenumber(beam, w_asked);
  const int elements = std::max(2, static_cast<int>(std::ceil(options.elements_per_wavelength * beam.length / wavelength)));
  const BeamModel model(beam, elements);

  // The mode nearest the drive (shift-invert about the asked frequency: a dense
  // solve of the pencil is too large here, so one mode by inverse iteration).
  const Eigen::SparseMatrix<double> shifted = model.stiffness() - (w_asked * w_asked) * model.mass();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> shift_invert(shifted);
  if (shift_invert.info() != Eigen::Success) throw NumericalError("the drive frequency is a natural frequency to round-off");
  Eigen::VectorXd mode = Eigen::VectorXd::Ones(model.size());
  double w2 = w_asked * w_asked, change = 0.0;
  bool found = false;
  for (int iteration = 0; iteration < 200 && !found; ++iteration) {
    mode = shift_invert.solve(model.mass() * mode);
    mode /= std::sqrt(mode.dot(model.mass() * mode));
    const double next = mode.dot(model.stiffness() * mode);
    change = std::abs(next - w2) / w2;
    found = change <= 1e-14;
    w2 = next;
  }
  if (!found) {  // two modes about equally near the drive: the iteration cannot pick one
    throw NumericalError(fmt::format("the span's natural mode nearest {} Hz: inverse iteration did not converge in 200 "
                                     "iterations (w^2 still changing by {:.2g} relative); two modes lie about equally "
                                     "near: ask for a frequency nearer one of them",
                                     options.frequency_hz, change));
  }
  const double wn = std::sqrt(w2);
  // Newmark's average acceleration lengthens the period: tan(w dt / 2) = wn dt / 2.
  // dt is chosen so that the stepped mode's period is exactly steps_per_period steps.
  const int steps = options.steps_per_period;
  const double dt = 2.0 * std::tan(std::numbers::pi / steps) / wn;
  const double w = 2.0 * std::numbers::pi / (steps * dt);
  const double f = w / (2.0 * std::numbers::pi);
  const double k = wavenumber(beam, w);

  // The start: the mode at its displacement peak, its largest local antinode amplitude as asked.
  const Eigen::VectorXcd mode_c = mode.cast<std::complex<double>>();
  double largest = 0.0;
  for (int i = 0; i <= elements; ++i) largest = std::max(largest, local_antinode(model, mode_c, i * model.element_length(), k));
  const Eigen::VectorXd u0 = mode * (options.start_amplitude_m / largest);

  const Matrix4 unit = unit_mass(model.element_length());
  const double length = beam.length;
  // c_e from element e's local antinode amplitude: over a loop, mean(q v) = c w^2 Y^2 / 4
  // is the EBM's net power per length there, (P_w - P_s) / L.
  auto damping_load = [&](const Eigen::VectorXcd& y) {
    Eigen::VectorXcd load = Eigen::VectorXcd::Zero(model.size());
    for (int e = 0; e < elements; ++e) {
      const double amplitude = local_antinode(model, y, (e + 0.5) * model.element_length(), k);
      if (!(amplitude > 0.0)) continue;
      const double net = (span.wind().power(amplitude, f, conductor.diameter, length) -
                          span.self_damping().power(amplitude, f, conductor, span.tension(), length)) /
                         length;
      const std::complex<double> c(0.0, 4.0 * net / (w * amplitude * amplitude));  // j w c
      const std::array<Eigen::Index, 4> dofs = element_dofs(model, e);
      const Eigen::Vector4cd part = c * (unit * gather(model, e, y));
      for (int i = 0; i < 4; ++i) {
        if (dofs[i] >= 0) load(dofs[i]) += part(i);
      }
    }
    return load;  // the complex amplitude of q = c v at the drive frequency
  };

  EbmWindHistory out;
  out.frequency_hz = f;
  out.elements = elements;
  out.dt_s = dt;
  Eigen::VectorXcd y = u0.cast<std::complex<double>>();  // the standing wave at t = 0
  Eigen::VectorXcd load_amplitude = damping_load(y);
  const auto load_at = [&](double t) -> Eigen::VectorXd { return (load_amplitude * std::polar(1.0, w * t)).real(); };
  NewmarkStepper stepper(model, dt, u0, Eigen::VectorXd::Zero(model.size()), load_at(0.0), model.damping(dashpots));
  const int periods = static_cast<int>(std::ceil(options.duration_s * f));
  Eigen::VectorXcd accumulated(model.size());
  int quiet_periods = 0;
  for (int period = 0; period < periods; ++period) {
    accumulated.setZero();
    for (int s = 0; s < steps; ++s) {
      const double t = stepper.time() + dt;
      stepper.step(load_at(t));
      accumulated += stepper.displacement().cast<std::complex<double>>() * std::polar(2.0 / steps, -w * t);
    }
    y = accumulated;  // y(t) = Re(y^ e^{jwt}) over the last period
    load_amplitude = damping_load(y);
    out.envelope_m.push_back(local_antinode(model, y, 0.5 * length, k));
    // Settled for 20 periods in a row: a start's transient (the drive mode reshaped
    // by the dashpots) can look settled for a moment.
    quiet_periods = settled(out.envelope_m, options.settled_change) ? quiet_periods + 1 : 0;
    if (quiet_periods >= 20) {
      out.settled = true;
      break;
    }
  }
  out.time_s = stepper.time();
  for (const PointDashpot& d : dashpots) {  // c w^2 |y^(x)|^2 / 2 over the last period
    out.dashpot_power_w.push_back(0.5 * d.coefficient_n_s_m * w * w * std::norm(model.at(y, d.position_m).first));
  }
  out.antinode_amplitude_m = out.envelope_m.back();
  for (int i = 0; i <= elements; ++i) {
    const double x = i * model.element_length();
    out.x_m.push_back(x);
    out.amplitude_m.push_back(std::abs(model.at(y, x).first));
  }
  return out;
}

}  // namespace stockbridge::span
