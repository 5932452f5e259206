#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"

namespace stockbridge::report {

std::string span_report(const requests::SpanResult& result, const ReportContext& context,
                        const std::vector<requests::TimeCheck>& checks) {
  const span::SpanAnalysis& a = result.analysis;
  const span::Span& s = a.span;
  const span::BalanceSummary& m = a.balance.summary;
  const std::string name = fmt::format("{}{} m span", s.conductor().name.empty() ? "" : s.conductor().name + ", ",
                                       parts::number(s.length()));
  HtmlPage page({"Span energy balance: " + name, context.generated_at, context.command});
  page.verdict(std::string(span::verdict_name(m.verdict)), " " + parts::span_verdict_reason(a), parts::verdict_tone(m.verdict));
  page.key_figures(parts::span_key_figures(a));

  page.section("Inputs");
  page.facts(parts::span_inputs(s, result.damper_model));
  if (a.position) {
    page.paragraph(fmt::format("The dampers' positions {} were searched (each its own) to minimise the {}, in {} balances on the "
                               "impedance tables, then balanced there.",
                               parts::positions_text(s),
                               a.position->criterion == span::PositionObjective::life ? "damage per year" : "largest fymax stress",
                               a.position->balances));
  }
  page.section("Figures");
  parts::span_figures(page, a, name);
  parts::time_checks_section(page, checks, s.judges_poffenberger_swart());

  page.section("Assumptions");
  page.list(parts::span_caveats(s.fatigue().life.has_value()));
  page.section("Warnings");
  std::vector<std::string> warnings = context.warnings;
  for (const std::string& f : parts::span_failures(a)) warnings.push_back(f);
  for (const span::BalancePoint& p : a.balance.points) {
    if (p.several_states) warnings.push_back(fmt::format("f = {} Hz: {}", parts::number(p.frequency_hz), p.note));
  }
  page.list(warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
