#include "stockbridge/section/regularised_section.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "stockbridge/core/error.hpp"

namespace stockbridge::section {

void RegularisedOptions::validate() const {
  if (!(std::isfinite(exponent) && exponent > 1.0)) throw_invalid("exponent", exponent, "a finite value > 1");
  require_positive("absolute_tolerance", absolute_tolerance, "");
  require_positive("relative_tolerance", relative_tolerance, "");
}

namespace {

MasingParameters validated(MasingParameters parameters, const RegularisedOptions& options) {
  validate(parameters);
  options.validate();
  return parameters;
}

/// The factor in brackets of (3.15): 1 while unloading, 1 - |H/h|^n while loading.
double rate_factor(double h_value, double slip, double direction, double exponent) {
  if (direction * h_value <= 0.0) return 1.0;
  return 1.0 - std::pow(std::abs(h_value / slip), exponent);
}

}  // namespace

RegularisedSection::RegularisedSection(MasingParameters parameters, RegularisedOptions options)
    : CommittedSectionLaw(SectionState::virgin(validated(parameters, options))),
      parameters_(std::move(parameters)),
      options_(options) {}

void RegularisedSection::set_trial_curvature(double curvature) {
  require_finite("curvature", curvature, "1/m");
  namespace odeint = boost::numeric::odeint;
  using Vector = std::vector<double>;

  const SectionState& from = state_.committed();
  SectionState& to = state_.trial();
  const std::size_t m = parameters_.jenkin.size();
  const double increment = curvature - from.curvature;
  const double direction = increment > 0.0 ? 1.0 : (increment < 0.0 ? -1.0 : 0.0);

  // Unknowns over tau in [0, 1], kappa = kappa_from + tau * increment: H_1..H_m, W.
  Vector y(from.hysteretic);
  y.push_back(0.0);
  auto rhs = [&](const Vector& u, Vector& du, double /*tau*/) {
    double power = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      const Jenkin& e = parameters_.jenkin[j];
      const double factor = rate_factor(u[j], e.h, direction, options_.exponent);
      du[j] = e.c * increment * factor;
      power += u[j] * increment * (1.0 - factor);
    }
    du[m] = power;
  };
  if (m > 0 && increment != 0.0) {
    auto stepper = odeint::make_controlled<odeint::runge_kutta_dopri5<Vector>>(
        options_.absolute_tolerance, options_.relative_tolerance);
    odeint::integrate_adaptive(stepper, rhs, y, 0.0, 1.0, 0.1);
  }
  to.curvature = curvature;
  to.moment = parameters_.ei * curvature;
  to.tangent = parameters_.ei;
  for (std::size_t j = 0; j < m; ++j) {
    const Jenkin& e = parameters_.jenkin[j];
    to.hysteretic[j] = y[j];
    to.moment += y[j];
    to.tangent += e.c * rate_factor(y[j], e.h, direction, options_.exponent);
  }
  to.dissipated = from.dissipated + y[m];
}

}  // namespace stockbridge::section
