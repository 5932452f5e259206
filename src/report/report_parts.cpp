#include "report_parts.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/numerics/solver_summary.hpp"
#include "stockbridge/requests/span_modes_request.hpp"
#include "stockbridge/span/fatigue.hpp"
#include "stockbridge/span/profile.hpp"
#include "stockbridge/span/tension_figures.hpp"

namespace stockbridge::report::parts {

namespace {

std::vector<double> column(const requests::TableValues& values, std::string_view name) {
  return values.column(name).numbers;
}

}  // namespace

std::string number(double value, int digits) {
  if (!std::isfinite(value)) return "-";
  return fmt::format("{:.{}g}", value, digits);
}

std::string megapascal(double pascal) { return number(pascal / 1e6, 3) + " MPa"; }

std::string years(double life_years) {
  return std::isfinite(life_years) ? number(life_years, 3) + " years" : "unlimited (no damage)";
}

Tone verdict_tone(span::Verdict verdict) {
  switch (verdict) {
    case span::Verdict::safe: return Tone::good;
    case span::Verdict::unsafe: return Tone::bad;
    default: return Tone::unknown;
  }
}

namespace {

/// Where a damper hangs, in words: "1 m from the clamp, at both ends", "at 118, 122 m from end 1".
std::string damper_place_text(const span::SpanDamper& d) {
  if (!d.in_span()) return fmt::format("{} m from the clamp, {}", number(d.position, 4), d.both_ends ? "at both ends" : "at one end");
  std::string at;
  for (const double x : d.along) at += (at.empty() ? "" : ", ") + number(x, 4);
  return fmt::format("at {} m from end 1", at);
}

}  // namespace

std::string positions_text(const span::Span& s) {
  std::string out;
  for (const span::SpanDamper& d : s.dampers()) {
    if (!d.in_span()) out += (out.empty() ? "" : ", ") + number(d.position, 4);
    for (const double x : d.along) out += (out.empty() ? "" : ", ") + number(x, 4) + " from end 1";
  }
  return out.empty() ? "none" : out + " m";
}

std::vector<Fact> span_inputs(const span::Span& s, span::DamperModel model) {
  const span::Conductor& c = s.conductor();
  const span::TensionFigures t = span::tension_figures(s);
  std::vector<Fact> facts{
      {"conductor", fmt::format("{}D = {} mm, {} kg/m, RTS {} kN, EI_min {} N m², E_a {} GPa",
                                c.name.empty() ? "" : c.name + ": ", number(1e3 * c.diameter), number(c.mass_per_length),
                                number(c.rated_tensile_strength / 1e3), number(c.ei_min), number(c.outer_wire_modulus / 1e9, 3))},
      {"span length", number(s.length()) + " m"},
      {"tension", fmt::format("{} kN = {} % RTS; H/w = {} m", number(t.tension / 1e3), number(100.0 * t.fraction_of_rts, 3),
                              number(t.catenary_parameter))},
      {"span parameter L D / m", number(t.span_parameter) + " m³/kg"},
  };
  if (const std::optional<span::SafeDesignTension> safe = span::safe_design_tension(s)) {
    facts.emplace_back("CIGRE TB 273", fmt::format("terrain category {} ({}): H/w {} m is {} the {} m an undamped single "
                                                   "conductor allows{}",
                                                   safe->terrain.category, safe->terrain.description,
                                                   number(safe->catenary_parameter), safe->within ? "within" : "above",
                                                   number(safe->terrain.catenary_parameter_limit),
                                                   safe->within ? "" : " (dampers needed)"));
  }
  const span::WindModel& w = s.wind();
  const span::Interval band = w.frequency_band(c.diameter);
  const std::string turbulence =
      w.law != span::WindLaw::foti ? std::string()
      : w.turbulence_terrain
          ? fmt::format(", turbulence intensity {} (terrain category {}: this program's assumed intensity, docs/span.md)",
                        number(w.turbulence_intensity, 3), *w.turbulence_terrain)
          : ", turbulence intensity " + number(w.turbulence_intensity, 3);
  facts.emplace_back("wind", fmt::format("law {}, Strouhal {}, {} to {} m/s: {} to {} Hz{}", span::wind_law_name(w.law),
                                         number(w.strouhal, 3), number(w.speed_min, 3), number(w.speed_max, 3),
                                         number(band.lo, 3), number(band.hi, 3), turbulence));
  const span::PowerLawExponents e = s.self_damping().exponents();
  facts.emplace_back("self-damping",
                     s.self_damping().law == span::SelfDampingLaw::foti
                         ? fmt::format("law foti, chi0 {} 1/m", number(s.self_damping().limit_curvature.value_or(NAN)))
                         : fmt::format("law {}: P = L k Y^{} f^{} / (T/1000)^{}, k = {}",
                                       span::self_damping_law_name(s.self_damping().law), number(e.l, 3), number(e.m, 3),
                                       number(e.n, 3), number(s.self_damping().factor(c))));
  if (s.dampers().empty()) {
    facts.emplace_back("dampers", "none");
  } else {
    for (const span::SpanDamper& d : s.dampers()) {
      const std::string mass = d.damper ? ", " + number(d.damper->total_mass(), 3) + " kg" : std::string();
      facts.emplace_back("damper " + d.name,
                         fmt::format("{}{}; {} model{}{}", damper_place_text(d), mass, span::damper_model_name(model),
                                     d.measured() ? ", Z from its measured sheet" : "",
                                     d.fit ? "; its model " + d.fit->summary() : std::string()));
    }
  }
  for (const span::SpanMass& m : s.masses()) {
    std::string at;
    for (const double x : m.positions) at += (at.empty() ? "" : ", ") + number(x, 4);
    facts.emplace_back("mass " + m.name, fmt::format("{} kg at {} m from end 1{}", number(m.mass, 3), at,
                                                     m.stress_factor != 1.0
                                                         ? ", its clamp's stress factor " + number(m.stress_factor, 3)
                                                         : std::string()));
  }
  const span::FatigueSpec& f = s.fatigue();
  facts.emplace_back("criterion", fmt::format("{}: {}, {} ({} microstrain peak-to-peak)",
                                              span::fatigue_criterion_name(f.criterion), s.criterion_description(),
                                              megapascal(s.endurance_limit()),
                                              number(span::bending_strain_pp_microstrain(c, s.endurance_limit()), 4)));
  facts.emplace_back("stresses",
                     fmt::format("{} at the clamp (the verdict); Poffenberger-Swart from Yb at {} mm (the life)",
                                 s.judges_poffenberger_swart() ? "the bending strain from Yb" : "fymax",
                                 number(1e3 * f.yb_distance, 3)));
  if (f.life) {
    facts.emplace_back("climate", fmt::format("Weibull wind k = {}, c = {} m/s; aeolian share of the year {}",
                                              number(f.life->wind_weibull.shape, 3), number(f.life->wind_weibull.scale, 3),
                                              number(f.life->aeolian_fraction, 3)));
  }
  return facts;
}

std::vector<Fact> span_key_figures(const span::SpanAnalysis& a) {
  const span::BalanceSummary& m = a.balance.summary;
  const span::Conductor& c = a.span.conductor();
  std::vector<Fact> out;
  const std::string partial = m.all_converged() ? "" : " (of the converged points)";
  if (m.converged > 0) {
    out.emplace_back("largest fymax stress" + partial,
                     fmt::format("{} at {} Hz", megapascal(m.max_stress_fymax), number(m.max_stress_frequency_hz, 3)));
    out.emplace_back("judged / endurance limit" + partial, number(100.0 * m.max_judged_stress / m.endurance_limit, 3) + " %");
    if (a.span.has_attachments() || m.max_judged_stress_place != "span clamp 1") {
      out.emplace_back("governing place" + partial,
                       fmt::format("{}: {} at {} Hz", m.max_judged_stress_place, megapascal(m.max_judged_stress),
                                   number(m.max_judged_stress_frequency_hz, 3)));
    }
    if (std::isfinite(m.max_judged_stress_high)) {
      out.emplace_back("top of the measured sheets' band" + partial,
                       fmt::format("{}, {} % of the endurance limit (the sheets' error estimate {} %)",
                                   megapascal(m.max_judged_stress_high),
                                   number(100.0 * m.max_judged_stress_high / m.endurance_limit, 3),
                                   number(100.0 * a.sheet_error_estimate, 3)));
    }
    out.emplace_back("largest Yb" + partial, fmt::format("{} mm p-p, {} µε", number(1e3 * m.max_bending_amplitude, 3),
                                                         number(span::bending_strain_pp_microstrain(c, m.max_stress_poffenberger_swart), 4)));
  }
  if (m.undamped_points > 0) {
    out.emplace_back("undamped largest fymax stress", fmt::format("{} at {} Hz", megapascal(m.undamped_max_stress_fymax),
                                                                  number(m.undamped_max_stress_frequency_hz, 3)));
    out.emplace_back("undamped largest Yb", fmt::format("{} mm p-p, {} µε", number(1e3 * m.undamped_max_bending_amplitude, 3),
                                                        number(span::bending_strain_pp_microstrain(c, m.undamped_max_stress_poffenberger_swart), 4)));
  }
  if (!a.span.dampers().empty() && m.converged > 0) {
    out.emplace_back("largest stress at a damper clamp" + partial, megapascal(m.max_damper_clamp_stress));
  }
  if (a.span.fatigue().life) {
    out.emplace_back("life (comparative)", m.life ? years(m.life->life_years)
                                                  : fmt::format("unknown: {} points missing", m.life_missing_points));
    out.emplace_back("undamped life (comparative)",
                     m.undamped_life ? years(m.undamped_life->life_years)
                                     : fmt::format("unknown: {} points missing", m.undamped_life_missing_points));
  }
  out.emplace_back("points converged", fmt::format("{} of {}", m.converged, m.points));
  return out;
}

std::string span_verdict_reason(const span::SpanAnalysis& a) {
  const span::BalanceSummary& m = a.balance.summary;
  const std::string limit = fmt::format("{} ({})", megapascal(m.endurance_limit), a.span.criterion_description());
  const std::string judged = a.span.judges_poffenberger_swart() ? "Poffenberger-Swart stress (from Yb)" : "fymax stress";
  switch (m.verdict) {
    case span::Verdict::safe:
      return fmt::format("every {} is within the endurance limit {}: the largest, {} at {} Hz, is {} % of it.", judged,
                         limit, megapascal(m.max_judged_stress), number(m.max_judged_stress_frequency_hz, 3),
                         number(100.0 * m.max_judged_stress / m.endurance_limit, 3));
    case span::Verdict::unsafe:
      return fmt::format("the {} reaches {} at {} Hz, {} % of the endurance limit {}.", judged,
                         megapascal(m.max_judged_stress), number(m.max_judged_stress_frequency_hz, 3),
                         number(100.0 * m.max_judged_stress / m.endurance_limit, 3), limit);
    case span::Verdict::uncertain:
      return fmt::format("the {} stays within the endurance limit {} (at most {} % of it), but the measured sheets' "
                         "band reaches {}, {} % of it: the sheets cannot tell whether the span is safe.",
                         judged, limit, number(100.0 * m.max_judged_stress / m.endurance_limit, 3),
                         megapascal(m.max_judged_stress_high), number(100.0 * m.max_judged_stress_high / m.endurance_limit, 3));
    default:
      return fmt::format("{} of {} points did not converge; no converged point exceeds the endurance limit {}, but the "
                         "verdict needs every point.",
                         m.points - m.converged, m.points, limit);
  }
}

namespace {

/// The stress chart of the analysis's CSV values `v`.
Chart stress_chart(const span::SpanAnalysis& a, const requests::TableValues& v, std::string_view title) {
  const std::vector<double> f = column(v, "frequency_hz");
  const span::Conductor& c = a.span.conductor();
  Chart chart(std::string(title), Axis("frequency (Hz)", true), Axis("fymax stress at the clamp (MPa)"));
  if (!a.span.dampers().empty()) chart.series.push_back({"with dampers", f, column(v, "stress_fymax_mpa"), LineStyle::solid, 0});
  const std::vector<double> low = column(v, "stress_fymax_low_mpa"), high = column(v, "stress_fymax_high_mpa");
  if (std::any_of(high.begin(), high.end(), [](double h) { return std::isfinite(h); })) {
    chart.bands.push_back({"measured sheets' band", f, low, high, 0});
  }
  chart.series.push_back({"without dampers", f, column(v, "undamped_stress_fymax_mpa"), LineStyle::dashed, 1});
  chart.references.push_back({"endurance limit " + megapascal(a.span.endurance_limit()), a.span.endurance_limit() / 1e6});
  chart.top = SecondaryAxis{"wind speed (m/s)", a.span.wind().wind_speed(1.0, c.diameter)};
  chart.right = SecondaryAxis{"bending strain, peak-to-peak (µε)", span::bending_strain_pp_microstrain(c, 1e6)};
  return chart;
}

}  // namespace

Chart span_stress_chart(const span::SpanAnalysis& a, std::string_view title) {
  return stress_chart(a, requests::span_table(a.span).values(a.balance.points), title);
}

void span_figures(HtmlPage& page, const span::SpanAnalysis& a, std::string_view name) {
  const requests::TableValues v = requests::span_table(a.span).values(a.balance.points);
  const std::vector<double> f = column(v, "frequency_hz");
  const double wind_scale = a.span.wind().wind_speed(1.0, a.span.conductor().diameter);
  const span::BalanceSummary& m = a.balance.summary;
  std::string title = fmt::format("{}: {}", name, span::verdict_name(m.verdict));
  if (!a.span.dampers().empty()) title += ", dampers at " + positions_text(a.span);
  if (m.converged > 0) title += fmt::format(", max {} at {} Hz", megapascal(m.max_stress_fymax), number(m.max_stress_frequency_hz, 3));
  if (std::isfinite(m.max_judged_stress_high)) title += ", band top " + megapascal(m.max_judged_stress_high);
  if (a.span.fatigue().life && m.life) title += ", life " + years(m.life->life_years);
  page.figure(svg(stress_chart(a, v, title)),
              "The fymax bending stress at the span clamp over the wind band, with and without the dampers, against "
              "the endurance limit; the right axis gives the same as the outer wires' peak-to-peak strain. A gap is "
              "a point that did not converge. With measured sheets, the shaded band is where the sheets' "
              "interpolation leaves the stress (the stress times 1 -+ the sheets' error estimate).");

  Chart amplitude(fmt::format("{}: antinode amplitude", name), Axis("frequency (Hz)", true),
                  Axis("amplitude Y, single peak (mm)", true));
  std::vector<double> y = column(v, "amplitude_m"), y0 = column(v, "undamped_amplitude_m");
  for (double& x : y) x *= 1e3;
  for (double& x : y0) x *= 1e3;
  if (!a.span.dampers().empty()) amplitude.series.push_back({"with dampers", f, y, LineStyle::solid, 0});
  amplitude.series.push_back({"without dampers", f, y0, LineStyle::dashed, 1});
  amplitude.top = SecondaryAxis{"wind speed (m/s)", wind_scale};
  page.figure(svg(amplitude), "The conductor's antinode amplitude where the wind's power equals the dissipated power.");

  Chart power(fmt::format("{}: power balance", name), Axis("frequency (Hz)", true), Axis("power (W)", true));
  power.series.push_back({"wind", f, column(v, "wind_power_w"), LineStyle::solid, 3});
  power.series.push_back({"conductor self-damping", f, column(v, "self_damping_power_w"), LineStyle::dashed, 2});
  if (!a.span.dampers().empty()) power.series.push_back({"dampers", f, column(v, "damper_power_w"), LineStyle::solid, 0});
  power.top = SecondaryAxis{"wind speed (m/s)", wind_scale};
  page.figure(svg(power), "The powers at the balance: what the wind brings in equals what the conductor and the dampers dissipate.");
  if (a.span.has_attachments() && m.converged > 0) {
    span_profile_figure(page, a, name);
    span_modes_figure(page, a, name);
  }
}

void span_profile_figure(HtmlPage& page, const span::SpanAnalysis& a, std::string_view name) {
  const span::SpanProfile profile = span::span_profile(a.span, span::governing_point(a.span, a.balance));
  Chart chart(fmt::format("{}: along the span at {} Hz", name, number(profile.frequency_hz, 3)),
              Axis("distance from end 1 (m)"), Axis("amplitude, single peak (mm)"));
  std::vector<double> y, envelope;
  for (const double d : profile.displacement) y.push_back(1e3 * d);
  for (const double e : profile.envelope) envelope.push_back(1e3 * e);
  chart.series.push_back({"|Y(x)|", profile.x, y, LineStyle::solid, 0});
  chart.series.push_back({"stretch's antinode |A| + |B|", profile.x, envelope, LineStyle::dashed, 1});
  Series masses{"masses", {}, {}, LineStyle::square, 3}, dampers{"dampers", {}, {}, LineStyle::ring, 2};
  const double top = envelope.empty() ? 0.0 : *std::max_element(envelope.begin(), envelope.end());
  for (const span::ProfileAttachment& at : profile.attachments) {
    Series& s = at.mass ? masses : dampers;
    s.x.push_back(at.position);
    s.y.push_back(1.05 * top);
  }
  if (!masses.x.empty()) chart.series.push_back(std::move(masses));
  if (!dampers.x.empty()) chart.series.push_back(std::move(dampers));
  page.figure(svg(chart),
              fmt::format("The standing wave along the span at the governing frequency ({} Hz, where the largest judged "
                          "stress is: {}): the displacement amplitude and, dashed, the antinode amplitude of each stretch "
                          "between attachments; the marks above show where the masses and dampers hang.",
                          number(profile.frequency_hz, 3), a.balance.summary.max_judged_stress_place));
}

void span_modes_figure(HtmlPage& page, const span::SpanAnalysis& a, std::string_view name) {
  const double governing = span::governing_point(a.span, a.balance).frequency_hz;
  const bool measured =
      std::any_of(a.span.dampers().begin(), a.span.dampers().end(), [](const span::SpanDamper& d) { return d.measured(); });
  requests::SpanModesRequest request;
  request.fmax = 1.2 * governing;
  request.dampers = measured ? "removed" : "linear";  // a sheet has no linear impedance of its own
  const span::SpanModes m = requests::run_span_modes(a.span, request).modes;
  if (m.modes.empty()) return;
  // One shape: on a long span at tens of Hz, two overlaid are no longer readable.
  const span::SpanMode& mode = *std::min_element(m.modes.begin(), m.modes.end(), [&](const auto& p, const auto& q) {
    return std::abs(p.frequency_hz - governing) < std::abs(q.frequency_hz - governing);
  });
  Chart chart(fmt::format("{}: the natural mode nearest {} Hz", name, number(governing, 3)),
              Axis("distance from end 1 (m)"), Axis("Y / largest |Y|"));
  chart.series.push_back({fmt::format("mode {}, {} Hz", mode.number, number(mode.frequency_hz, 4)), m.x, mode.shape,
                          LineStyle::solid, 0});
  Series masses{"masses", {}, {}, LineStyle::square, 3}, dampers{"dampers", {}, {}, LineStyle::ring, 2};
  for (const span::ModeAttachment& at : m.attachments) {
    Series& s = at.kind == span::AttachmentKind::mass ? masses : dampers;
    s.x.push_back(at.position);
    s.y.push_back(1.1);
  }
  if (!masses.x.empty()) chart.series.push_back(std::move(masses));
  if (!dampers.x.empty()) chart.series.push_back(std::move(dampers));
  const double bare = m.wave_speed / (2.0 * m.length);
  page.figure(svg(chart),
              fmt::format("The span's natural mode nearest the governing frequency ({} Hz), with its masses as rigid "
                          "masses and its dampers {}; the bare span's mode n would be at n x {} Hz. {} modes lie below "
                          "{} Hz (stockbridge span --modes lists them all).",
                          number(governing, 3),
                          measured ? "removed (a measured sheet has no linear impedance)"
                                   : "at their linear impedance (every element sticking)",
                          number(bare, 4), m.modes.size(), number(m.max_frequency_hz, 3)));
}

std::vector<std::string> span_caveats(bool life) {
  std::vector<std::string> out{
      "The energy balance method (EPRI's Orange Book, CIGRE's wind power and self-damping data, IEC 61897's damper "
      "effectiveness evaluation; CIGRE TB 273's H/w rule is a separate judgement beside it) takes one standing mode "
      "at a time in steady wind across the span; span-wise wind variation and travelling-wave effects other than at "
      "the dampers are not modelled, and turbulence only through the foti law's intensity, so the stresses are upper "
      "estimates of what a calm site sees.",
      "The verdict compares the largest stress its criterion judges with the endurance limit; it needs every point "
      "of the band to converge ('unknown' otherwise), and with measured sheets it is 'uncertain' where the sheets' "
      "band reaches above the limit while the stress itself stays below.",
  };
  if (life) {
    out.push_back("Lives are comparative, not predictions: they rest on the assumed wind climate (a Weibull distribution "
                  "and an aeolian share of the year), one cycle per period and Miner's rule on the Safe Border Line. Use "
                  "them to rank arrangements and dampers, not as a service life.");
  }
  return out;
}

std::vector<std::string> span_failures(const span::SpanAnalysis& a, std::size_t shown) {
  std::vector<std::string> out;
  std::size_t failed = 0;
  for (const span::BalancePoint& p : a.balance.points) {
    if (p.converged()) continue;
    if (++failed <= shown) out.push_back(fmt::format("f = {} Hz did not converge: {}", number(p.frequency_hz, 4), brief_report(p.summary)));
  }
  if (failed > shown) out.push_back(fmt::format("... and {} more points", failed - shown));
  return out;
}

}  // namespace stockbridge::report::parts

namespace stockbridge::report::parts {

namespace {

std::string amplitude_label(double amplitude, bool constant_displacement) {
  return constant_displacement ? "X = " + number(1e3 * amplitude, 3) + " mm" : "V = " + number(amplitude, 3) + " m/s";
}

/// The messenger's law and its stiffness at the clamp, in words.
std::string cable_law_summary(const cable::CableDescription& c) {
  return c.law->summary(c, [](double value) { return number(value, 3); });
}

}  // namespace

std::vector<Fact> damper_facts(const damper::Damper& d) {
  std::vector<Fact> out{{"total mass", number(d.total_mass(), 4) + " kg"},
                        {"clamp mass", number(d.description().clamp_mass, 4) + " kg"}};
  std::size_t k = 0;
  for (const damper::ArmDescription& arm : d.description().arms) {
    ++k;
    const cable::CableDescription& c = arm.cable;
    out.emplace_back(fmt::format("arm {}{}", k, arm.name.empty() ? "" : " (" + arm.name + ")"),
                     fmt::format("mass {} kg, inertia {} kg m², offset {} mm; messenger {} mm long, {}",
                                 number(arm.mass, 4), number(arm.inertia, 3), number(1e3 * arm.offset, 3),
                                 number(1e3 * c.length, 4), cable_law_summary(c)));
  }
  return out;
}

std::vector<Fact> largest_power_facts(const std::vector<damper::SweepRun>& runs, bool constant_displacement) {
  std::vector<Fact> out;
  for (const damper::SweepRun& run : runs) {
    const damper::ImpedancePoint* best = nullptr;
    for (const damper::ImpedancePoint& p : run.points) {
      if (p.converged() && (!best || p.power > best->power)) best = &p;
    }
    out.emplace_back("largest power at " + amplitude_label(run.amplitude, constant_displacement),
                     best ? fmt::format("{} W at {} Hz", number(best->power, 3), number(best->frequency_hz, 3))
                          : std::string("none converged"));
  }
  return out;
}

void impedance_figures(HtmlPage& page, const damper::Damper& d, const std::vector<damper::SweepRun>& runs,
                       bool constant_displacement, std::string_view name) {
  const requests::Table<damper::ImpedancePoint> table = requests::impedance_table(d);
  Chart abs_z(fmt::format("{}: impedance magnitude", name), Axis("frequency (Hz)", true), Axis("|Z| (N s/m)", true));
  Chart phase(fmt::format("{}: impedance phase", name), Axis("frequency (Hz)", true), Axis("phase of Z (deg)"));
  Chart power(fmt::format("{}: power taken from the clamp", name), Axis("frequency (Hz)", true), Axis("power (W)", true));
  for (const damper::SweepRun& run : runs) {
    const requests::TableValues v = table.values(run.points);
    const std::vector<double>& f = v.column("frequency_hz").numbers;
    const std::string label = amplitude_label(run.amplitude, constant_displacement);
    abs_z.series.push_back({label, f, v.column("abs_z_n_s_m").numbers});
    phase.series.push_back({label, f, v.column("phase_deg").numbers});
    power.series.push_back({label, f, v.column("power_w").numbers});
  }
  page.figure(svg(abs_z), "The magnitude of the damper's impedance Z = F / V at the clamp, a curve per amplitude; a "
                          "gap is a point that did not converge.");
  page.figure(svg(phase), "The phase of Z: 0° is a pure damper, +90° a mass, -90° a spring.");
  page.figure(svg(power), "The mean power the damper takes at its clamp, V² Re Z / 2.");
}

void impedance_table(HtmlPage& page, const damper::Damper& d, const std::vector<damper::SweepRun>& runs,
                     bool constant_displacement) {
  const requests::Table<damper::ImpedancePoint> table = requests::impedance_table(d);
  std::vector<std::vector<std::string>> rows;
  for (const damper::SweepRun& run : runs) {
    const requests::TableValues v = table.values(run.points);
    const std::size_t n = run.points.size();
    const std::size_t step = std::max<std::size_t>(1, n / 10);
    for (std::size_t i = 0; i < n; i += step) {
      rows.push_back({amplitude_label(run.amplitude, constant_displacement), number(v.column("frequency_hz").numbers[i], 4),
                      number(v.column("abs_z_n_s_m").numbers[i], 4), number(v.column("phase_deg").numbers[i], 3),
                      number(v.column("re_z_n_s_m").numbers[i], 4), number(v.column("power_w").numbers[i], 3)});
    }
  }
  page.table({"amplitude", "frequency (Hz)", "|Z| (N s/m)", "phase (deg)", "Re Z (N s/m)", "power (W)"}, rows);
}

void modes_table(HtmlPage& page, const requests::ModesResult& modes) {
  std::vector<std::vector<std::string>> rows;
  for (const requests::ModeRow& r : requests::mode_rows(modes)) {
    rows.push_back({r.arm == "damper" ? "whole damper (clamp free)" : "arm " + r.arm + " (clamp held)",
                    r.limit == damper::CableLimit::stick ? "stick (EI_max)" : "slip (EI_min)", std::to_string(r.mode),
                    number(r.frequency_hz, 4)});
  }
  page.table({"body", "messenger", "mode", "frequency (Hz)"}, rows);
}

std::vector<std::string> sweep_failures(const std::vector<damper::SweepRun>& runs, bool constant_displacement,
                                        std::size_t shown) {
  std::vector<std::string> out;
  std::size_t failed = 0;
  for (const damper::SweepRun& run : runs) {
    for (const damper::ImpedancePoint& p : run.points) {
      if (p.converged()) continue;
      if (++failed <= shown) {
        out.push_back(fmt::format("{}, f = {} Hz did not converge: {}", amplitude_label(run.amplitude, constant_displacement),
                                  number(p.frequency_hz, 4), p.failure));
      }
    }
  }
  if (failed > shown) out.push_back(fmt::format("... and {} more points", failed - shown));
  return out;
}

}  // namespace stockbridge::report::parts
