#include <cmath>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"

namespace stockbridge::report {

namespace {

using parts::number;

/// The column of an evaluation's figure, as the design CSV and the summary name it.
struct Figure {
  std::string label;
  double (*value)(const design::Evaluation&);
};

const std::vector<Figure>& figures() {
  static const std::vector<Figure> list{
      {"largest stress / endurance limit", [](const design::Evaluation& e) { return e.max_stress_ratio; }},
      {"largest fymax stress (MPa)", [](const design::Evaluation& e) { return e.max_stress / 1e6; }},
      {"at (Hz)", [](const design::Evaluation& e) { return e.frequency_at_max_hz; }},
      {"total mass (kg)", [](const design::Evaluation& e) { return e.total_mass; }},
      {"largest messenger curvature (1/m)", [](const design::Evaluation& e) { return e.messenger_curvature_max; }},
      {"shortest life (years, comparative)", [](const design::Evaluation& e) { return e.shortest_life_years; }},
  };
  return list;
}

std::string state(const design::Evaluation& e) {
  if (e.feasible()) return "feasible";
  if (!e.converged()) return e.termination == Termination::not_run ? "not valid: " + e.infeasibility : "not converged";
  return "infeasible: " + e.infeasibility;
}

double objective_value(const design::DesignStudy& study, const design::Evaluation& e) {
  return study.objective() == design::Objective::life ? e.shortest_life_years : e.max_stress_ratio;
}

/// A variable with its unit, from the damper number it names (its last part).
std::string variable_label(const std::string& name) {
  const std::string last = name.substr(name.find_last_of('.') + 1);
  const std::vector<std::pair<std::string_view, std::string_view>> units{
      {"mass", "kg"}, {"inertia", "kg m²"}, {"offset", "m"}, {"length", "m"}, {"position", "m"},
      {"ei", "N m²"},  {"c", "N m²"},        {"h", "N m"},    {"k0", "N"},      {"mirror_length", "m"}};
  for (const auto& [key, unit] : units) {
    if (last == key) return fmt::format("{} ({})", name, unit);
  }
  if (name == design::kPositionLoopFraction) return name + " (of the shortest loop)";
  return name;
}

/// The objective against variable d over every converged candidate; the optimum and
/// the rounded design marked.
Chart variable_chart(const DesignReportInput& in, std::size_t d) {
  const design::DesignStudy& study = *in.study;
  const bool life = study.objective() == design::Objective::life;
  Chart chart(fmt::format("{} against {}", life ? "Shortest life" : "Largest stress ratio", study.variables()[d].name),
              Axis(variable_label(study.variables()[d].name)), Axis(life ? "shortest life (years)" : "largest stress / endurance limit", life));
  Series feasible{"feasible candidates", {}, {}, LineStyle::markers, 0};
  Series infeasible{"converged, infeasible", {}, {}, LineStyle::markers, 7};
  for (const design::StudyEvaluation& s : in.result->evaluations) {
    const design::Evaluation& e = s.evaluation;
    if (!e.converged()) continue;
    Series& into = e.feasible() ? feasible : infeasible;
    into.x.push_back(e.x[d]);
    into.y.push_back(objective_value(study, e));
  }
  chart.series = {infeasible, feasible};
  if (in.result->best) {
    const design::Evaluation& best = in.result->evaluations[*in.result->best].evaluation;
    chart.series.push_back({"optimum", {best.x[d]}, {objective_value(study, best)}, LineStyle::ring, 1});
  }
  if (in.rounded && in.rounded->converged()) {
    chart.series.push_back({"rounded to build", {in.rounded->x[d]}, {objective_value(study, *in.rounded)}, LineStyle::square, 2});
  }
  if (!life) chart.references.push_back({"endurance limit", 1.0});
  return chart;
}

}  // namespace

std::string design_report(const DesignReportInput& in, const ReportContext& context) {
  const design::DesignStudy& study = *in.study;
  const design::DesignResult& result = *in.result;
  HtmlPage page({"Damper design: " + in.design_name, context.generated_at, context.command});
  const design::Evaluation& base = result.evaluations[result.base].evaluation;
  const design::Evaluation* optimum = result.best ? &result.evaluations[*result.best].evaluation : nullptr;
  const bool rounded_ok = in.rounded && in.rounded->feasible();
  const design::Evaluation* build = rounded_ok ? in.rounded : optimum;
  int converged = 0, feasible = 0;
  for (const design::StudyEvaluation& s : result.evaluations) {
    converged += s.evaluation.converged();
    feasible += s.evaluation.feasible();
  }
  if (!build) {
    page.verdict("no feasible design", fmt::format(" none of the {} candidates converged on every span within the "
                                                   "constraints.", result.evaluations.size()),
                 Tone::bad);
  } else {
    const bool safe = build->max_stress_ratio <= 1.0;
    page.verdict(safe ? "safe" : "unsafe",
                 fmt::format(" the design to build{} keeps the largest stress at {} % of the endurance limit on its "
                             "governing span {} (base design: {} %).",
                             rounded_ok ? fmt::format(" (rounded to {} significant digits)", in.round_digits) : "",
                             number(100.0 * build->max_stress_ratio, 3), study.spans()[build->span_at_max].name,
                             number(100.0 * base.max_stress_ratio, 3)),
                 safe ? Tone::good : Tone::bad);
  }
  std::vector<Fact> key{{"objective", std::string(design::objective_name(study.objective()))},
                        {"candidates", fmt::format("{}: {} converged, {} feasible", result.evaluations.size(), converged, feasible)}};
  if (build) {
    key.emplace_back("stress ratio to build", number(build->max_stress_ratio, 3));
    key.emplace_back("mass to build", number(build->total_mass, 4) + " kg");
    if (std::isfinite(build->shortest_life_years)) key.emplace_back("shortest life (comparative)", parts::years(build->shortest_life_years));
  }
  key.emplace_back("base stress ratio", number(base.max_stress_ratio, 3));
  page.key_figures(key);

  page.section("The study");
  std::vector<Fact> study_facts;
  for (const design::DesignSpan& s : study.spans()) {
    study_facts.emplace_back("span " + s.name, fmt::format("{} m at {} kN, {}", number(s.span.length()),
                                                          number(s.span.tension() / 1e3), s.span.conductor().name));
  }
  if (study.constraints().total_mass_max) study_facts.emplace_back("total mass at most", number(*study.constraints().total_mass_max) + " kg");
  if (study.constraints().messenger_curvature_max) {
    study_facts.emplace_back("messenger curvature at most", number(*study.constraints().messenger_curvature_max) + " 1/m");
  }
  for (const design::DesignTie& t : study.ties()) study_facts.emplace_back("tied", t.name + " = " + t.equals);
  study_facts.emplace_back("frequencies", fmt::format("{} per span over its wind band", study.points()));
  page.facts(study_facts);

  page.section("The design");
  std::vector<std::vector<std::string>> vars;
  for (std::size_t d = 0; d < study.variables().size(); ++d) {
    const design::DesignVariable& v = study.variables()[d];
    vars.push_back({v.name, number(v.min), number(v.max), number(base.x[d]), optimum ? number(optimum->x[d], 6) : "-",
                    in.rounded ? number(in.rounded->x[d], 6) : "-"});
  }
  page.table({"variable", "min", "max", "base", "optimum", fmt::format("to build ({} digits)", in.round_digits)}, vars);
  std::vector<std::vector<std::string>> figs;
  for (const Figure& f : figures()) {
    figs.push_back({f.label, number(f.value(base), 4), optimum ? number(f.value(*optimum), 4) : "-",
                    in.rounded && in.rounded->converged() ? number(f.value(*in.rounded), 4) : "-"});
  }
  figs.push_back({"state", state(base), optimum ? state(*optimum) : "-", in.rounded ? state(*in.rounded) : "-"});
  page.table({"figure", "base", "optimum", "rounded to build"}, figs);
  if (build) {
    std::vector<std::vector<std::string>> spans;
    std::vector<Tone> tones;
    for (std::size_t k = 0; k < build->spans.size(); ++k) {
      const design::SpanFigures& f = build->spans[k];
      const auto position = study.position_on(k, build->x);
      spans.push_back({study.spans()[k].name, position ? number(*position, 3) : "-", number(f.max_stress / 1e6, 3),
                       f.governing_place.empty() ? "-" : f.governing_place, number(f.undamped_max_stress / 1e6, 3),
                       number(100.0 * f.max_stress_ratio, 3),
                       std::isnan(f.life_years) ? "-" : parts::years(f.life_years),
                       f.worse_than_undamped() ? "WORSE than undamped" : k == build->span_at_max ? "governs" : ""});
      tones.push_back(f.max_stress_ratio <= 1.0 ? Tone::good : Tone::bad);
    }
    page.table({"span", "dampers from (m)", "max (MPa)", "at", "undamped max (MPa)", "of the limit (%)", "life", "note"},
               spans, tones);
  }

  page.section("Figures");
  for (std::size_t d = 0; d < study.variables().size(); ++d) {
    page.figure(svg(variable_chart(in, d)), "The objective of every converged candidate against this variable (the "
                                            "others vary too); the optimum and the design to build marked.");
  }
  for (std::size_t k = 0; k < in.best_spans.size(); ++k) {
    const span::SpanAnalysis& a = in.best_spans[k].analysis;
    const span::BalanceSummary& m = a.balance.summary;
    page.figure(svg(parts::span_stress_chart(
                    a, fmt::format("The design to build on {}: {}, max {} at {} Hz", study.spans()[k].name,
                                   span::verdict_name(m.verdict), parts::megapascal(m.max_stress_fymax),
                                   number(m.max_stress_frequency_hz, 3)))),
                "The fymax stress of the design to build on this span, with and without it, against the endurance limit.");
  }
  page.section("Assumptions");
  std::vector<std::string> caveats = parts::span_caveats(std::isfinite(base.shortest_life_years) || study.objective() == design::Objective::life);
  caveats.push_back("The search samples the variables' box, then polishes the best candidates locally (COBYLA); it finds a "
                    "good design, not a proven global optimum.");
  page.list(caveats);
  page.section("Warnings");
  std::vector<std::string> warnings = context.warnings;
  if (converged < static_cast<int>(result.evaluations.size())) {
    warnings.push_back(fmt::format("{} of {} candidates did not converge on every span or could not be built (the design "
                                   "CSV's converged column); none of them enters the ranking.",
                                   result.evaluations.size() - converged, result.evaluations.size()));
  }
  if (in.rounded && !rounded_ok) {
    warnings.push_back("the optimum rounded to build is not feasible (" + state(*in.rounded) + "): the damper file gives the "
                       "optimum's own values");
  }
  for (const requests::SpanResult& s : in.best_spans) {
    for (const std::string& f : parts::span_failures(s.analysis)) warnings.push_back("the design to build: " + f);
  }
  page.list(warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
