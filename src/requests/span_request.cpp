#include "stockbridge/requests/span_request.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::requests {

namespace {

// Names in this unnamed namespace are unique across the library (unity batches).

constexpr double kSpanNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr double kPascalPerMegapascal = 1e6;
constexpr int kSpanMaxPoints = 100000;

/// The columns every balance point has, whatever the dampers.
const std::vector<std::string>& span_point_columns() {
  static const std::vector<std::string> columns{
      "frequency_hz",          "wind_speed_m_s",          "wavelength_m",
      "amplitude_m",           "amplitude_over_diameter", "wind_power_w",
      "self_damping_power_w",  "damper_power_w",          "clamp_loop_amplitude_m",
      "damper_clamp_velocity_m_s", "stress_fymax_mpa",    "stress_ps_mpa",
      "damper_clamp_stress_mpa", "undamped_amplitude_m",  "undamped_stress_fymax_mpa",
      "converged",             "endurance_limit_mpa",     "energy_identity_error",
      "undamped_stress_ps_mpa", "several_states"};
  return columns;
}

/// The (damper index, end) of each entry of a point's `dampers`: end 1's, then end
/// 2's (the dampers at both ends), each end's in the order of their positions from
/// the clamp (the travelling-wave order; equal positions in the span's order).
std::vector<std::pair<std::size_t, int>> span_damper_slots(const span::Span& span) {
  const auto& dampers = span.dampers();
  std::vector<std::size_t> order(dampers.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return dampers[a].position < dampers[b].position; });
  std::vector<std::pair<std::size_t, int>> slots;
  for (const std::size_t k : order) slots.emplace_back(k, 1);
  for (const std::size_t k : order) {
    if (dampers[k].both_ends) slots.emplace_back(k, 2);
  }
  return slots;
}

/// The slot order of the per-damper columns: each damper's end 1, then its end 2.
std::vector<std::pair<std::size_t, int>> span_column_slots(const span::Span& span) {
  std::vector<std::pair<std::size_t, int>> slots;
  const auto& dampers = span.dampers();
  for (std::size_t k = 0; k < dampers.size(); ++k) {
    slots.emplace_back(k, 1);
    if (dampers[k].both_ends) slots.emplace_back(k, 2);
  }
  return slots;
}

constexpr const char* kSpanDamperFields[] = {"velocity_m_s", "re_z_n_s_m", "im_z_n_s_m", "power_w", "clamp_stress_mpa"};

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

void validate(const SpanRequest& request) {
  check_span_frequencies(request.frequencies);
  if (request.frequencies.empty()) require_in_range("points", request.points, 2, kSpanMaxPoints);
  if (request.damper_model) span::parse_damper_model(*request.damper_model);
  require_in_range("threads", request.threads, 1, 1024);
  if (request.position_min.has_value() != request.position_max.has_value()) {
    throw InvalidParameter("optimize_position", ": expected both ends of the range, AMIN:AMAX (m)");
  }
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
  }
}

span::AnalysisOptions analysis_options(const span::BalanceOptions& file, const SpanRequest& request) {
  validate(request);
  span::AnalysisOptions options;
  options.balance = file;
  if (request.damper_model) options.balance.damper_model = span::parse_damper_model(*request.damper_model);
  options.balance.table.threads = request.threads;
  if (request.position_min) options.position_range = span::Interval{*request.position_min, *request.position_max};
  options.validate();
  return options;
}

SpanResult run_span(const span::Span& file_span, const span::BalanceOptions& file, const SpanRequest& request,
                    const damper::SweepProgress& progress) {
  const span::AnalysisOptions options = analysis_options(file, request);
  const span::Span span = request.no_dampers ? file_span.without_dampers() : file_span;
  if (request.position_min && span.dampers().empty()) {
    throw InvalidParameter("optimize_position", ": the span file has no [[damper]] to place");
  }
  std::vector<double> frequencies =
      request.frequencies.empty() ? span::band_frequencies(span, request.points) : request.frequencies;
  return SpanResult{span::analyse_span(span, std::move(frequencies), options, progress), options.balance.damper_model};
}

std::vector<std::string> span_damper_prefixes(const span::Span& span) {
  std::vector<std::string> names;
  bool usable = true;
  for (const span::SpanDamper& d : span.dampers()) {
    const bool word = !d.name.empty() && std::all_of(d.name.begin(), d.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    });
    usable = usable && word && std::find(names.begin(), names.end(), d.name) == names.end();
    names.push_back(d.name);
  }
  if (usable) return names;
  for (std::size_t k = 0; k < names.size(); ++k) names[k] = "damper" + std::to_string(k + 1);
  return names;
}

std::vector<std::string> span_columns(const span::Span& span) {
  std::vector<std::string> columns = span_point_columns();
  const std::vector<std::string> prefixes = span_damper_prefixes(span);
  for (const auto& [k, end] : span_column_slots(span)) {
    for (const char* field : kSpanDamperFields) columns.push_back(fmt::format("{}_end{}_{}", prefixes[k], end, field));
  }
  return columns;
}

std::vector<double> span_row(const span::Span& span, const span::BalancePoint& p) {
  const bool ok = p.converged();
  const auto masked = [ok](double value) { return ok ? value : kSpanNoValue; };
  const auto mpa = [&masked](double pascal) { return masked(pascal / kPascalPerMegapascal); };
  const bool dampers = !span.dampers().empty();
  // The damper nearest the span clamp at end 1: the first entry (dampers by their positions).
  const std::vector<std::pair<std::size_t, int>> slots = span_damper_slots(span);
  const double nearest_velocity = dampers && !p.dampers.empty() ? p.dampers.front().clamp_velocity : kSpanNoValue;
  const double diameter = span.conductor().diameter;
  std::vector<double> row{p.frequency_hz,
                          p.wind_speed,
                          p.wavelength,
                          masked(p.amplitude),
                          masked(p.amplitude / diameter),
                          masked(p.wind_power),
                          masked(p.self_damping_power),
                          masked(p.damper_power),
                          masked(p.clamp_loop_amplitude),
                          dampers ? masked(nearest_velocity) : kSpanNoValue,
                          mpa(p.stress_fymax),
                          mpa(p.stress_poffenberger_swart),
                          dampers ? mpa(p.damper_clamp_stress) : kSpanNoValue,
                          masked(p.undamped_amplitude),
                          mpa(p.undamped_stress_fymax),
                          ok ? 1.0 : 0.0,
                          span.endurance_limit() / kPascalPerMegapascal,
                          masked(p.identity_error),
                          mpa(p.undamped_stress_poffenberger_swart),
                          ok ? (p.several_states ? 1.0 : 0.0) : kSpanNoValue};
  // Per damper and end, in the columns' order; the point's entries by their slot.
  for (const auto& slot : span_column_slots(span)) {
    const auto at = std::find(slots.begin(), slots.end(), slot);
    const std::size_t i = static_cast<std::size_t>(at - slots.begin());
    if (!ok || i >= p.dampers.size()) {
      row.insert(row.end(), std::size(kSpanDamperFields), kSpanNoValue);
      continue;
    }
    const span::DamperAtBalance& d = p.dampers[i];
    row.insert(row.end(), {d.clamp_velocity, d.impedance.real(), d.impedance.imag(), d.power,
                           d.clamp_stress / kPascalPerMegapascal});
  }
  return row;
}

io::JsonObject span_summary(const SpanResult& result) {
  const span::SpanAnalysis& a = result.analysis;
  const span::BalanceSummary& s = a.balance.summary;
  const auto mpa = [](double pascal) { return pascal / kPascalPerMegapascal; };
  const bool dampers = !a.span.dampers().empty();
  io::JsonObject json;
  json.add("points", s.points)
      .add("converged", s.converged)
      .add("damper_model", span::damper_model_name(result.damper_model))
      .add("dampers", static_cast<int>(a.span.dampers().size()))
      .add("endurance_limit_mpa", mpa(s.endurance_limit))
      .add("verdict", span::verdict_name(s.verdict))
      .add("max_stress_fymax_mpa", s.converged > 0 ? mpa(s.max_stress_fymax) : kSpanNoValue)
      .add("max_stress_frequency_hz", s.converged > 0 ? s.max_stress_frequency_hz : kSpanNoValue)
      .add("max_damper_clamp_stress_mpa", dampers && s.converged > 0 ? mpa(s.max_damper_clamp_stress) : kSpanNoValue)
      .add("undamped_max_stress_fymax_mpa", mpa(s.undamped_max_stress_fymax))
      .add("undamped_max_stress_frequency_hz", s.undamped_max_stress_frequency_hz)
      .add("undamped_verdict", span::verdict_name(s.undamped_verdict))
      .add("position_m", dampers ? a.span.dampers().front().position : kSpanNoValue)
      .add("position_optimized", a.position.has_value());
  if (a.span.fatigue().life) {
    const auto add_life = [&json](std::string_view prefix, const std::optional<span::LifeEstimate>& life, int missing) {
      json.add(fmt::format("{}life_years", prefix), life ? life->life_years : kSpanNoValue)
          .add(fmt::format("{}damage_per_year", prefix), life ? life->damage_per_year : kSpanNoValue)
          .add(fmt::format("{}life_missing_points", prefix), missing);
    };
    add_life("", s.life, s.life_missing_points);
    add_life("undamped_", s.undamped_life, s.undamped_life_missing_points);
  }
  double identity = kSpanNoValue;
  std::vector<io::JsonObject> failed;
  std::vector<double> several;
  for (const span::BalancePoint& p : a.balance.points) {
    if (p.converged()) {
      identity = std::isnan(identity) ? p.identity_error : std::max(identity, p.identity_error);
      if (p.several_states) several.push_back(p.frequency_hz);
      continue;
    }
    failed.push_back(io::JsonObject()
                         .add("frequency_hz", p.frequency_hz)
                         .add("termination", termination_name(p.summary.termination))
                         .add("reason", brief_report(p.summary)));
  }
  json.add("impedance_nodes", s.impedance_nodes)
      .add("failed_impedance_nodes", s.failed_impedance_nodes)
      .add("direct_solves", s.direct_solves)
      .add("max_energy_identity_error", identity)
      .add("several_states_hz", several)
      .add("failed", failed);
  return json;
}

}  // namespace stockbridge::requests
