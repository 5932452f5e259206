#include "stockbridge/requests/solver_settings.hpp"

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::requests {

namespace {

/// Applies a setting where the method uses it; names the methods that do otherwise.
template <class T, class Apply>
void apply(const std::optional<T>& setting, std::string_view name, bool used, std::string_view used_by, Apply&& to) {
  if (!setting) return;
  if (!used) {
    throw InvalidParameter(std::string(name), fmt::format(" = {}: not used by this method (only by {})", *setting, used_by));
  }
  to(*setting);
}

}  // namespace

damper::SolverOptions solver_options(const SolverSettings& settings) {
  using damper::Method;
  damper::SolverOptions options;
  options.method = damper::parse_method(settings.method);
  const Method m = options.method;
  const bool hb = m == Method::harmonic_balance, collocation = m == Method::collocation;
  const bool time = m == Method::time_integration, shooting = m == Method::shooting;
  damper::HarmonicBalanceOptions& balance = collocation ? options.collocation : options.harmonic_balance;
  apply(settings.harmonics, "harmonics", hb || collocation, "hb and collocation", [&](int h) { balance.harmonics = h; });
  apply(settings.samples, "samples", hb, "hb", [&](int n) { balance.samples = n; });
  apply(settings.half_wave, "half_wave", hb, "hb", [&](bool on) { balance.half_wave = on; });
  apply(settings.steps, "steps", time || shooting, "time and shooting", [&](int n) {
    options.time_integration.steps_per_period = n;
    options.shooting.steps_per_period = n;
  });
  apply(settings.max_iterations, "max_iterations", hb || collocation || shooting, "hb, collocation and shooting",
        [&](int n) {
          balance.max_iterations = n;
          options.shooting.max_iterations = n;
        });
  apply(settings.max_periods, "max_periods", time, "time", [&](int n) { options.time_integration.max_periods = n; });
  if (settings.energy_tolerance) options.energy_tolerance = *settings.energy_tolerance;
  // The chosen method's options, named as the settings name them ("harmonics = 0: ...").
  if (hb || collocation) balance.validate();
  if (time) options.time_integration.validate();
  if (shooting) options.shooting.validate();
  require_positive("energy_tolerance", options.energy_tolerance, "");
  return options;
}

}  // namespace stockbridge::requests
