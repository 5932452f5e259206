#include "stockbridge/requests/span_request.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_names.hpp"

namespace stockbridge::requests {

namespace {

// Names in this unnamed namespace are unique across the library (unity batches).

constexpr int kSpanMaxPoints = 100000;

/// One column member of the per-damper family: a damper at one of its places.
struct SpanDamperSlot {
  std::size_t damper = 0;
  double position = 0.0;  ///< m from end 1
  std::string suffix;     ///< "end1", "end2", or "at_150m" for one along the span
};

/// A place along the span in a column's name: "150m", "12.5m".
std::string span_place_name(double position) {
  std::string text = fmt::format("{:.4g}", position);
  std::replace(text.begin(), text.end(), '.', 'p');
  return text + "m";
}

/// The per-damper columns' members: each damper's end 1, then its end 2, or its places along the span.
std::vector<SpanDamperSlot> span_column_slots(const span::Span& span) {
  std::vector<SpanDamperSlot> slots;
  const auto& dampers = span.dampers();
  for (std::size_t k = 0; k < dampers.size(); ++k) {
    const span::SpanDamper& d = dampers[k];
    const std::vector<double> places = d.positions_from_end1(span.length());
    for (std::size_t i = 0; i < places.size(); ++i) {
      slots.push_back({k, places[i], d.in_span() ? "at_" + span_place_name(places[i]) : fmt::format("end{}", i + 1)});
    }
  }
  return slots;
}

/// The entry of a point's `dampers` at (damper, position); `dampers.size()` if none.
std::size_t span_damper_entry(const std::vector<span::DamperAtBalance>& dampers, std::size_t damper, double position,
                              double length) {
  for (std::size_t i = 0; i < dampers.size(); ++i) {
    if (dampers[i].damper == damper && std::abs(dampers[i].position - position) <= 1e-9 * length) return i;
  }
  return dampers.size();
}

void check_span_frequencies(const std::vector<double>& frequencies) {
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    const std::string name = fmt::format("frequencies[{}]", i);
    require_plausible(name, frequencies[i], "Hz");
    if (i > 0 && !(frequencies[i] > frequencies[i - 1])) {
      throw_invalid(name, frequencies[i],
                    fmt::format("more than the frequency before ({} Hz): strictly increasing", format_value(frequencies[i - 1])));
    }
  }
}

}  // namespace

CheckedSpanRequest check_span_request(const SpanRequest& request) {
  check_span_frequencies(request.frequencies);
  if (request.frequencies.empty()) require_in_range("points", request.points, 2, kSpanMaxPoints);
  require_in_range("threads", request.threads, 1, 1024);
  CheckedSpanRequest checked(request);
  if (request.damper_model) checked.damper_model_ = io::parse_damper_model(*request.damper_model);
  if (request.position_min.has_value() != request.position_max.has_value()) {
    throw InvalidParameter("optimize_position", ": expected both ends of the range, AMIN:AMAX (m)");
  }
  require_non_negative("spacing_min", request.spacing_min, "m");
  const span::PositionObjective objective = io::parse_position_objective(request.objective);
  if (request.position_min) {
    const double lo = *request.position_min, hi = *request.position_max;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0.0 && hi > lo)) {
      throw InvalidParameter("optimize_position", fmt::format(" = {}:{}: expected AMIN:AMAX with 0 < AMIN < AMAX (m from "
                                                              "the span end's clamp)",
                                                              format_value(lo), format_value(hi)));
    }
    if (request.no_dampers) {
      throw InvalidParameter("optimize_position", ": given with no_dampers: there is no damper to place");
    }
    span::PositionRules rules;
    rules.position_min = lo;
    rules.position_max = hi;
    rules.spacing_min = request.spacing_min;
    rules.objective = objective;
    checked.positions_ = rules;
  }
  return checked;
}

void check_against_span(const CheckedSpanRequest& checked, const span::Span& span) {
  if (!checked.positions()) return;
  if (span.dampers().empty()) throw InvalidParameter("optimize_position", ": the span file has no [[damper]] to place");
  if (checked.positions()->objective == span::PositionObjective::life && !span.fatigue().life) {
    throw InvalidParameter("objective", " = \"life\": the span gives no climate ([fatigue] wind_weibull and "
                                        "aeolian_fraction) to compute a life with");
  }
}

span::AnalysisOptions analysis_options(const span::BalanceOptions& file, const CheckedSpanRequest& checked) {
  span::AnalysisOptions options;
  options.balance = file;
  if (checked.damper_model()) options.balance.damper_model = *checked.damper_model();
  options.balance.table.threads = checked.request().threads;
  options.positions = checked.positions();
  options.validate();
  return options;
}

namespace {

/// The span file's span without what the request leaves out.
span::Span span_as_asked(const span::Span& file_span, const SpanRequest& request) {
  span::Span span = request.no_dampers ? file_span.without_dampers() : file_span;
  if (!request.no_attachments) return span;
  std::vector<span::SpanDamper> at_ends;
  for (const span::SpanDamper& d : span.dampers()) {
    if (!d.in_span()) at_ends.push_back(d);
  }
  return span.with_dampers(std::move(at_ends)).with_masses({});
}

}  // namespace

SpanResult run_span(const span::Span& file_span, const span::BalanceOptions& file, const CheckedSpanRequest& checked,
                    const damper::SweepProgress& progress,
                    std::function<void(const span::Span&, span::BalancePoint&&)> take_point) {
  check_against_span(checked, file_span);
  const SpanRequest& request = checked.request();
  span::AnalysisOptions options = analysis_options(file, checked);
  options.take_point = std::move(take_point);
  const span::Span span = span_as_asked(file_span, request);
  std::vector<double> frequencies =
      request.frequencies.empty() ? span::band_frequencies(span, request.points) : request.frequencies;
  return SpanResult{span::analyse_span(span, std::move(frequencies), options, progress), options.balance.damper_model};
}

std::vector<std::string> span_damper_prefixes(const span::Span& span) {
  std::vector<std::string> names;
  for (const span::SpanDamper& d : span.dampers()) names.push_back(d.name);
  return column_prefixes(names, "damper");
}

namespace {

using SpanQuantity = Quantity<span::BalancePoint>;

/// What the span table's quantities read beside the point: the span's.
struct SpanTableContext {
  double diameter = 0.0;
  double endurance_limit = 0.0;
  span::Conductor conductor;
  bool dampers = false;
  double length = 0.0;
  /// Per member of the per-damper family (each damper's end 1, then its end 2, or its
  /// places along the span): the damper and its position from end 1.
  std::vector<SpanDamperSlot> damper_slots;
  /// Per member of the per-mass family: the mass and its position from end 1.
  std::vector<std::pair<std::size_t, double>> mass_slots;
};

/// A number always given (the point's frequency and what follows from it).
SpanQuantity span_given(std::string name, std::string unit, std::string meaning,
                        std::function<double(const span::BalancePoint&)> value) {
  return {std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
          [value = std::move(value)](const span::BalancePoint& p, std::size_t) { return value(p); }, {}};
}

/// A number computed by the balance: NaN where the point did not converge.
SpanQuantity span_solved(std::string name, std::string unit, std::string meaning,
                         std::function<double(const span::BalancePoint&)> value) {
  return masked_quantity<span::BalancePoint>(
      std::move(name), std::move(unit), std::move(meaning), [](const span::BalancePoint& p) { return p.converged(); },
      [value = std::move(value)](const span::BalancePoint& p, std::size_t) { return value(p); });
}

/// A number of each damper and end: NaN where the point did not converge.
SpanQuantity span_per_damper(std::string name, std::string unit, std::string meaning,
                             std::shared_ptr<const SpanTableContext> context,
                             std::function<double(const span::DamperAtBalance&)> value) {
  return masked_quantity<span::BalancePoint>(
      std::move(name), std::move(unit), std::move(meaning),
      [context](const span::BalancePoint& p) { return p.converged(); },
      [context, value = std::move(value)](const span::BalancePoint& p, std::size_t member) {
        const SpanDamperSlot& slot = context->damper_slots[member];
        const std::size_t i = span_damper_entry(p.dampers, slot.damper, slot.position, context->length);
        return i < p.dampers.size() ? value(p.dampers[i]) : kNoValue;
      });
}

/// A number of each mass and position: NaN where the point did not converge.
SpanQuantity span_per_mass(std::string name, std::string unit, std::string meaning,
                           std::shared_ptr<const SpanTableContext> context,
                           std::function<double(const span::MassAtBalance&)> value) {
  return masked_quantity<span::BalancePoint>(
      std::move(name), std::move(unit), std::move(meaning),
      [context](const span::BalancePoint& p) { return p.converged(); },
      [context, value = std::move(value)](const span::BalancePoint& p, std::size_t member) {
        const auto [mass, position] = context->mass_slots[member];
        for (const span::MassAtBalance& m : p.masses) {
          if (m.mass == mass && std::abs(m.position - position) <= 1e-9 * context->length) return value(m);
        }
        return kNoValue;
      });
}

std::shared_ptr<const SpanTableContext> span_table_context(const span::Span& span) {
  auto context = std::make_shared<SpanTableContext>();
  context->diameter = span.conductor().diameter;
  context->endurance_limit = span.endurance_limit();
  context->conductor = span.conductor();
  context->dampers = !span.dampers().empty();
  context->length = span.length();
  context->damper_slots = span_column_slots(span);
  for (std::size_t m = 0; m < span.masses().size(); ++m) {
    for (const double x : span.masses()[m].positions) context->mass_slots.emplace_back(m, x);
  }
  return context;
}

}  // namespace

Table<span::BalancePoint> span_table(const span::Span& span) {
  using P = span::BalancePoint;
  using D = span::DamperAtBalance;
  const std::shared_ptr<const SpanTableContext> c = span_table_context(span);
  std::vector<SpanQuantity> q{
      span_given("frequency_hz", "Hz", "f", [](const P& p) { return p.frequency_hz; }),
      span_given("wind_speed_m_s", "m/s", "the wind speed that sheds vortices at f, U = f D / St",
                 [](const P& p) { return p.wind_speed; }),
      span_given("wavelength_m", "m", "lambda = c / f", [](const P& p) { return p.wavelength; }),
      span_solved("amplitude_m", "m", "Y, the antinode amplitude of the standing wave in the free span",
                  [](const P& p) { return p.amplitude; }),
      span_solved("amplitude_over_diameter", "", "Y / D", [c](const P& p) { return p.amplitude / c->diameter; }),
      span_solved("wind_power_w", "W", "P_w(Y)", [](const P& p) { return p.wind_power; }),
      span_solved("self_damping_power_w", "W", "P_s(Y)", [](const P& p) { return p.self_damping_power; }),
      span_solved("damper_power_w", "W", "what the dampers of both ends take (0 without dampers)",
                  [](const P& p) { return p.damper_power; }),
      span_solved("clamp_loop_amplitude_m", "m", "S, the loop next to the span clamp of end 1 (Y without dampers)",
                  [](const P& p) { return p.clamp_loop_amplitude; }),
      span_solved("damper_clamp_velocity_m_s", "m/s",
                  "the clamp velocity amplitude of the damper nearest the span clamp at end 1 (empty without dampers)",
                  [c](const P& p) {
                    // The first entry: the dampers of end 1 by their positions.
                    return c->dampers && !p.dampers.empty() ? p.dampers.front().clamp_velocity : kNoValue;
                  }),
      span_solved("stress_fymax_mpa", "MPa", "fymax stress at the span clamp",
                  [](const P& p) { return megapascal_of(p.stress_fymax); }),
      span_solved("stress_ps_mpa", "MPa", "Poffenberger-Swart stress at the span clamp",
                  [](const P& p) { return megapascal_of(p.stress_poffenberger_swart); }),
      span_solved("damper_clamp_stress_mpa", "MPa", "the largest stress at a damper clamp (empty without dampers)",
                  [c](const P& p) { return c->dampers ? megapascal_of(p.damper_clamp_stress) : kNoValue; }),
      span_solved("undamped_amplitude_m", "m", "Y of the same span without dampers",
                  [](const P& p) { return p.undamped_amplitude; }),
      span_solved("undamped_stress_fymax_mpa", "MPa", "its fymax stress",
                  [](const P& p) { return megapascal_of(p.undamped_stress_fymax); }),
      {"converged", "", "1, or 0 where the balance did not converge", ColumnKind::flag,
       [](const P& p, std::size_t) { return p.converged() ? 1.0 : 0.0; }, {}},
      span_given("endurance_limit_mpa", "MPa",
                 "the endurance limit the verdict uses (the same in every row; the plot reads it)",
                 [c](const P&) { return megapascal_of(c->endurance_limit); }),
      span_solved("energy_identity_error", "",
                  "|P_d - sum Re Z w^2 |Y_j|^2 / 2| relative to the power the incoming waves bring to the ends, "
                  "sum Z0 w^2 |B|^2 / 2 (the identity checked at every point, to 1e-8; P_d is a difference of the "
                  "waves' powers, so this is the scale of its round-off)",
                  [](const P& p) { return p.identity_error; }),
      span_solved("undamped_stress_ps_mpa", "MPa", "the undamped span's Poffenberger-Swart stress (its life's)",
                  [](const P& p) { return megapascal_of(p.undamped_stress_poffenberger_swart); }),
      {"several_states", "",
       "1 where the dampers' clamp velocities passed a fold since the frequency before: several self-consistent "
       "states near here ([several dampers per end](#several-dampers-per-end))",
       ColumnKind::flag,
       [](const P& p, std::size_t) { return p.converged() ? (p.several_states ? 1.0 : 0.0) : kNoValue; }, {}},
      span_solved("bending_amplitude_pp_m", "m",
                  "Yb, the peak-to-peak displacement relative to the span clamp at x_b (fatigue.yb_distance, 89 mm): "
                  "what a vibration recorder measures",
                  [](const P& p) { return p.bending_amplitude; }),
      span_solved("bending_strain_pp_microstrain", "microstrain",
                  "the outer wires' peak-to-peak bending strain at the span clamp, 2 sigma_ps / E_a",
                  [c](const P& p) { return span::bending_strain_pp_microstrain(c->conductor, p.stress_poffenberger_swart); }),
      span_solved("undamped_bending_amplitude_pp_m", "m", "Yb of the span without dampers",
                  [](const P& p) { return p.undamped_bending_amplitude; }),
      span_solved("undamped_bending_strain_pp_microstrain", "microstrain", "its bending strain",
                  [c](const P& p) {
                    return span::bending_strain_pp_microstrain(c->conductor, p.undamped_stress_poffenberger_swart);
                  }),
      span_solved("stress_fymax_low_mpa", "MPa",
                  "with a damper known by its measured sheet: the band its interpolation leaves, the fymax stress times "
                  "(1 - the sheets' error estimate, the largest change leaving out every other curve makes; empty "
                  "without a sheet)",
                  [](const P& p) { return megapascal_of(p.stress_fymax_low); }),
      span_solved("stress_fymax_high_mpa", "MPa", "the stress times (1 + the estimate)",
                  [](const P& p) { return megapascal_of(p.stress_fymax_high); }),
      span_given("endurance_limit_pp_microstrain", "microstrain", "the endurance limit as a peak-to-peak strain",
                 [c](const P&) { return span::bending_strain_pp_microstrain(c->conductor, c->endurance_limit); }),
      span_per_damper("<damper>_end<k>_velocity_m_s", "m/s",
                      "per damper and end it is at (k = 1, 2): its clamp velocity amplitude v_j", c,
                      [](const D& d) { return d.clamp_velocity; }),
      span_per_damper("<damper>_end<k>_re_z_n_s_m", "N s/m", "the real part of its impedance Z(f, v_j)", c,
                      [](const D& d) { return d.impedance.real(); }),
      span_per_damper("<damper>_end<k>_im_z_n_s_m", "N s/m", "its imaginary part", c,
                      [](const D& d) { return d.impedance.imag(); }),
      span_per_damper("<damper>_end<k>_power_w", "W", "the power it takes, Re Z w^2 |Y_j|^2 / 2", c,
                      [](const D& d) { return d.power; }),
      span_per_damper("<damper>_end<k>_clamp_stress_mpa", "MPa", "the conductor's stress at its clamp", c,
                      [](const D& d) { return megapascal_of(d.clamp_stress); }),
      span_per_damper("<damper>_end<k>_bending_strain_pp_microstrain", "microstrain",
                      "the outer wires' peak-to-peak bending strain at its clamp", c,
                      [c](const D& d) { return span::bending_strain_pp_microstrain(c->conductor, d.clamp_stress); }),
  };
  std::vector<SpanQuantity> attachments{
      span_solved("stress_fymax_end2_mpa", "MPa", "fymax stress at the span clamp of end 2",
                  [](const P& p) { return megapascal_of(p.stress_fymax_end2); }),
      span_solved("stress_ps_end2_mpa", "MPa", "Poffenberger-Swart stress at the span clamp of end 2",
                  [](const P& p) { return megapascal_of(p.stress_poffenberger_swart_end2); }),
      span_solved("bending_amplitude_end2_pp_m", "m", "Yb at the span clamp of end 2",
                  [](const P& p) { return p.bending_amplitude_end2; }),
      span_solved("max_subspan_amplitude_m", "m",
                  "the largest antinode amplitude of the stretches between the span's attachments (masses, dampers "
                  "placed along the span; Y without them)",
                  [](const P& p) { return p.max_subspan_amplitude; }),
      span_solved("max_subspan_from_m", "m", "where that stretch starts, from end 1",
                  [](const P& p) { return p.max_subspan_from; }),
      span_solved("max_subspan_to_m", "m", "where it ends", [](const P& p) { return p.max_subspan_to; }),
      span_solved("governing_stress_mpa", "MPa",
                  "the largest stress the criterion judges over both span clamps and the masses' clamps",
                  [span_copy = std::make_shared<span::Span>(span)](const P& p) {
                    return megapascal_of(span::governing_place(*span_copy, p).stress);
                  }),
      span_per_mass("<mass>_amplitude_m", "m", "per mass and position: the conductor's amplitude |Y| there", c,
                    [](const span::MassAtBalance& m) { return m.displacement; }),
      span_per_mass("<mass>_clamp_stress_mpa", "MPa",
                    "the conductor's stress at its clamp, the point force w^2 M |Y| times its stress_factor", c,
                    [](const span::MassAtBalance& m) { return megapascal_of(m.clamp_stress); }),
  };
  q.insert(q.end(), std::make_move_iterator(attachments.begin()), std::make_move_iterator(attachments.end()));
  std::vector<std::string> members;
  const std::vector<std::string> prefixes = span_damper_prefixes(span);
  for (const SpanDamperSlot& slot : c->damper_slots) members.push_back(fmt::format("{}_{}", prefixes[slot.damper], slot.suffix));
  std::vector<std::string> mass_names;
  for (const span::SpanMass& m : span.masses()) mass_names.push_back(m.name);
  const std::vector<std::string> mass_prefixes = column_prefixes(mass_names, "mass");
  std::vector<std::string> mass_members;
  for (const auto& [m, x] : c->mass_slots) mass_members.push_back(fmt::format("{}_at_{}", mass_prefixes[m], span_place_name(x)));
  return Table<span::BalancePoint>(std::move(q), {{"<damper>_end<k>", members}, {"<mass>", mass_members}});
}

Table<span::BalancePoint> span_point_notes_table(const span::Span& span) {
  using P = span::BalancePoint;
  return Table<span::BalancePoint>({
      {"governing_place", "", "where the judged stress is largest: span clamp 1 or 2, or a mass's clamp (empty where not converged)",
       ColumnKind::label, {},
       [span_copy = std::make_shared<span::Span>(span)](const P& p, std::size_t) {
         return p.converged() ? span::governing_place(*span_copy, p).place : std::string();
       }},
      {"termination", "", "how the point's balance ended (converged, or why not)", ColumnKind::label, {},
       [](const P& p, std::size_t) { return std::string(termination_name(p.summary.termination)); }},
      {"messages", "", "why a point did not converge (empty where it did)", ColumnKind::label, {},
       [](const P& p, std::size_t) { return p.converged() ? std::string() : brief_report(p.summary); }},
      {"notes", "", "what the point's balance noted (a fold passed, a damper solved cold)", ColumnKind::label, {},
       [](const P& p, std::size_t) { return p.note; }},
  });
}

std::vector<SpanProfileRow> span_profile_rows(const span::SpanProfile& profile) {
  std::vector<SpanProfileRow> rows;
  for (std::size_t i = 0; i < profile.x.size(); ++i) {
    rows.push_back({profile.x[i], profile.displacement[i], profile.envelope[i], {}});
    for (const span::ProfileAttachment& a : profile.attachments) {
      if (a.position != profile.x[i]) continue;
      std::string& label = rows.back().attachment;
      label += fmt::format("{}{} ({})", label.empty() ? "" : "; ", a.name, a.mass ? "mass" : "damper");
    }
  }
  return rows;
}

Table<SpanProfileRow> span_profile_table() {
  using R = SpanProfileRow;
  const auto number = [](std::string name, std::string unit, std::string meaning, double R::*field) {
    return Quantity<R>{std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
                       [field](const R& r, std::size_t) { return r.*field; }, {}};
  };
  return Table<R>({
      // A label leads a CSV.
      {"attachment", "", "at an attachment's place: its name and kind (mass or damper); empty elsewhere",
       ColumnKind::label, {}, [](const R& r, std::size_t) { return r.attachment; }},
      number("x_m", "m", "the place along the span, from end 1", &R::x),
      number("displacement_m", "m", "|Y(x)|, the conductor's displacement amplitude there (zero-to-peak)",
             &R::displacement),
      number("envelope_m", "m", "|A| + |B|, the antinode amplitude of the stretch x lies in", &R::envelope),
  });
}

void SpanPointTally::add(const span::Span& span, const span::BalancePoint& p) {
  if (!p.converged()) {
    failed.emplace_back(p.frequency_hz, p.summary);
    return;
  }
  max_identity_error = std::isnan(max_identity_error) ? p.identity_error : std::max(max_identity_error, p.identity_error);
  if (p.several_states) several_states.emplace_back(p.frequency_hz, p.note);
  if (span::governs_instead(span, p, governing ? &*governing : nullptr)) governing = p;
}

SpanPointTally SpanPointTally::of(const SpanResult& result) {
  SpanPointTally tally;
  for (const span::BalancePoint& p : result.analysis.balance.points) tally.add(result.analysis.span, p);
  return tally;
}

span::SpanProfile governing_profile(const span::Span& span, const SpanPointTally& tally) {
  if (!tally.governing) {
    throw InvalidParameter("profile", ": no point of the balance converged: no governing frequency to show");
  }
  return span::span_profile(span, *tally.governing);
}

span::SpanProfile governing_profile(const SpanResult& result) {
  return governing_profile(result.analysis.span, SpanPointTally::of(result));
}

}  // namespace stockbridge::requests
