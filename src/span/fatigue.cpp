#include "stockbridge/span/fatigue.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {
constexpr double fatigue_pa_per_mpa = 1e6;
}  // namespace

double fymax_stress(const Conductor& c, double frequency, double loop_amplitude) {
  return std::numbers::pi * c.outer_wire_diameter * c.outer_wire_modulus * std::sqrt(c.mass_per_length / c.ei_min) *
         frequency * loop_amplitude;
}

double poffenberger_swart_factor(const Conductor& c, double tension, double x_b) {
  const double p = bending_decay(c, tension);
  const double px = p * x_b;
  const double shape = std::expm1(-px) + px;  // exp(-px) - 1 + px, accurate for a small px too
  return c.outer_wire_modulus * c.outer_wire_diameter * p * p / (4.0 * shape);
}

double bending_amplitude(const Conductor& c, double tension, double frequency, double loop_amplitude, double x_b) {
  const BeamWavenumbers w = beam_wavenumbers(c, tension, frequency);
  const double k = w.travelling;
  const double r = k / w.decaying;
  const double y = loop_amplitude * (std::sin(k * x_b) - r * std::cos(k * x_b) + r * std::exp(-w.decaying * x_b)) /
                   std::sqrt(1.0 + r * r);
  return 2.0 * y;
}

double poffenberger_swart_stress(const Conductor& c, double tension, double bending_amplitude, double x_b) {
  return poffenberger_swart_factor(c, tension, x_b) * bending_amplitude;
}

double point_force_stress(const Conductor& c, double tension, double force_amplitude) {
  return c.outer_wire_modulus * c.outer_wire_diameter * std::abs(force_amplitude) /
         (4.0 * bending_decay(c, tension) * c.ei_min);
}

double bending_strain_pp_microstrain(const Conductor& c, double stress) {
  return 2.0 * stress / c.outer_wire_modulus * 1e6;
}

double SafeBorderLine::endurance_limit(double cycles) const {
  const double mpa = cycles <= knee ? a_low * std::pow(cycles, b_low) : a_high * std::pow(cycles, b_high);
  return fatigue_pa_per_mpa * mpa;
}

double SafeBorderLine::cycles_to_failure(double stress) const {
  if (!(stress > 0.0)) return std::numeric_limits<double>::infinity();
  const double mpa = stress / fatigue_pa_per_mpa;
  if (mpa > a_low * std::pow(knee, b_low)) return std::pow(mpa / a_low, 1.0 / b_low);
  if (mpa < a_high * std::pow(knee, b_high)) return std::pow(mpa / a_high, 1.0 / b_high);
  return knee;  // inside the step at the knee
}

SafeBorderLine safe_border_line(int aluminium_layers) {
  require_in_range("aluminium_layers", aluminium_layers, 1, 1000);
  if (aluminium_layers == 1) return {730.0, -0.2, 2e7, 430.0, -0.17};
  return {450.0, -0.2, 1.56e7, 263.0, -0.17};
}

SnCurve::SnCurve(const SafeBorderLine& line, std::string name)
    : SnCurve({{line.a_low, line.b_low, line.knee, 1.0},
               {line.a_high, line.b_high, std::numeric_limits<double>::infinity(), 1.0}},
              std::move(name)) {}

SnCurve::SnCurve(std::vector<SnBranch> branches, std::string name, std::string source)
    : branches_(std::move(branches)), name_(std::move(name)), source_(std::move(source)) {
  if (branches_.empty()) throw InvalidParameter("branches", ": none given; expected at least one");
  double before = 0.0;
  for (std::size_t i = 0; i < branches_.size(); ++i) {
    const SnBranch& branch = branches_[i];
    const bool last = i + 1 == branches_.size();
    if (!(branch.a > 0.0 && std::isfinite(branch.a)) || !(branch.b < 0.0 && std::isfinite(branch.b)) ||
        !(branch.anchor > 0.0 && std::isfinite(branch.anchor))) {
      throw InvalidParameter(fmt::format("branches[{}]", i),
                             fmt::format(": a = {}, b = {}, anchor = {}: expected a > 0 (MPa), b < 0 (the stress falls "
                                         "with N) and anchor > 0 (cycles)",
                                         format_value(branch.a), format_value(branch.b), format_value(branch.anchor)));
    }
    if (last ? !std::isinf(branch.until) : !(branch.until > before && std::isfinite(branch.until))) {
      throw InvalidParameter(fmt::format("branches[{}].until", i),
                             fmt::format(" = {}: expected {}", format_value(branch.until),
                                         last ? "infinity (the last branch holds beyond every N)"
                                              : fmt::format("finite cycles above {}", format_value(before))));
    }
    before = branch.until;
  }
}

SnCurve SnCurve::from_table(const std::vector<double>& stress_mpa, const std::vector<double>& cycles, std::string name,
                            std::string source) {
  if (stress_mpa.size() < 2) {
    throw InvalidParameter("stress_mpa", fmt::format(": {} value(s): expected at least 2 points", stress_mpa.size()));
  }
  if (cycles.size() != stress_mpa.size()) {
    throw InvalidParameter("cycles", fmt::format(": {} value(s) for {} stresses: expected one per stress", cycles.size(),
                                                 stress_mpa.size()));
  }
  for (std::size_t i = 0; i < stress_mpa.size(); ++i) {
    if (!(stress_mpa[i] > 0.0 && std::isfinite(stress_mpa[i])) || (i > 0 && !(stress_mpa[i] < stress_mpa[i - 1]))) {
      throw_invalid(fmt::format("stress_mpa[{}]", i), stress_mpa[i],
                    "stresses > 0, strictly decreasing (zero-to-peak, MPa)");
    }
    if (!(cycles[i] > 0.0 && std::isfinite(cycles[i])) || (i > 0 && !(cycles[i] > cycles[i - 1]))) {
      throw_invalid(fmt::format("cycles[{}]", i), cycles[i], "cycles > 0, strictly increasing");
    }
  }
  std::vector<SnBranch> branches;
  for (std::size_t i = 0; i + 1 < stress_mpa.size(); ++i) {
    const double b = std::log(stress_mpa[i + 1] / stress_mpa[i]) / std::log(cycles[i + 1] / cycles[i]);
    const bool last = i + 2 == stress_mpa.size();
    branches.push_back({stress_mpa[i], b, last ? std::numeric_limits<double>::infinity() : cycles[i + 1], cycles[i]});
  }
  return SnCurve(std::move(branches), std::move(name), std::move(source));
}

double SnCurve::endurance_limit(double cycles) const {
  for (const SnBranch& branch : branches_) {
    if (cycles <= branch.until) return fatigue_pa_per_mpa * branch.a * std::pow(cycles / branch.anchor, branch.b);
  }
  const SnBranch& last = branches_.back();
  return fatigue_pa_per_mpa * last.a * std::pow(cycles / last.anchor, last.b);
}

double SnCurve::cycles_to_failure(double stress) const {
  if (!(stress > 0.0)) return std::numeric_limits<double>::infinity();
  const double mpa = stress / fatigue_pa_per_mpa;
  double start = 0.0;
  for (const SnBranch& branch : branches_) {
    // The branch's stress at its end (0 for the last, b < 0): above it, N lies on the branch or,
    // inside a step down at the branch's start, at that start.
    const double end = std::isinf(branch.until) ? 0.0 : branch.a * std::pow(branch.until / branch.anchor, branch.b);
    if (mpa > end) return std::max(branch.anchor * std::pow(mpa / branch.a, 1.0 / branch.b), start);
    start = branch.until;
  }
  return std::numeric_limits<double>::infinity();
}

std::string SnCurve::description() const {
  return source_.empty() ? name_ : fmt::format("'{}' ({})", name_, source_);
}

SnCurve safe_border_curve(int aluminium_layers) {
  return SnCurve(safe_border_line(aluminium_layers),
                 aluminium_layers == 1 ? "the CIGRE Safe Border Line (one aluminium layer)"
                                       : "the CIGRE Safe Border Line (several aluminium layers)");
}

}  // namespace stockbridge::span
