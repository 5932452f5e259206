#include "stockbridge/span/conductor_in_time.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <fmt/format.h>

#include "hermite_element.hpp"
#include "stockbridge/core/error.hpp"

// The span in time's beam: the Hermite element model, its Newmark stepper with the
// dampers coupled at their clamps, and the wake oscillators of the wind in time
// (docs/time-domain.md). The runs that settle a span on a wind are conductor_in_time.cpp.
namespace stockbridge::span {

using namespace hermite;

double BeamProperties::pinned_frequency(int n) const {
  const double kn = n * std::numbers::pi / length;
  return n / (2.0 * length) * std::sqrt(tension / mass_per_length) * std::sqrt(1.0 + kn * kn * ei / tension);
}

namespace {

/// The element of x and where in it (s in [0, 1]).
std::pair<int, double> element_at(const BeamModel& model, double x) {
  const std::vector<double>& nodes = model.nodes();
  const auto above = std::upper_bound(nodes.begin() + 1, nodes.end() - 1, x);
  const int e = static_cast<int>(above - nodes.begin()) - 1;
  return {e, std::clamp((x - nodes[e]) / model.element_length(e), 0.0, 1.0)};
}

std::vector<double> uniform_nodes(double length, int elements) {
  require_in_range("elements", elements, 2, 1000000);
  std::vector<double> nodes(elements + 1);
  for (int i = 0; i <= elements; ++i) nodes[i] = length * i / elements;
  return nodes;
}

}  // namespace

BeamModel::BeamModel(const BeamProperties& properties, int elements)
    : BeamModel(properties, uniform_nodes(properties.length, elements)) {}

BeamModel::BeamModel(const BeamProperties& properties, std::vector<double> nodes)
    : properties_(properties), nodes_(std::move(nodes)) {
  require_positive("length", properties.length, "m");
  require_positive("mass_per_length", properties.mass_per_length, "kg/m");
  require_positive("tension", properties.tension, "N");
  if (!(properties.ei >= 0.0) || !std::isfinite(properties.ei)) throw_invalid("ei", properties.ei, "a finite value >= 0 (N m^2)");
  require_in_range("nodes", static_cast<long long>(nodes_.size()), 3, 1000001);
  bool increasing = nodes_.front() == 0.0 && nodes_.back() == properties.length;
  for (std::size_t i = 1; i < nodes_.size(); ++i) increasing = increasing && nodes_[i] > nodes_[i - 1];
  if (!increasing) {
    throw InvalidParameter("nodes", fmt::format(": expected positions increasing from 0 to the length, {} m", properties.length));
  }
  const int elements = this->elements();
  dof_.assign(2 * nodes_.size(), -1);
  Eigen::Index next = 0;
  for (int i = 0; i <= elements; ++i) {
    const bool end = i == 0 || i == elements;
    if (!end) dof_[2 * i] = next++;
    if (!end || properties.ends == BeamEnds::pinned) dof_[2 * i + 1] = next++;
  }
  std::vector<Eigen::Triplet<double>> mass, stiffness;
  for (int e = 0; e < elements; ++e) {
    const double h = element_length(e);
    add_element(mass, element_dofs(*this, e), properties.mass_per_length * unit_mass(h));
    add_element(stiffness, element_dofs(*this, e), properties.ei * bending(h) + properties.tension * geometric(h));
  }
  mass_.resize(next, next);
  stiffness_.resize(next, next);
  mass_.setFromTriplets(mass.begin(), mass.end());
  stiffness_.setFromTriplets(stiffness.begin(), stiffness.end());
}

Eigen::SparseMatrix<double> BeamModel::damping(const std::vector<PointDashpot>& dashpots) const {
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t i = 0; i < dashpots.size(); ++i) {
    const PointDashpot& d = dashpots[i];
    if (!(d.position_m > 0.0 && d.position_m < properties_.length)) {
      throw_invalid(fmt::format("dashpots[{}].position", i), d.position_m,
                    fmt::format("a distance from end 1 > 0 and < the span's length, {} m", properties_.length));
    }
    require_positive(fmt::format("dashpots[{}].coefficient", i), d.coefficient_n_s_m, "N s/m");
    const auto [e, s] = element_at(*this, d.position_m);
    const Eigen::Vector4d n = shape(s, element_length(e));
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
  return {shape(s, element_length(e)).template cast<Scalar>().dot(q),
          shape_slope(s, element_length(e)).template cast<Scalar>().dot(q)};
}
template std::pair<double, double> BeamModel::at(const Eigen::VectorXd&, double) const;
template std::pair<std::complex<double>, std::complex<double>> BeamModel::at(const Eigen::VectorXcd&, double) const;

namespace {

/// N(x): the free vector whose dot product with u is the displacement at x.
Eigen::VectorXd point_vector(const BeamModel& model, double x) {
  const auto [e, s] = element_at(model, x);
  const Eigen::Vector4d n = shape(s, model.element_length(e));
  const std::array<Eigen::Index, 4> dofs = element_dofs(model, e);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(model.size());
  for (int i = 0; i < 4; ++i) {
    if (dofs[i] >= 0) out(dofs[i]) = n(i);
  }
  return out;
}

}  // namespace

NewmarkStepper::NewmarkStepper(const BeamModel& model, double dt, const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                               const Eigen::VectorXd& load0, Eigen::SparseMatrix<double> damping,
                               std::vector<BeamDamper> dampers)
    : model_(model), damping_(std::move(damping)), dt_(dt), u_(u0), v_(v0), dampers_(std::move(dampers)) {
  require_positive("dt", dt, "s");
  if (u0.size() != model.size() || v0.size() != model.size() || load0.size() != model.size()) {
    throw InvalidParameter("initial state", fmt::format(": expected {} values (the free degrees of freedom)", model.size()));
  }
  if (damping_.size() == 0) damping_.resize(model.size(), model.size());
  const Eigen::SparseMatrix<double> effective =
      model.mass() + (0.5 * dt) * damping_ + (0.25 * dt * dt) * model.stiffness();
  effective_.compute(effective);
  if (effective_.info() != Eigen::Success) throw NumericalError("Newmark: M + dt C / 2 + dt^2 K / 4 is not positive definite");
  const double length = model.properties().length;
  attachment_.resize(model.size(), static_cast<Eigen::Index>(dampers_.size()));
  for (std::size_t d = 0; d < dampers_.size(); ++d) {
    const double x = dampers_[d].position_m;
    if (!(x > 0.0 && x < length)) {
      throw_invalid(fmt::format("dampers[{}].position", d), x,
                    fmt::format("a distance from end 1 > 0 and < the span's length, {} m", length));
    }
    if (dampers_[d].damper.dt() != dt) {
      throw InvalidParameter(fmt::format("dampers[{}]", d),
                             fmt::format(" steps by {} s: expected the beam's step, {} s", dampers_[d].damper.dt(), dt));
    }
    attachment_.col(static_cast<Eigen::Index>(d)) = point_vector(model, x);
  }
  influence_ = effective_.solve(attachment_);
  coupling_ = attachment_.transpose() * influence_;
  start_dampers(load0);
}

void NewmarkStepper::set_damping(Eigen::SparseMatrix<double> damping) {
  damping_ = std::move(damping);
  effective_.factorize(model_.mass() + (0.5 * dt_) * damping_ + (0.25 * dt_ * dt_) * model_.stiffness());
  if (effective_.info() != Eigen::Success) throw NumericalError("Newmark: M + dt C / 2 + dt^2 K / 4 is not positive definite");
  if (attachment_.cols() > 0) {
    influence_ = effective_.solve(attachment_);
    coupling_ = attachment_.transpose() * influence_;
  }
}

// M a0 = F0 - K u0 - C v0 + N F with F_d = -m_c,d a_c,d (the dampers at rest, undeflected:
// their cables carry nothing yet), a_c = N^T a0: with S_m = M^-1 N and G_m = N^T S_m,
// (I + G_m diag(m_c)) a_c = N^T M^-1 (F0 - K u0 - C v0).
void NewmarkStepper::start_dampers(const Eigen::VectorXd& load0) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> mass(model_.mass());
  a_ = mass.solve(load0 - model_.stiffness() * u_ - damping_ * v_);
  const auto n = static_cast<Eigen::Index>(dampers_.size());
  forces_ = Eigen::VectorXd::Zero(n);
  damper_work_ = Eigen::VectorXd::Zero(n);
  if (n == 0) return;
  const Eigen::MatrixXd s = mass.solve(attachment_);
  Eigen::VectorXd clamp_mass(n);
  for (Eigen::Index d = 0; d < n; ++d) clamp_mass(d) = -dampers_[d].damper.start(0.0).force_per_acceleration_kg;
  const Eigen::MatrixXd system = Eigen::MatrixXd::Identity(n, n) + (attachment_.transpose() * s) * clamp_mass.asDiagonal();
  const Eigen::VectorXd clamp = system.partialPivLu().solve(attachment_.transpose() * a_);
  for (Eigen::Index d = 0; d < n; ++d) forces_(d) = dampers_[d].damper.start(clamp(d)).force_n;
  a_ += s * forces_;
}

// With beta = 1/4, gamma = 1/2: u+ = u + dt v + dt^2 (a + a+) / 4 and v+ = v + dt (a + a+) / 2,
// so (M + dt C / 2 + dt^2 K / 4) a+ = F+ - C (v + dt a / 2) - K (u + dt v + dt^2 a / 4) + N F+.
void NewmarkStepper::step(const Eigen::VectorXd& load_next) {
  predicted_u_ = u_ + dt_ * v_ + (0.25 * dt_ * dt_) * a_;
  predicted_v_ = v_ + (0.5 * dt_) * a_;
  rhs_ = load_next;
  rhs_.noalias() -= model_.stiffness() * predicted_u_;
  rhs_.noalias() -= damping_ * predicted_v_;
  const Eigen::VectorXd clamps_before = attachment_.transpose() * u_;  // a few values: one per damper
  const Eigen::VectorXd forces_before = forces_;
  uncoupled_ = effective_.solve(rhs_);
  const Eigen::VectorXd& a_next = coupled_acceleration(uncoupled_);
  velocity_sum_ = v_;
  u_ = predicted_u_ + (0.25 * dt_ * dt_) * a_next;
  v_ = predicted_v_ + (0.5 * dt_) * a_next;
  a_ = a_next;
  velocity_sum_ += v_;
  damped_.noalias() = damping_ * velocity_sum_;
  dissipated_ += 0.25 * dt_ * velocity_sum_.dot(damped_);
  if (!dampers_.empty()) {
    damper_work_ += 0.5 * (attachment_.transpose() * u_ - clamps_before).cwiseProduct(forces_before + forces_);
  }
  time_ += dt_;
}

// Newton on r(a_c) = a_c - N^T a0 - G F(a_c), its Jacobian I - G diag(dF/da_c) from the
// dampers' own tangents; then a+ = a0 + S F.
const Eigen::VectorXd& NewmarkStepper::coupled_acceleration(Eigen::VectorXd& uncoupled) {
  if (dampers_.empty()) return uncoupled;
  constexpr int kMaxIterations = 50;
  constexpr double kTolerance = 1e-11;
  const auto n = static_cast<Eigen::Index>(dampers_.size());
  const Eigen::VectorXd free_clamps = attachment_.transpose() * uncoupled;
  Eigen::VectorXd clamps = free_clamps + coupling_ * forces_;
  Eigen::VectorXd slopes(n);
  for (int iteration = 0;; ++iteration) {
    for (Eigen::Index d = 0; d < n; ++d) {
      const damper::ClampResponse response = dampers_[d].damper.trial(clamps(d));
      forces_(d) = response.force_n;
      slopes(d) = response.force_per_acceleration_kg;
    }
    const Eigen::VectorXd pulled = coupling_ * forces_;
    const Eigen::VectorXd residual = clamps - free_clamps - pulled;
    const double scale = std::max({clamps.lpNorm<Eigen::Infinity>(), free_clamps.lpNorm<Eigen::Infinity>(),
                                   pulled.lpNorm<Eigen::Infinity>(), 1e-300});
    Eigen::Index worst = 0;
    const double norm = residual.cwiseAbs().maxCoeff(&worst);
    if (norm <= kTolerance * scale) break;
    if (iteration == kMaxIterations || !std::isfinite(norm)) {
      throw NumericalError(fmt::format(
          "the span and its dampers in the time step to t = {:.9g} s: the clamps' accelerations did not converge in {} "
          "Newton iterations (residual {:.3g} relative, largest at damper {} at {} m)",
          time_ + dt_, iteration, norm / scale, worst + 1, dampers_[static_cast<std::size_t>(worst)].position_m));
    }
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Identity(n, n);
    jacobian -= coupling_ * slopes.asDiagonal();
    clamps -= jacobian.partialPivLu().solve(residual);
  }
  for (BeamDamper& d : dampers_) d.damper.commit();
  uncoupled.noalias() += influence_ * forces_;
  return uncoupled;
}

double NewmarkStepper::energy() const {
  return 0.5 * (v_.dot(model_.mass() * v_) + u_.dot(model_.stiffness() * u_));
}

namespace {
/// Newton's iterations of a wake step: from the step with the start's damping, one
/// already holds the van der Pol limit cycle's amplitude to 1e-3 and period to 2e-4
/// at 160 steps a period; the second takes the residual to round-off.
constexpr int kWakeNewtonIterations = 2;
}  // namespace

WakeOscillators::WakeOscillators(Eigen::Index count, const WakeParameters& parameters, double shedding_w,
                                 double diameter, double dt, double q0)
    : parameters_(parameters), w_(shedding_w), diameter_(diameter), dt_(dt), q_(Eigen::VectorXd::Constant(count, q0)),
      p_(Eigen::VectorXd::Zero(count)), qa_(Eigen::VectorXd::Constant(count, -shedding_w * shedding_w * q0)) {
  parameters_.validate();
  require_positive("shedding_w", shedding_w, "rad/s");
  require_positive("diameter", diameter, "m");
  require_positive("dt", dt, "s");
}

void WakeOscillators::step(const Eigen::VectorXd& acceleration) {
  // Newmark's rule on q_tt + epsilon w (q^2 - 1) q_t + w^2 q = F, the van der Pol
  // term taken at the step's end as the rule takes every force: per oscillator a
  // scalar equation in the end's q_tt, solved by Newton's method from the step with
  // the start's damping (a few iterations: it is nearly linear over a step).
  const double h = dt_, w2 = w_ * w_, beta = 0.25 * h * h, gamma = 0.5 * h, e = parameters_.epsilon * w_;
  const double coupling = parameters_.coupling / diameter_;
  for (Eigen::Index i = 0; i < q_.size(); ++i) {
    const double force = coupling * acceleration(i);
    const double q_predicted = q_(i) + h * p_(i) + beta * qa_(i), p_predicted = p_(i) + gamma * qa_(i);
    const double c0 = e * (q_(i) * q_(i) - 1.0);
    double qa = (force - c0 * p_predicted - w2 * q_predicted) / (1.0 + gamma * c0 + beta * w2);
    for (int iteration = 0; iteration < kWakeNewtonIterations; ++iteration) {
      const double q = q_predicted + beta * qa, p = p_predicted + gamma * qa;
      const double residual = qa + e * (q * q - 1.0) * p + w2 * q - force;
      const double slope = 1.0 + e * (2.0 * beta * q * p + gamma * (q * q - 1.0)) + w2 * beta;
      qa -= residual / slope;
    }
    q_(i) = q_predicted + beta * qa;
    p_(i) = p_predicted + gamma * qa;
    qa_(i) = qa;
  }
}

}  // namespace stockbridge::span
