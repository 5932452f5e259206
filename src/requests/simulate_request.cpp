#include "stockbridge/requests/simulate_request.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::requests {

namespace {

/// "y_at_89mm": the probe's column, its position in whole millimetres.
std::string probe_column(double x) { return fmt::format("y_at_{}mm", static_cast<long long>(std::llround(x * 1000.0))); }

/// Each position of each damper, m from end 1, in the span file's order (a damper at
/// both ends: end 1's first): the order the simulation steps them in.
std::vector<double> damper_positions(const span::Span& span) {
  std::vector<double> x;
  for (const span::SpanDamper& d : span.dampers()) {
    const std::vector<double> each = d.positions_from_end1(span.length());
    x.insert(x.end(), each.begin(), each.end());
  }
  return x;
}

/// The span clamp's Y_b point, each damper's position (from end 1), mid-span.
std::vector<double> default_probes(const span::Span& span) {
  std::vector<double> x = damper_positions(span);
  x.push_back(span.fatigue().yb_distance);
  x.push_back(0.5 * span.length());
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end(), [](double a, double b) { return probe_column(a) == probe_column(b); }), x.end());
  return x;
}

/// The balance's point (the span command's) at one frequency.
span::BalancePoint balance_at(const span::Span& span, const span::BalanceOptions& balance, double frequency_hz) {
  span::AnalysisOptions options;
  options.balance = balance;
  return span::analyse_span(span, {frequency_hz}, options).balance.points.at(0);
}

double ratio(double a, double b) { return std::isfinite(a) && std::isfinite(b) && b != 0.0 ? a / b : kNoValue; }

}  // namespace

void validate(const SimulateRequest& request) {
  require_positive("frequency", request.frequency_hz, "Hz");
  if (request.duration_s) require_positive("duration", *request.duration_s, "s");
  if (request.ends) span::parse_beam_ends(*request.ends);
  if (request.elements_per_wavelength) {
    require_in_range("elements_per_wavelength", *request.elements_per_wavelength, 4, 1000);
  }
  if (request.steps_per_period) require_in_range("steps_per_period", *request.steps_per_period, 8, 100000);
  span::parse_wind_in_time(request.wind);
  for (std::size_t i = 0; i < request.probes.size(); ++i) {
    if (!(request.probes[i] >= 0.0) || !std::isfinite(request.probes[i])) {
      throw_invalid(fmt::format("probes[{}]", i), request.probes[i], "a distance from end 1, m, >= 0");
    }
  }
  if (request.start_amplitude_m) require_positive("start_amplitude", *request.start_amplitude_m, "m");
  require_in_range("every", request.every, 1, 1000000);
}

span::TimeSettings time_settings(const SimulateRequest& request, const span::TimeSettings& file) {
  span::TimeSettings settings = file;
  if (request.ends) settings.ends = span::parse_beam_ends(*request.ends);
  settings.elements_per_wavelength = request.elements_per_wavelength.value_or(settings.elements_per_wavelength);
  settings.steps_per_period = request.steps_per_period.value_or(settings.steps_per_period);
  settings.duration_s = request.duration_s.value_or(settings.duration_s);
  return settings;
}

std::vector<double> simulation_probes(const span::Span& span, const SimulateRequest& request) {
  const std::vector<double> probes = request.probes.empty() ? default_probes(span) : request.probes;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    if (probes[i] > span.length()) {
      throw_invalid(fmt::format("probes[{}]", i), probes[i], fmt::format("at most the span's length, {} m", span.length()));
    }
    if (!seen.insert(probe_column(probes[i])).second) {
      throw_invalid(fmt::format("probes[{}]", i), probes[i], "a position not within 0.5 mm of another probe's");
    }
  }
  return probes;
}

std::size_t simulation_dampers(const span::Span& span) { return damper_positions(span).size(); }

std::vector<std::string> probe_columns(const std::vector<double>& probes) {
  std::vector<std::string> out;
  for (const double x : probes) out.push_back(probe_column(x));
  return out;
}

bool SimulateResult::balance_converged() const {
  return balance.converged();
}

const span::DamperAtBalance* SimulateResult::balance_damper(double position_m) const {
  if (!balance_converged()) return nullptr;
  for (const span::DamperAtBalance& b : balance.dampers) {
    if (std::abs(b.position - position_m) < 1e-9) return &b;
  }
  return nullptr;
}

SimulateResult run_simulate(const io::SpanFile& file, const SimulateRequest& request,
                            const std::function<void(const SimulationRow&)>& row,
                            const std::function<void(double, double)>& progress, const std::atomic<bool>* stop) {
  validate(request);
  const span::Span& span = file.span;
  const span::BalanceOptions& balance = file.balance;
  span::check_in_time(span);
  SimulateResult result;
  result.asked_frequency_hz = request.frequency_hz;
  result.settings = time_settings(request, file.time);
  result.wind = span::parse_wind_in_time(request.wind);
  result.probes = simulation_probes(span, request);
  result.probe_columns = probe_columns(result.probes);
  if (request.start_amplitude_m) {
    result.start_amplitude_m = *request.start_amplitude_m;
  } else {
    const span::BalancePoint p = balance_at(span, balance, request.frequency_hz);
    if (!p.converged()) {
      throw NumericalError(fmt::format("the balance at {} Hz, which gives the simulation its start, did not converge ({}): "
                                       "give --start-amplitude",
                                       request.frequency_hz, brief_report(p.summary)));
    }
    result.start_amplitude_m = p.amplitude;
  }

  span::EbmWindOptions options;
  options.frequency_hz = request.frequency_hz;
  options.duration_s = result.settings.duration_s;
  options.elements_per_wavelength = result.settings.elements_per_wavelength;
  options.steps_per_period = result.settings.steps_per_period;
  options.start_amplitude_m = result.start_amplitude_m;
  options.wind = result.wind;
  options.wake = result.settings.wake;
  options.stop = stop;
  long long step = 0;
  double next_progress = 0.0;
  SimulationRow record;
  options.observer = [&](const span::NewmarkStepper& stepper) {
    ++step;
    if (row && step % request.every == 0) {
      record.time_s = stepper.time();
      record.y_m.clear();
      for (const double x : result.probes) record.y_m.push_back(stepper.model().at(stepper.displacement(), x).first);
      record.force_n.clear();
      record.velocity_m_s.clear();
      for (std::size_t d = 0; d < stepper.dampers().size(); ++d) {
        record.force_n.push_back(stepper.dampers()[d].damper.force());
        record.velocity_m_s.push_back(stepper.clamp_velocity(d));
      }
      row(record);
    }
    if (progress && stepper.time() >= next_progress) {
      progress(stepper.time(), options.duration_s);
      next_progress += 1.0;
    }
  };
  result.history = span::settle_on_ebm_wind(span, result.settings.ends, options);
  result.balance = balance_at(span, balance, result.history.frequency_hz);
  return result;
}

Table<SimulationRow> simulation_table(const std::vector<std::string>& probe_columns, std::size_t dampers) {
  std::vector<std::string> damper_columns;
  for (std::size_t d = 0; d < dampers; ++d) damper_columns.push_back(fmt::format("damper_{}", d + 1));
  std::vector<Quantity<SimulationRow>> q;
  q.push_back({"time_s", "s", "time since the start", ColumnKind::number,
               [](const SimulationRow& r, std::size_t) { return r.time_s; }, {}});
  if (!probe_columns.empty()) {
    q.push_back({"<probe>_m", "m", "the conductor's displacement at the probe (y_at_89mm: 89 mm from end 1)",
                 ColumnKind::number, [](const SimulationRow& r, std::size_t i) { return r.y_m[i]; }, {}});
  }
  if (dampers > 0) {
    q.push_back({"<damper>_force_n", "N", "the damper's force on the conductor, upward", ColumnKind::number,
                 [](const SimulationRow& r, std::size_t i) { return r.force_n[i]; }, {}});
    q.push_back({"<damper>_velocity_m_s", "m/s", "the damper's clamp velocity", ColumnKind::number,
                 [](const SimulationRow& r, std::size_t i) { return r.velocity_m_s[i]; }, {}});
  }
  return Table<SimulationRow>(std::move(q), {{"<probe>", probe_columns}, {"<damper>", damper_columns}});
}

namespace {

/// A steady figure beside the balance's: "<name>", "ebm_<name>" and "<name>_ratio".
void add_compared(io::JsonObject& json, std::string_view name, const ComparedFigure& figure) {
  json.add(name, figure.simulated);
  json.add(fmt::format("ebm_{}", name), figure.balanced);
  json.add(fmt::format("{}_ratio", name), figure.ratio);
}

ComparedFigure compared(double simulated, double balanced, bool settled, bool balance_converged) {
  const double s = settled ? simulated : kNoValue, b = balance_converged ? balanced : kNoValue;
  return {s, b, ratio(s, b)};
}

io::JsonObject damper_summary(const span::DamperInTimeFigures& d, const span::DamperAtBalance* at_balance, bool settled,
                              std::size_t index) {
  io::JsonObject json;
  json.add("column", fmt::format("damper_{}", index + 1)).add("name", d.name).add("position_m", d.position_m);
  add_compared(json, "power_w", compared(d.power_w, at_balance ? at_balance->power : kNoValue, settled, at_balance != nullptr));
  add_compared(json, "velocity_m_s", compared(d.velocity_amplitude_m_s, at_balance ? at_balance->clamp_velocity : kNoValue,
                                              settled, at_balance != nullptr));
  json.add("dissipated_w", settled ? d.dissipated_w : kNoValue);
  json.add("force_harmonics_n", settled ? d.force_harmonics_n : std::vector<double>{});
  double higher = 0.0;
  for (std::size_t h = 1; h < d.force_harmonics_n.size(); ++h) higher += d.force_harmonics_n[h] * d.force_harmonics_n[h];
  json.add("force_distortion", settled ? ratio(std::sqrt(higher), d.force_harmonics_n.front()) : kNoValue);
  return json;
}

}  // namespace

SteadyComparison steady_comparison(const span::Span& span, const SimulateResult& result) {
  const span::EbmWindHistory& h = result.history;
  const bool settled = h.settled, converged = result.balance_converged();
  const span::BalancePoint& p = result.balance;
  const span::Conductor& c = span.conductor();
  const double f = h.frequency_hz, s = h.end_loop_amplitude_m[0], xb = span.fatigue().yb_distance;
  const double yb = span::bending_amplitude(c, span.tension(), f, s, xb);
  SteadyComparison out;
  out.antinode_amplitude_m = compared(h.antinode_amplitude_m, p.amplitude, settled, converged);
  out.clamp_loop_amplitude_m = compared(s, p.clamp_loop_amplitude, settled, converged);
  out.bending_amplitude_m = compared(yb, p.bending_amplitude, settled, converged);
  out.stress_poffenberger_swart_pa = compared(span::poffenberger_swart_stress(c, span.tension(), yb, xb),
                                              p.stress_poffenberger_swart, settled, converged);
  out.stress_fymax_pa = compared(span::fymax_stress(c, f, s), p.stress_fymax, settled, converged);
  return out;
}

io::JsonObject simulate_summary(const span::Span& span, const SimulateResult& result) {
  const span::EbmWindHistory& h = result.history;
  const bool settled = h.settled, converged = result.balance_converged();
  io::JsonObject json;
  json.add("frequency_hz", h.frequency_hz).add("asked_frequency_hz", result.asked_frequency_hz);
  json.add("ends", span::beam_ends_name(result.settings.ends)).add("wind", span::wind_in_time_name(result.wind));
  json.add("wind_speed_m_s", result.wind == span::WindInTime::wake ? h.wind_speed_m_s : kNoValue);
  json.add("elements", h.elements).add("dt_s", h.dt_s).add("simulated_s", h.time_s);
  json.add("periods", static_cast<int>(h.envelope_m.size())).add("settled", settled).add("interrupted", h.interrupted);
  json.add("settled_by", span::settled_by_name(h.settled_by)).add("figure_periods", h.figure_periods);
  json.add("envelope_fluctuation", settled ? h.envelope_fluctuation : kNoValue);
  json.add("start_amplitude_m", result.start_amplitude_m).add("ebm_converged", converged);
  json.add("last_envelope_m", h.envelope_m.empty() ? kNoValue : h.envelope_m.back());
  json.add("wind_power_w", settled ? h.wind_power_w : kNoValue).add("damping_power_w", settled ? h.damping_power_w : kNoValue);
  const SteadyComparison figures = steady_comparison(span, result);
  add_compared(json, "antinode_amplitude_m", figures.antinode_amplitude_m);
  add_compared(json, "clamp_loop_amplitude_m", figures.clamp_loop_amplitude_m);
  add_compared(json, "bending_amplitude_m", figures.bending_amplitude_m);
  add_compared(json, "stress_poffenberger_swart_pa", figures.stress_poffenberger_swart_pa);
  add_compared(json, "stress_fymax_pa", figures.stress_fymax_pa);
  std::vector<io::JsonObject> dampers;
  for (std::size_t d = 0; d < h.dampers.size(); ++d) {
    dampers.push_back(damper_summary(h.dampers[d], result.balance_damper(h.dampers[d].position_m), settled, d));
  }
  json.add("dampers", dampers);
  json.add("probes_m", result.probes);
  json.add("envelope_m", h.envelope_m);
  json.add("x_m", h.x_m);
  json.add("amplitude_m", h.amplitude_m);
  json.add("antinode_along_m", h.antinode_along_m);
  json.add("seconds", result.seconds);
  return json;
}

}  // namespace stockbridge::requests
