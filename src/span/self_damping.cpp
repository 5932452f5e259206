#include "stockbridge/span/self_damping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

struct SelfDampingEntry {
  SelfDampingLaw law;
  std::string_view name;
  std::optional<PublishedExponents> exponents;
};

constexpr PublishedExponent sd_value(double v) { return {v, v}; }
constexpr PublishedExponent sd_range(double lo, double hi) { return {lo, hi}; }

// Exponents (l, m, n) as MODEL.md section 9 lists them; sources in docs/span.md.
const std::array<SelfDampingEntry, 9> self_damping_entries{{
    {SelfDampingLaw::noiseux_1991, "noiseux-1991", PublishedExponents{sd_value(2.44), sd_value(5.63), sd_value(2.76)}},
    {SelfDampingLaw::kraus_hagedorn_1991, "kraus-hagedorn-1991",
     PublishedExponents{sd_value(2.47), sd_value(5.38), sd_value(2.80)}},
    {SelfDampingLaw::seppa_1971, "seppa-1971", PublishedExponents{sd_value(2.5), sd_value(5.75), sd_value(2.8)}},
    {SelfDampingLaw::moecks_schmidt_1989, "moecks-schmidt-1989",
     PublishedExponents{sd_value(2.45), sd_value(5.38), sd_value(2.4)}},
    {SelfDampingLaw::claren_diana_1969, "claren-diana-1969",
     PublishedExponents{sd_value(2.0), sd_value(4.0), sd_range(1.5, 3.0)}},
    {SelfDampingLaw::tompkins_1956, "tompkins-1956",
     PublishedExponents{sd_range(2.3, 2.6), sd_range(5.0, 6.0), sd_value(1.9)}},
    {SelfDampingLaw::polimi_2000, "polimi-2000", PublishedExponents{sd_value(2.43), sd_value(5.5), sd_value(2.0)}},
    {SelfDampingLaw::power, "power", std::nullopt},
    {SelfDampingLaw::foti, "foti", std::nullopt},
}};

const SelfDampingEntry& sd_entry(SelfDampingLaw law) {
  return *std::find_if(self_damping_entries.begin(), self_damping_entries.end(),
                       [law](const SelfDampingEntry& e) { return e.law == law; });
}

/// Throws InvalidParameter naming `name` if `value` is given although the law does not use it.
void sd_reject(std::string_view name, const std::optional<double>& value, SelfDampingLaw law, std::string_view why) {
  if (value) {
    throw InvalidParameter(std::string(name), fmt::format(" = {}: not used by law = '{}' ({})", format_value(*value),
                                                          self_damping_law_name(law), why));
  }
}

/// Checks one exponent of a named law against what its source published.
void sd_check_exponent(std::string_view name, const std::optional<double>& value, const PublishedExponent& published,
                       SelfDampingLaw law) {
  if (!published.is_range()) {
    sd_reject(name, value, law, fmt::format("it fixes {} = {}; law = 'power' takes your own", name,
                                            format_value(published.lo)));
    return;
  }
  if (!value) {
    throw InvalidParameter(std::string(name),
                           fmt::format(": law = '{}' gives {} only as a range, {} to {}: give the value to use",
                                       self_damping_law_name(law), name, format_value(published.lo),
                                       format_value(published.hi)));
  }
  if (!(*value >= published.lo && *value <= published.hi)) {
    throw_invalid(name, *value, fmt::format("a value from {} to {} (the range of law = '{}')", format_value(published.lo),
                                            format_value(published.hi), self_damping_law_name(law)));
  }
}

/// The user's exponents of law = "power": l > 0, m > 0, n finite.
void sd_check_power_exponents(const SelfDampingModel& model) {
  for (const auto& [name, value] : {std::pair{"l", model.l}, std::pair{"m", model.m}, std::pair{"n", model.n}}) {
    if (!value) throw InvalidParameter(name, ": missing: law = 'power' needs l, m and n");
  }
  require_positive("l", *model.l, "");
  require_positive("m", *model.m, "");
  require_finite("n", *model.n, "");
}

}  // namespace

SelfDampingLaw parse_self_damping_law(std::string_view name) {
  for (const SelfDampingEntry& e : self_damping_entries) {
    if (e.name == name) return e.law;
  }
  std::string names;
  for (const SelfDampingEntry& e : self_damping_entries) names += fmt::format("{}{}", names.empty() ? "" : ", ", e.name);
  throw InvalidParameter("law", fmt::format(" = '{}': expected one of {}", printable(name), names));
}

std::string_view self_damping_law_name(SelfDampingLaw law) { return sd_entry(law).name; }

std::optional<PublishedExponents> published_exponents(SelfDampingLaw law) { return sd_entry(law).exponents; }

void SelfDampingModel::validate() const {
  if (law == SelfDampingLaw::foti) {
    sd_reject("k", k, law, "a power-law factor");
    for (const auto& [name, value] : {std::pair{"l", l}, std::pair{"m", m}, std::pair{"n", n}}) {
      sd_reject(name, value, law, "a power-law exponent");
    }
    if (!limit_curvature) throw InvalidParameter("limit_curvature", ": missing: law = 'foti' needs it (1/m)");
    require_plausible("limit_curvature", *limit_curvature, "1/m");
    return;
  }
  sd_reject("limit_curvature", limit_curvature, law, "only law = 'foti' uses it");
  if (k) require_plausible("k", *k, "");
  if (law == SelfDampingLaw::power) {
    sd_check_power_exponents(*this);
    return;
  }
  const PublishedExponents published = *published_exponents(law);
  sd_check_exponent("l", l, published.l, law);
  sd_check_exponent("m", m, published.m, law);
  sd_check_exponent("n", n, published.n, law);
}

void SelfDampingModel::validate_with(const Conductor& conductor) const {
  validate();
  if (law == SelfDampingLaw::foti && conductor.ei_max == 0.0) {
    throw InvalidParameter("conductor.ei_max", ": not given: self_damping law = 'foti' needs it (N m^2)");
  }
}

PowerLawExponents SelfDampingModel::exponents() const {
  if (law == SelfDampingLaw::power) return {*l, *m, *n};
  const PublishedExponents published = *published_exponents(law);
  return {l.value_or(published.l.lo), m.value_or(published.m.lo), n.value_or(published.n.lo)};
}

double SelfDampingModel::factor(const Conductor& conductor) const { return k.value_or(lilien_k(conductor)); }

double SelfDampingModel::power(double amplitude, double frequency, const Conductor& conductor, double tension,
                               double span_length) const {
  if (law == SelfDampingLaw::foti) {
    return span_length * foti_self_damping(conductor, tension, *limit_curvature, amplitude, frequency);
  }
  return span_length * power_law_self_damping(factor(conductor), exponents(), amplitude, frequency, tension);
}

double power_law_self_damping(double k, const PowerLawExponents& e, double amplitude, double frequency,
                              double tension) {
  return k * std::pow(amplitude, e.l) * std::pow(frequency, e.m) / std::pow(tension / 1000.0, e.n);
}

double foti_self_damping(const Conductor& conductor, double tension, double chi0, double amplitude,
                         double frequency) {
  constexpr double pi = std::numbers::pi;
  const double k = wavenumber(conductor, tension, frequency);
  const double chi_m = k * k * amplitude;  // curvature amplitude at the antinodes
  const double t = std::asin(std::min(1.0, chi0 / chi_m));  // phase where chi reaches chi0
  const double g1 = 1.0 / 3.0 - 0.375 * std::cos(t) + std::cos(3.0 * t) / 24.0;
  const double g2 = pi - 2.0 * t + std::sin(2.0 * t);
  const double micro = 2.0 / pi * g1 * chi_m * chi_m * chi_m / chi0;
  const double gross = g2 * chi_m * chi_m / (4.0 * pi);
  return frequency * conductor.ei_max * (micro + gross);
}

}  // namespace stockbridge::span
