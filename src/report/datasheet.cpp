#include <cmath>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/span/tension_figures.hpp"

namespace stockbridge::report {

namespace {

using parts::number;

/// The damper on one span: a row of the overview table.
std::vector<std::string> span_row(const std::string& name, const requests::SpanResult& r) {
  const span::SpanAnalysis& a = r.analysis;
  const span::BalanceSummary& m = a.balance.summary;
  const span::TensionFigures t = span::tension_figures(a.span);
  const bool all = m.all_converged();
  std::string life = "-";
  if (a.span.fatigue().life) life = m.life ? parts::years(m.life->life_years) : "unknown";
  return {name,
          a.span.conductor().name,
          number(a.span.length()),
          number(100.0 * t.fraction_of_rts, 3),
          parts::positions_text(a.span),
          all ? number(m.max_stress_fymax / 1e6, 3) : "-",
          number(m.undamped_max_stress_fymax / 1e6, 3),
          number(m.endurance_limit / 1e6, 3),
          life,
          std::string(span::verdict_name(m.verdict))};
}

}  // namespace

std::string datasheet(const DatasheetInput& in, const ReportContext& context) {
  HtmlPage page({"Damper data sheet: " + in.damper_name, context.generated_at, context.command});
  int safe = 0;
  for (const requests::SpanResult& s : in.spans) safe += s.analysis.balance.summary.verdict == span::Verdict::safe;
  page.verdict(parts::number(in.damper->total_mass(), 3) + " kg",
               in.spans.empty() ? std::string(" impedance and power at the test velocities, and the linear modes.")
                                : fmt::format(" safe on {} of the {} spans below.", safe, in.spans.size()),
               Tone::neutral);
  std::vector<Fact> key{{"total mass", number(in.damper->total_mass(), 4) + " kg"}};
  for (Fact& f : parts::largest_power_facts(*in.runs, false)) key.push_back(std::move(f));
  page.key_figures(key);
  page.section("The damper");
  page.facts(parts::damper_facts(*in.damper));
  page.section("Impedance and power at the test velocities");
  parts::impedance_figures(page, *in.damper, *in.runs, false, in.damper_name);
  parts::impedance_table(page, *in.damper, *in.runs, false);
  page.section("Linear modes");
  parts::modes_table(page, *in.modes);
  if (!in.spans.empty()) {
    page.section("On the spans");
    std::vector<std::vector<std::string>> rows;
    std::vector<Tone> tones;
    for (std::size_t k = 0; k < in.spans.size(); ++k) {
      rows.push_back(span_row(in.span_names[k], in.spans[k]));
      tones.push_back(parts::verdict_tone(in.spans[k].analysis.balance.summary.verdict));
    }
    page.table({"span", "conductor", "length (m)", "tension (% RTS)", "positions", "max (MPa)", "undamped max (MPa)",
                "limit (MPa)", "life", "verdict"},
               rows, tones);
    for (std::size_t k = 0; k < in.spans.size(); ++k) {
      const span::SpanAnalysis& a = in.spans[k].analysis;
      const span::BalanceSummary& m = a.balance.summary;
      std::string title = fmt::format("{} on {}: {}", in.damper_name, in.span_names[k], span::verdict_name(m.verdict));
      if (m.converged > 0) title += fmt::format(", max {} at {} Hz", parts::megapascal(m.max_stress_fymax), number(m.max_stress_frequency_hz, 3));
      if (a.span.fatigue().life && m.life) title += ", life " + parts::years(m.life->life_years);
      page.figure(svg(parts::span_stress_chart(a, title)),
                  fmt::format("The damper at {} from the clamps of {}: the fymax stress with and without it.",
                              parts::positions_text(a.span), in.span_names[k]));
    }
  }
  page.section("Assumptions");
  std::vector<std::string> caveats{"The impedance is computed at a constant clamp velocity amplitude over the sweep, as "
                                   "IEC 61897 and IEEE 664 test it on a shaker."};
  bool life = false;
  for (const requests::SpanResult& s : in.spans) life = life || s.analysis.span.fatigue().life.has_value();
  if (!in.spans.empty()) {
    for (const std::string& c : parts::span_caveats(life)) caveats.push_back(c);
  }
  page.list(caveats);
  page.section("Warnings");
  std::vector<std::string> warnings = context.warnings;
  for (const std::string& f : parts::sweep_failures(*in.runs, false)) warnings.push_back(f);
  for (std::size_t k = 0; k < in.spans.size(); ++k) {
    for (const std::string& f : parts::span_failures(in.spans[k].analysis)) warnings.push_back(in.span_names[k] + ": " + f);
  }
  page.list(warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
