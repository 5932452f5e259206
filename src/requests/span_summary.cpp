#include "stockbridge/requests/span_request.hpp"

#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "stockbridge/io/span_names.hpp"
#include "stockbridge/requests/conductor_request.hpp"
#include "stockbridge/span/tension_figures.hpp"

// The span's JSON summary (span_summary): the verdict and its figures, what a
// recorder measures, the life, and what the span was computed with.
namespace stockbridge::requests {

namespace {

// Names in this unnamed namespace are unique across the library (unity batches).

/// Every damper's position, in the span's order (m).
std::vector<double> span_positions(const span::Span& span) {
  std::vector<double> positions;
  for (const span::SpanDamper& d : span.dampers()) positions.push_back(d.position);
  return positions;
}

/// The tension in its three forms, the span parameter, and TB 273's judgement where the terrain is given.
void add_tension_figures(io::JsonObject& json, const span::Span& span) {
  const span::TensionFigures t = span::tension_figures(span);
  json.add("tension_n", t.tension)
      .add("tension_percent_rts", 100.0 * t.fraction_of_rts)
      .add("catenary_parameter_m", t.catenary_parameter)
      .add("span_parameter_m3_kg", t.span_parameter);
  if (const std::optional<span::SafeDesignTension> safe = span::safe_design_tension(span)) {
    json.add("terrain", safe->terrain.category)
        .add("safe_design_catenary_parameter_m", safe->terrain.catenary_parameter_limit)
        .add("safe_design_tension", safe->within ? "within" : "above");
  } else {
    json.add_null("terrain").add_null("safe_design_catenary_parameter_m").add_null("safe_design_tension");
  }
}

/// What a vibration recorder measures (Yb) and the strain engineers quote, at their largest.
void add_field_figures(io::JsonObject& json, const span::SpanAnalysis& a) {
  const span::Conductor& c = a.span.conductor();
  const span::BalanceSummary& s = a.balance.summary;
  const bool damped = s.converged > 0;
  const bool undamped = s.undamped_points > 0;
  json.add("yb_distance_m", a.span.fatigue().yb_distance)
      .add("max_bending_amplitude_pp_m", damped ? s.max_bending_amplitude : kNoValue)
      .add("max_bending_strain_pp_microstrain",
           damped ? span::bending_strain_pp_microstrain(c, s.max_stress_poffenberger_swart) : kNoValue)
      .add("undamped_max_bending_amplitude_pp_m", undamped ? s.undamped_max_bending_amplitude : kNoValue)
      .add("undamped_max_bending_strain_pp_microstrain",
           undamped ? span::bending_strain_pp_microstrain(c, s.undamped_max_stress_poffenberger_swart) : kNoValue)
      .add("endurance_limit_pp_microstrain", span::bending_strain_pp_microstrain(c, s.endurance_limit));
}

/// What the span was computed with, as used (after the catalogue, the file and the
/// keys beside them): the conductor and where it comes from, the tension in its three
/// forms, the wind, the self-damping and the fatigue criterion.
io::JsonObject span_inputs(const span::Span& span) {
  const span::Conductor& c = span.conductor();
  io::JsonObject conductor;
  conductor.add("name", c.name).add("source", c.source).add("stranding", c.stranding);
  add_conductor_figures(conductor, c);
  const span::TensionFigures t = span::tension_figures(span);
  const span::WindModel& w = span.wind();
  io::JsonObject wind;
  wind.add("law", span::wind_law_name(w.law))
      .add("strouhal", w.strouhal)
      .add("speed_min_m_s", w.speed_min)
      .add("speed_max_m_s", w.speed_max);
  if (w.law == span::WindLaw::foti) {
    wind.add("turbulence_intensity", w.turbulence_intensity)
        .add("turbulence_source", w.turbulence_terrain
                                      ? fmt::format("terrain category {} (this program's assumed intensity)",
                                                    *w.turbulence_terrain)
                                      : std::string("given"));
  }
  const span::SelfDampingModel& sd = span.self_damping();
  io::JsonObject self_damping;
  self_damping.add("law", span::self_damping_law_name(sd.law));
  if (sd.law == span::SelfDampingLaw::foti) {
    self_damping.add("limit_curvature_per_m", sd.limit_curvature.value_or(kNoValue));
  } else {
    const span::PowerLawExponents e = sd.exponents();
    self_damping.add("k", sd.factor(c)).add("k_source", sd.k ? "given" : "Lilien's").add("l", e.l).add("m", e.m).add("n", e.n);
  }
  io::JsonObject fatigue;
  fatigue.add("criterion", span::fatigue_criterion_name(span.fatigue().criterion))
      .add("criterion_description", span.criterion_description())
      .add("endurance_limit_mpa", megapascal_of(span.endurance_limit()))
      .add("yb_distance_m", span.fatigue().yb_distance);
  std::vector<io::JsonObject> dampers;
  for (const span::SpanDamper& d : span.dampers()) {
    io::JsonObject damper;
    damper.add("name", d.name);
    if (d.in_span()) {
      damper.add("positions_from_end1_m", d.along).add("ends", "along");
    } else {
      damper.add("position_m", d.position).add("ends", d.both_ends ? "both" : "one");
    }
    damper.add("source", d.fit ? "fitted" : d.measured() ? "sheet" : "model");
    if (d.fit) {
      damper.add("fit", io::JsonObject()
                            .add("sheet", d.fit->sheet)
                            .add("start", d.fit->start)
                            .add("rms_relative_error", d.fit->rms_relative_error)
                            .add("points", d.fit->points)
                            .add("poor_fit", d.fit->poor_fit)
                            .add("lack_of_fit", d.fit->lack_of_fit)
                            .add("cached", d.fit->cached));
    }
    dampers.push_back(std::move(damper));
  }
  std::vector<io::JsonObject> masses;
  for (const span::SpanMass& m : span.masses()) {
    masses.push_back(io::JsonObject()
                         .add("name", m.name)
                         .add("mass_kg", m.mass)
                         .add("positions_from_end1_m", m.positions)
                         .add("stress_factor", m.stress_factor));
  }
  return io::JsonObject()
      .add("conductor", conductor)
      .add("dampers", dampers)
      .add("masses", masses)
      .add("length_m", span.length())
      .add("tension", io::JsonObject()
                          .add("tension_n", t.tension)
                          .add("fraction_of_rts", t.fraction_of_rts)
                          .add("catenary_parameter_m", t.catenary_parameter))
      .add("wind", wind)
      .add("self_damping", self_damping)
      .add("fatigue", fatigue);
}

}  // namespace

io::JsonObject span_summary(const SpanResult& result) { return span_summary(result, SpanPointTally::of(result)); }

io::JsonObject span_summary(const SpanResult& result, const SpanPointTally& tally) {
  const span::SpanAnalysis& a = result.analysis;
  const span::BalanceSummary& s = a.balance.summary;
  const bool dampers = !a.span.dampers().empty();
  io::JsonObject json;
  json.add("points", s.points)
      .add("converged", s.converged)
      .add("damper_model", span::damper_model_name(result.damper_model))
      .add("dampers", static_cast<int>(a.span.dampers().size()))
      .add("endurance_limit_mpa", megapascal_of(s.endurance_limit))
      .add("criterion", span::fatigue_criterion_name(a.span.fatigue().criterion))
      .add("verdict", span::verdict_name(s.verdict))
      .add("max_judged_stress_mpa", s.converged > 0 ? megapascal_of(s.max_judged_stress) : kNoValue)
      .add("max_judged_stress_high_mpa", s.converged > 0 ? megapascal_of(s.max_judged_stress_high) : kNoValue)
      .add("governing_place", s.max_judged_stress_place)
      .add("governing_frequency_hz", s.converged > 0 ? s.max_judged_stress_frequency_hz : kNoValue)
      .add("undamped_max_judged_stress_mpa", megapascal_of(s.undamped_max_judged_stress))
      .add("max_stress_fymax_mpa", s.converged > 0 ? megapascal_of(s.max_stress_fymax) : kNoValue)
      .add("max_stress_frequency_hz", s.converged > 0 ? s.max_stress_frequency_hz : kNoValue)
      .add("max_damper_clamp_stress_mpa",
           dampers && s.converged > 0 ? megapascal_of(s.max_damper_clamp_stress) : kNoValue)
      .add("undamped_max_stress_fymax_mpa", megapascal_of(s.undamped_max_stress_fymax))
      .add("undamped_max_stress_frequency_hz", s.undamped_max_stress_frequency_hz)
      .add("undamped_verdict", span::verdict_name(s.undamped_verdict))
      .add("position_m", dampers ? a.span.dampers().front().position : kNoValue)
      .add("positions_m", span_positions(a.span))
      .add("position_optimized", a.position.has_value());
  add_tension_figures(json, a.span);
  add_field_figures(json, a);
  if (a.span.fatigue().life) {
    const auto add_life = [&json](std::string_view prefix, const std::optional<span::LifeEstimate>& life, int missing) {
      json.add(fmt::format("{}life_years", prefix), life ? life->life_years : kNoValue)
          .add(fmt::format("{}damage_per_year", prefix), life ? life->damage_per_year : kNoValue)
          .add(fmt::format("{}life_missing_points", prefix), missing);
    };
    add_life("", s.life, s.life_missing_points);
    add_life("undamped_", s.undamped_life, s.undamped_life_missing_points);
  }
  std::vector<io::JsonObject> failed;
  for (const auto& [frequency, why] : tally.failed) {
    failed.push_back(io::JsonObject()
                         .add("frequency_hz", frequency)
                         .add("termination", termination_name(why.termination))
                         .add("reason", brief_report(why)));
  }
  std::vector<double> several;
  for (const auto& [frequency, note] : tally.several_states) several.push_back(frequency);
  json.add("impedance_nodes", s.impedance_nodes)
      .add("failed_impedance_nodes", s.failed_impedance_nodes)
      .add("direct_solves", s.direct_solves)
      .add("max_energy_identity_error", tally.max_identity_error)
      .add("several_states_hz", several)
      .add("failed", failed)
      .add("sheet_error_estimate", a.sheet_error_estimate)
      .add("warnings", a.warnings)
      .add("inputs", span_inputs(a.span));
  return json;
}

}  // namespace stockbridge::requests
