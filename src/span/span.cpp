#include "stockbridge/span/span.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/tension_figures.hpp"

namespace stockbridge::span {

std::string SheetFit::summary() const {
  return fmt::format("fitted to {} from {} (free: {}), RMS {:.3g} % of |Z| over {} points{}", sheet, start,
                     free.empty() ? std::string("the cable only") : fmt::format("{}", fmt::join(free, ", ")),
                     100.0 * rms_relative_error, points,
                     poor_fit || lack_of_fit ? ": it does not follow the sheet" : "");
}

namespace {

/// Positions along the span, m from end 1: each strictly inside it.
void check_along(const std::string& field, const std::vector<double>& positions, double length) {
  if (positions.empty()) throw InvalidParameter(field, ": empty: expected at least one position (m from end 1)");
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double x = positions[i];
    if (!(std::isfinite(x) && x > 0.0 && x < length)) {
      throw_invalid(fmt::format("{}[{}]", field, i), x,
                    fmt::format("a distance from end 1 > 0 and < the span's length, {} m", format_value(length)));
    }
  }
}

}  // namespace

FatigueCriterion parse_fatigue_criterion(std::string_view name) {
  if (name == "safe-border-line") return FatigueCriterion::safe_border_line;
  if (name == "microstrain") return FatigueCriterion::microstrain;
  if (name == "stress") return FatigueCriterion::stress;
  throw InvalidParameter("criterion", fmt::format(" = '{}': expected safe-border-line, microstrain or stress",
                                                  printable(name)));
}

std::string_view fatigue_criterion_name(FatigueCriterion criterion) {
  switch (criterion) {
    case FatigueCriterion::safe_border_line: return "safe-border-line";
    case FatigueCriterion::microstrain: return "microstrain";
    case FatigueCriterion::stress: return "stress";
  }
  return "safe-border-line";
}

void FatigueSpec::validate() const {
  const auto refuse_beside = [this](const std::optional<double>& value, std::string_view name) {
    if (value) {
      throw InvalidParameter(std::string(name), fmt::format(": given beside criterion = \"{}\", which does not use it",
                                                            fatigue_criterion_name(criterion)));
    }
  };
  switch (criterion) {
    case FatigueCriterion::safe_border_line:
      if (!cycles) throw InvalidParameter("cycles", ": missing: criterion \"safe-border-line\" takes the Safe Border Line at cycles");
      require_plausible("cycles", *cycles, "");
      refuse_beside(endurance_limit, "endurance_limit");
      refuse_beside(limit_pp_microstrain, "limit_pp_microstrain");
      break;
    case FatigueCriterion::microstrain:
      if (limit_pp_microstrain) require_plausible("limit_pp_microstrain", *limit_pp_microstrain, "microstrain");
      refuse_beside(cycles, "cycles");
      refuse_beside(endurance_limit, "endurance_limit");
      break;
    case FatigueCriterion::stress:
      if (!endurance_limit) {
        throw InvalidParameter("endurance_limit", ": missing: criterion \"stress\" takes endurance_limit_mpa (or endurance_limit in Pa)");
      }
      require_plausible("endurance_limit", *endurance_limit, "Pa");
      refuse_beside(cycles, "cycles");
      refuse_beside(limit_pp_microstrain, "limit_pp_microstrain");
      break;
  }
  if (life) life->validate();
  require_plausible("yb_distance", yb_distance, "m");
}

namespace {

// Names in this unnamed namespace are unique across the library (the sanitizer
// presets compile it in unity batches).

/// "steel", "aluminium-clad-steel": what a message says the outer wires are.
std::string outer_wires_named(const Conductor& conductor) {
  return fmt::format("the conductor's outer wires are {}", wire_material_name(conductor.outer_wire_material));
}

/// The CIGRE Safe Border Line is stated for outer wires of aluminium or aluminium alloy
/// only: for others the span must give its own limit (endurance_limit_mpa) or curve.
/// Throws InvalidParameter naming the key to give, within [fatigue].
void check_safe_border_line_applies(const Conductor& conductor, const FatigueSpec& fatigue) {
  if (conductor.safe_border_line_applies() || fatigue.curve) return;
  if (fatigue.criterion == FatigueCriterion::safe_border_line) {
    throw InvalidParameter(
        "endurance_limit_mpa",
        fmt::format(": missing: {}, and the CIGRE Safe Border Line (criterion \"safe-border-line\") is stated for "
                    "aluminium outer layers only: expected endurance_limit_mpa (the outer wires' endurance limit, MPa "
                    "zero-to-peak) in place of cycles, or curve = an S-N curve of these wires",
                    outer_wires_named(conductor)));
  }
  if (fatigue.life) {
    throw InvalidParameter(
        "curve", fmt::format(": missing: {}, and the life's N(sigma) is the CIGRE Safe Border Line's, stated for "
                             "aluminium outer layers only: expected curve = an S-N curve of these wires, or no "
                             "wind_weibull and aeolian_fraction",
                             outer_wires_named(conductor)));
  }
}

}  // namespace

Span::Span(Conductor conductor, double length, double tension, WindModel wind, SelfDampingModel self_damping,
           std::vector<SpanDamper> dampers, FatigueSpec fatigue, std::optional<int> terrain,
           std::vector<SpanMass> masses)
    : conductor_(std::move(conductor)),
      length_(length),
      tension_(tension),
      wind_(std::move(wind)),
      self_damping_(std::move(self_damping)),
      dampers_(std::move(dampers)),
      fatigue_(std::move(fatigue)),
      terrain_(terrain),
      masses_(std::move(masses)) {
  within_field("conductor", [&] { conductor_.validate(); });
  require_plausible("span.length", length_, "m");
  check_tension(conductor_, tension_, "span.tension");
  within_field("wind", [&] { wind_.validate(); });
  within_field("self_damping", [&] { self_damping_.validate(); });
  self_damping_.validate_with(conductor_);  // names conductor.ei_max itself
  for (std::size_t j = 0; j < dampers_.size(); ++j) {
    if (dampers_[j].damper.has_value() == dampers_[j].measured()) {
      throw InvalidParameter(fmt::format("damper[{}]", j), ": expected a damper model or a measured sheet, one of the two");
    }
    if (dampers_[j].in_span()) {
      check_along(fmt::format("damper[{}].positions", j), dampers_[j].along, length_);
      continue;
    }
    const double a = dampers_[j].position;
    if (a > 0.0 && !(a < 0.5 * length_) && typical::damper_position.contains(a)) {
      throw_invalid("span.length", length_,
                    fmt::format("more than twice damper[{}].position = {} m: the span is too short for its dampers{}",
                                j, format_value(a),
                                typical::span_length.slipped(length_) ? " (a length in km?)" : ""));
    }
    if (!(a > 0.0 && a < 0.5 * length_)) {
      throw_invalid(fmt::format("damper[{}].position", j), a,
                    fmt::format("a distance from the span end > 0 and < half the span, {} m{}", 0.5 * length_,
                                typical::damper_position.slipped(a) ? " (a position in mm?)" : ""));
    }
  }
  for (std::size_t m = 0; m < masses_.size(); ++m) {
    const SpanMass& mass = masses_[m];
    const std::string field = fmt::format("mass[{}]", m);
    require_non_negative(field + ".mass", mass.mass, "kg");
    if (!(std::isfinite(mass.stress_factor) && mass.stress_factor > 0.0)) {
      throw_invalid(field + ".stress_factor", mass.stress_factor, "a factor > 0 on the clamp's stress");
    }
    check_along(field + ".positions", mass.positions, length_);
  }
  within_field("fatigue", [&] {
    fatigue_.validate();
    check_safe_border_line_applies(conductor_, fatigue_);
  });
  if (terrain_) terrain_category(*terrain_, "span.terrain");
}

bool Span::has_attachments() const {
  return !masses_.empty() ||
         std::any_of(dampers_.begin(), dampers_.end(), [](const SpanDamper& d) { return d.in_span(); });
}

double Span::endurance_limit() const {
  switch (fatigue_.criterion) {
    case FatigueCriterion::safe_border_line:
      return sn_curve().endurance_limit(*fatigue_.cycles);
    case FatigueCriterion::microstrain:
      return 0.5e-6 * fatigue_.limit_pp_microstrain.value_or(ieee_limit_pp_microstrain) * conductor_.outer_wire_modulus;
    case FatigueCriterion::stress: return *fatigue_.endurance_limit;
  }
  return *fatigue_.endurance_limit;
}

SnCurve Span::sn_curve() const {
  if (fatigue_.curve) return *fatigue_.curve;
  if (!conductor_.safe_border_line_applies()) {
    throw InvalidParameter("fatigue.curve", fmt::format(": missing: {}, and the CIGRE Safe Border Line is stated for "
                                                        "aluminium outer layers only: expected an S-N curve of these wires",
                                                        outer_wires_named(conductor_)));
  }
  return safe_border_curve(conductor_.aluminium_layers);
}

std::string Span::criterion_description() const {
  switch (fatigue_.criterion) {
    case FatigueCriterion::safe_border_line:
      return fatigue_.curve ? fmt::format("the S-N curve {} at {:.3g} cycles", fatigue_.curve->description(), *fatigue_.cycles)
                            : fmt::format("the CIGRE Safe Border Line at {:.3g} cycles", *fatigue_.cycles);
    case FatigueCriterion::microstrain:
      return fatigue_.limit_pp_microstrain
                 ? fmt::format("{:.4g} microstrain peak-to-peak (given)", *fatigue_.limit_pp_microstrain)
                 : fmt::format("{:.4g} microstrain peak-to-peak (the IEEE committee's limit)", ieee_limit_pp_microstrain);
    case FatigueCriterion::stress: return "a given endurance limit";
  }
  return "";
}

Span Span::with_dampers_at(double position) const {
  std::vector<SpanDamper> moved = dampers_;
  const auto first = std::find_if(dampers_.begin(), dampers_.end(), [](const SpanDamper& d) { return !d.in_span(); });
  const double shift = first == dampers_.end() ? 0.0 : position - first->position;
  for (SpanDamper& d : moved) {
    if (!d.in_span()) d.position += shift;
  }
  return with_dampers(std::move(moved));
}

Span Span::with_dampers(std::vector<SpanDamper> dampers) const {
  return Span(conductor_, length_, tension_, wind_, self_damping_, std::move(dampers), fatigue_, terrain_, masses_);
}

Span Span::without_dampers() const { return with_dampers({}); }

Span Span::with_masses(std::vector<SpanMass> masses) const {
  return Span(conductor_, length_, tension_, wind_, self_damping_, dampers_, fatigue_, terrain_, std::move(masses));
}

}  // namespace stockbridge::span
