// The span in time in the reports: `simulate --report` (a page of its own) and the
// span report's section of `span --check-time`.

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/report/svg_chart.hpp"

namespace stockbridge::report {

namespace {

std::string time_ratio(double ratio) { return std::isfinite(ratio) ? fmt::format("{:.3f}", ratio) : "-"; }

/// A compared figure's row: what, in time, by the balance, their ratio.
std::vector<std::string> time_compared_row(std::string what, const requests::ComparedFigure& f, double scale,
                                           std::string_view unit) {
  const auto cell = [&](double v) {
    return std::isfinite(v) ? fmt::format("{} {}", parts::number(scale * v), unit) : std::string("-");
  };
  return {std::move(what), cell(f.simulated), cell(f.balanced), time_ratio(f.ratio)};
}

Tone time_tone(bool compared, bool agrees) { return !compared ? Tone::unknown : agrees ? Tone::good : Tone::bad; }

/// Why a run's figures can or cannot stand beside the balance's.
std::string time_reason(const requests::SimulateResult& r, const requests::SteadyComparison& f, bool poffenberger_swart) {
  const span::EbmWindHistory& h = r.history;
  if (!h.settled) {
    return fmt::format(": the envelope did not settle in {} s simulated{}; no steady figure is given",
                       parts::number(h.time_s), h.interrupted ? " (interrupted)" : "");
  }
  if (!r.balance_converged()) return ": the balance at this frequency did not converge; nothing to compare with";
  return fmt::format(": in time, the antinode amplitude is {} and the {} stress {} of the balance's ({} % apart at most "
                     "counts as agreeing)",
                     time_ratio(f.antinode_amplitude_m.ratio), poffenberger_swart ? "Poffenberger-Swart" : "fymax",
                     time_ratio(requests::judged_stress(f, poffenberger_swart).ratio),
                     parts::number(100.0 * requests::kTimeCheckTolerance, 2));
}

/// The envelope per period and the amplitude along the span, the balance's antinode
/// amplitude beside each, the dampers marked.
void time_figures(HtmlPage& page, const requests::SimulateResult& r, std::string_view name) {
  const span::EbmWindHistory& h = r.history;
  const double balanced = r.balance_converged() ? 1e3 * r.balance.amplitude : NAN;
  Chart envelope(fmt::format("{}: the envelope at mid-span, period by period", name), Axis("period"),
                 Axis("antinode amplitude (mm)"));
  Series e{"in time", {}, {}, LineStyle::solid, 0};
  for (std::size_t k = 0; k < h.envelope_m.size(); ++k) {
    e.x.push_back(static_cast<double>(k + 1));
    e.y.push_back(1e3 * h.envelope_m[k]);
  }
  envelope.series.push_back(std::move(e));
  if (std::isfinite(balanced)) envelope.references.push_back({"the balance's", balanced});
  page.figure(svg(envelope),
              fmt::format("The local antinode amplitude at mid-span, once a period, from the start ({} mm) to the end: "
                          "it settles where the wind's input meets the self-damping and the dampers.",
                          parts::number(1e3 * r.start_amplitude_m)));
  Chart along(fmt::format("{}: along the span, the last period", name), Axis("distance from end 1 (m)"),
              Axis("amplitude, single peak (mm)"));
  std::vector<double> y;
  for (const double a : h.antinode_along_m) y.push_back(1e3 * a);
  along.series.push_back({"local antinode amplitude in time", h.x_m, y, LineStyle::solid, 0});
  Series dampers{"dampers", {}, {}, LineStyle::ring, 2};
  const double top = y.empty() ? 0.0 : *std::max_element(y.begin(), y.end());
  for (const span::DamperInTimeFigures& d : h.dampers) {
    dampers.x.push_back(d.position_m);
    dampers.y.push_back(1.05 * top);
  }
  if (!dampers.x.empty()) along.series.push_back(std::move(dampers));
  if (std::isfinite(balanced)) along.references.push_back({"the balance's antinode", balanced});
  page.figure(svg(along), "The standing wave's local antinode amplitude along the span over the last period (from the "
                          "displacement and slope at the drive frequency), the balance's antinode amplitude as a line: "
                          "it grows toward the dampers, where part of the wave travels; the marks above show where the "
                          "dampers hang.");
}

void time_dampers_table(HtmlPage& page, const requests::SimulateResult& r) {
  const span::EbmWindHistory& h = r.history;
  std::vector<std::vector<std::string>> rows;
  for (const span::DamperInTimeFigures& d : h.dampers) {
    const span::DamperAtBalance* at = r.balance_damper(d.position_m);
    std::string harmonics;
    for (std::size_t k = 0; k < d.force_harmonics_n.size(); k += 2) {
      harmonics += fmt::format("{}{}", harmonics.empty() ? "" : " / ", parts::number(d.force_harmonics_n[k], 3));
    }
    const bool settled = h.settled;
    rows.push_back({d.name, parts::number(d.position_m), settled ? parts::number(d.power_w, 3) : "-",
                    at ? parts::number(at->power, 3) : "-",
                    settled ? parts::number(1e3 * d.velocity_amplitude_m_s, 3) : "-",
                    at ? parts::number(1e3 * at->clamp_velocity, 3) : "-", settled ? harmonics : "-"});
  }
  page.table({"damper", "at (m from end 1)", "power in time (W)", "balance's (W)", "clamp velocity in time (mm/s)",
              "balance's (mm/s)", "force harmonics 1 / 3 / 5 (N)"},
             rows);
}

std::vector<std::string> time_assumptions(span::WindInTime wind) {
  if (wind == span::WindInTime::wake) {
    return {"The conductor is a tensioned Euler-Bernoulli beam (EI = EI_min) in cubic Hermite elements, stepped by "
            "Newmark's average acceleration rule; its ends as the span file's [span] ends say.",
            "The wind is Facchinetti's wake oscillator, one per element, shedding at the frequency asked (the wind "
            "speed from the span file's Strouhal number), coupled to the conductor's acceleration; the self-damping "
            "is the balance's law. The balance beside it has its own wind: the two differ by the wind's model too.",
            "Each damper is stepped by its own nonlinear model in time and solved with the conductor at every step."};
  }
  return {"The conductor is a tensioned Euler-Bernoulli beam (EI = EI_min) in cubic Hermite elements, stepped by "
          "Newmark's average acceleration rule; its ends as the span file's [span] ends say.",
          "The wind is the balance's own: its power law and the self-damping law act as distributed forces on the "
          "velocity, their coefficients from the local antinode amplitude, so that any difference from the balance is "
          "the balance's structural assumption: one standing wave, the travelling-wave picture at the ends, the "
          "dampers' first harmonic.",
          "Each damper is stepped by its own nonlinear model in time and solved with the conductor at every step.",
          "The drive is the span's natural mode nearest the frequency asked; the figures are means over the last "
          "periods once the envelope settled."};
}

}  // namespace

std::string simulate_report(const span::Span& span, span::DamperModel model, const requests::SimulateResult& r,
                            const ReportContext& context) {
  const span::EbmWindHistory& h = r.history;
  const bool ps = span.judges_poffenberger_swart();
  const requests::SteadyComparison f = requests::steady_comparison(span, r);
  const bool compared = h.settled && r.balance_converged();
  const std::string name = fmt::format("{}{} m span at {} Hz",
                                       span.conductor().name.empty() ? "" : span.conductor().name + ", ",
                                       parts::number(span.length()), parts::number(h.frequency_hz, 5));
  HtmlPage page({"Span in time: " + name, context.generated_at, context.command});
  const bool agrees = compared && requests::agrees(f);
  page.verdict(!compared ? "nothing compared" : agrees ? "agrees with the balance" : "differs from the balance",
               time_reason(r, f, ps), time_tone(compared, agrees));
  const auto mm = [](double v) { return std::isfinite(v) ? parts::number(1e3 * v) + " mm" : std::string("-"); };
  page.key_figures({{"antinode amplitude in time", mm(f.antinode_amplitude_m.simulated)},
                    {"the balance's", mm(f.antinode_amplitude_m.balanced)},
                    {"ratio", time_ratio(f.antinode_amplitude_m.ratio)},
                    {"simulated", fmt::format("{} s, {} periods", parts::number(h.time_s), h.envelope_m.size())}});

  page.section("Inputs");
  std::vector<Fact> inputs = parts::span_inputs(span, model);
  inputs.push_back({"frequency", fmt::format("{} Hz (the natural mode nearest the {} Hz asked)",
                                             parts::number(h.frequency_hz, 6), parts::number(r.asked_frequency_hz))});
  inputs.push_back({"ends", std::string(span::beam_ends_name(r.settings.ends))});
  const span::WakeParameters& wake = r.settings.wake;
  inputs.push_back({"wind in time",
                    r.wind == span::WindInTime::ebm
                        ? std::string("the energy balance's own")
                        : fmt::format("the wake oscillator at U = {} m/s (epsilon {}, A {}, C_L0 {}, rho {} kg/m^3)",
                                      parts::number(h.wind_speed_m_s), parts::number(wake.epsilon),
                                      parts::number(wake.coupling), parts::number(wake.lift_coefficient),
                                      parts::number(wake.air_density))});
  inputs.push_back({"powers", h.settled ? fmt::format("the wind's {} W, the self-damping's {} W",
                                                      parts::number(h.wind_power_w), parts::number(h.damping_power_w))
                                        : std::string("-")});
  inputs.push_back({"mesh and step", fmt::format("{} elements ({} a wavelength), dt = {} s ({} a period)", h.elements,
                                                 r.settings.elements_per_wavelength, parts::number(h.dt_s),
                                                 r.settings.steps_per_period)});
  inputs.push_back({"start", fmt::format("antinode amplitude {}", mm(r.start_amplitude_m))});
  inputs.push_back({"settled", h.settled ? fmt::format("by the {} rule, means over the last {} periods (the envelope "
                                                       "fluctuating by {} %)",
                                                       span::settled_by_name(h.settled_by), h.figure_periods,
                                                       parts::number(100.0 * h.envelope_fluctuation, 2))
                                         : std::string("no")});
  page.facts(inputs);

  page.section("In time beside the balance");
  page.table({"figure", "in time", "the balance's", "ratio"},
             {time_compared_row("antinode amplitude at mid-span", f.antinode_amplitude_m, 1e3, "mm"),
              time_compared_row("loop amplitude S next to clamp 1", f.clamp_loop_amplitude_m, 1e3, "mm"),
              time_compared_row("Y_b, peak-to-peak", f.bending_amplitude_m, 1e3, "mm"),
              time_compared_row("fymax stress", f.stress_fymax_pa, 1e-6, "MPa"),
              time_compared_row("Poffenberger-Swart stress", f.stress_poffenberger_swart_pa, 1e-6, "MPa")});
  if (!h.dampers.empty()) time_dampers_table(page, r);
  page.section("Figures");
  time_figures(page, r, name);
  page.section("Assumptions");
  page.list(time_assumptions(r.wind));
  page.section("Warnings");
  page.list(context.warnings, true);
  return page.html();
}

namespace {

/// " The runs: ... ." from the first run's settings (all share the span file's).
std::string time_settings_text(const std::vector<requests::TimeCheck>& checks) {
  for (const requests::TimeCheck& c : checks) {
    if (!c.result) continue;
    const span::TimeSettings& t = c.result->settings;
    return fmt::format(" The runs: {} ends, {} elements a wavelength, {} steps a period, {} s at most.",
                       span::beam_ends_name(t.ends), t.elements_per_wavelength, t.steps_per_period,
                       parts::number(t.duration_s));
  }
  return {};
}

}  // namespace

namespace parts {

void time_checks_section(HtmlPage& page, const std::vector<requests::TimeCheck>& checks, bool poffenberger_swart) {
  if (checks.empty()) return;
  page.section("Checked in time");
  page.paragraph(fmt::format(
      "The span was also simulated in time at {} frequencies (stockbridge simulate: the conductor a tensioned beam, "
      "the dampers by their own nonlinear models, the balance's own wind and self-damping). Where the two part by "
      "more than {} %, the balance's assumptions (one standing wave, the travelling-wave picture at the ends, the "
      "dampers' first harmonic) do not carry the answer there.{}",
      checks.size(), parts::number(100.0 * requests::kTimeCheckTolerance, 2), time_settings_text(checks)));
  std::vector<std::vector<std::string>> rows;
  std::vector<Tone> tones;
  const char* stress = poffenberger_swart ? "Poffenberger-Swart" : "fymax";
  for (const requests::TimeCheck& c : checks) {
    const requests::ComparedFigure& s = requests::judged_stress(c.figures, poffenberger_swart);
    const auto value = [](double v, double scale) { return std::isfinite(v) ? number(scale * v) : std::string("-"); };
    rows.push_back({number(c.asked_frequency_hz),
                    c.result ? number(c.result->history.frequency_hz, 6) : "-",
                    !c.result ? "no run" : c.result->history.settled ? "yes" : "no",
                    value(c.figures.antinode_amplitude_m.simulated, 1e3), value(c.figures.antinode_amplitude_m.balanced, 1e3),
                    time_ratio(c.figures.antinode_amplitude_m.ratio), value(s.simulated, 1e-6), value(s.balanced, 1e-6),
                    time_ratio(s.ratio)});
    tones.push_back(time_tone(c.compared(), c.agrees()));
  }
  page.table({"asked (Hz)", "simulated (Hz)", "settled", "Y in time (mm)", "Y balance (mm)", "ratio",
              fmt::format("{} stress in time (MPa)", stress), "balance (MPa)", "ratio"},
             rows, tones);
}

}  // namespace parts

}  // namespace stockbridge::report
