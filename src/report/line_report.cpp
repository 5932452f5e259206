#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/reports.hpp"

namespace stockbridge::report {

namespace {

std::string arrangement(const line::ScheduleRow& r) {
  return r.per_end == 0 ? std::string("none") : fmt::format("{} × {}", r.per_end, r.damper_type);
}

std::string positions(const line::ScheduleRow& r) {
  std::string out;
  for (const double x : r.positions) out += (out.empty() ? "" : "; ") + parts::number(x, 4);
  return out.empty() ? "-" : out;
}

/// The dampers beside the span's masses: "8 beside masses at 1.5 m" ("-": none).
std::string beside_masses(const line::ScheduleRow& r) {
  return r.sphere_dampers > 0
             ? fmt::format("{} beside masses at {} m", r.sphere_dampers, parts::number(r.sphere_distance, 4))
             : "-";
}

/// The span's terrain category and whether its H/w is within CIGRE TB 273's limit for it: "4, within".
std::string terrain_cell(const line::ScheduleRow& r) {
  if (r.terrain <= 0) return "-";
  if (r.terrain_within < 0) return std::to_string(r.terrain);
  return fmt::format("{}, {}", r.terrain, r.terrain_within == 1 ? "within" : "above");
}

/// A stress of a balance that did not converge throughout is not shown.
std::string stress_cell(double pascal, bool trusted) { return trusted ? parts::number(pascal / 1e6, 3) : "-"; }

std::vector<Fact> line_rules(const io::LineFile& file) {
  const line::ScheduleRules& r = file.line.rules();
  std::vector<Fact> out;
  for (const line::DamperType& t : file.line.types()) {
    out.emplace_back("damper type " + t.name,
                     fmt::format("{}{}{}", t.mass ? parts::number(*t.mass, 4) + " kg each" : "mass not given",
                                 t.price ? ", price " + parts::number(*t.price, 6) : "",
                                 t.damper.measured() ? ", from a measured impedance sheet"
                                 : t.damper.fit      ? ", its model " + t.damper.fit->summary()
                                                     : ", from its model"));
  }
  out.emplace_back("dampers per end", fmt::format("{} to {}", r.min_per_end, r.max_per_end));
  out.emplace_back("positions", fmt::format("{} to {} m from the clamp, at least {} m apart, on a {} mm step",
                                            parts::number(r.positions.position_min), parts::number(r.positions.position_max),
                                            parts::number(r.positions.spacing_min), parts::number(1e3 * r.position_step)));
  const bool masses = std::any_of(file.line.spans().begin(), file.line.spans().end(),
                                  [](const line::LineSpan& s) { return !s.span.masses().empty(); });
  if (masses) {
    out.emplace_back("dampers beside masses",
                     r.sphere_dampers == line::SphereDampers::none
                         ? std::string("none")
                         : fmt::format("one on either side of each mass along a span, {} to {} m from it (the best "
                                       "of the least, the middle and the most, each with its own end positions)",
                                       parts::number(r.sphere_distance_min), parts::number(r.sphere_distance_max)));
  }
  out.emplace_back("objective", r.positions.objective == span::PositionObjective::life ? "the shortest life (damage per year)"
                                                                                       : "the largest fymax stress");
  const span::Span& first = file.line.spans().front().span;
  out.emplace_back("criterion", fmt::format("{}: {}", span::fatigue_criterion_name(first.fatigue().criterion),
                                            first.criterion_description()));
  out.emplace_back("safe", (r.life_target ? fmt::format("every point converged and a life of at least {} years (comparative)",
                                                        parts::number(*r.life_target))
                                          : std::string("every point converged and every judged stress within the "
                                                        "endurance limit")) +
                               (r.accept_uncertain ? "; uncertain (a sheet's band above the limit) accepted"
                                                   : "; uncertain (a sheet's band above the limit) is not safe"));
  out.emplace_back("damper type chosen", fmt::format("{} (among the types safe with the fewest dampers)",
                                                     line::type_choice_name(r.choose)));
  out.emplace_back("no dampers where",
                   r.undamped_rule == line::UndampedRule::tb273
                       ? "the span's balance without dampers is safe, or its H/w is within CIGRE TB 273's limit for its terrain"
                       : "the span's balance without dampers is safe");
  out.emplace_back("frequencies", fmt::format("{} per balance over each span's wind band ({} in the position search)", r.points,
                                              r.search_points));
  return out;
}

Chart ratio_chart(const std::vector<line::ScheduleRow>& rows) {
  Chart chart("Largest stress over the endurance limit, span by span", Axis("span"),
              Axis("largest judged stress / endurance limit", true));
  Series damped{"with the scheduled dampers", {}, {}, LineStyle::markers, 0};
  Series undamped{"without dampers", {}, {}, LineStyle::markers, 1};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const line::ScheduleRow& r = rows[i];
    chart.x_categories.push_back(r.id);
    const bool trusted = r.converged == r.points;
    damped.x.push_back(static_cast<double>(i));
    damped.y.push_back(trusted && r.per_end > 0 ? r.stress_ratio() : NAN);
    undamped.x.push_back(static_cast<double>(i));
    undamped.y.push_back(r.undamped_max_stress / r.endurance_limit);
  }
  chart.series = {undamped, damped};
  chart.references.push_back({"endurance limit", 1.0});
  return chart;
}

Chart dampers_chart(const std::vector<line::ScheduleRow>& rows) {
  Chart chart("Dampers per end, span by span", Axis("span"), Axis("dampers per end"));
  Series s{"", {}, {}, LineStyle::markers, 0};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    chart.x_categories.push_back(rows[i].id);
    s.x.push_back(static_cast<double>(i));
    s.y.push_back(rows[i].per_end);
  }
  chart.series = {s};
  chart.y.min = 0.0;
  chart.y.integer = true;
  return chart;
}

}  // namespace

std::string line_report(const io::LineFile& file, const requests::LineSchedule& schedule, const ReportContext& context) {
  HtmlPage page({"Damper schedule: line " + file.name, context.generated_at, context.command});
  const std::vector<line::ScheduleRow>& rows = schedule.rows;
  const line::ScheduleCounts counts = line::schedule_counts(rows);
  const std::vector<line::BillLine>& bill = schedule.bill;
  int dampers = 0;
  double mass = 0.0;
  bool mass_known = true;
  for (const line::BillLine& b : bill) {
    dampers += b.dampers;
    mass += b.mass.value_or(0.0);
    mass_known = mass_known && b.mass.has_value();
  }
  const Tone tone = counts.unsafe > 0 ? Tone::bad : counts.unknown + counts.uncertain > 0 ? Tone::unknown : Tone::good;
  page.verdict(counts.unsafe > 0 ? "unsafe spans" : counts.unknown > 0 ? "incomplete"
                                                  : counts.uncertain > 0 ? "uncertain spans" : "safe",
               fmt::format(" {} spans: {} safe, {} unsafe even with the most dampers allowed, {} unknown (not converged "
                           "throughout), {} uncertain (a measured sheet's band reaches above the limit); {} dampers in "
                           "all.",
                           rows.size(), counts.safe, counts.unsafe, counts.unknown, counts.uncertain, dampers),
               tone);
  std::vector<Fact> key{{"spans", std::to_string(rows.size())},
                        {"safe / unsafe / unknown / uncertain",
                         fmt::format("{} / {} / {} / {}", counts.safe, counts.unsafe, counts.unknown, counts.uncertain)},
                        {"dampers", std::to_string(dampers)},
                        {"damper mass", mass_known ? parts::number(mass, 4) + " kg" : "not known for every type"}};
  if (counts.governing) {
    const std::string& place = counts.governing->governing_place;
    key.emplace_back("governing span", fmt::format("{}: {} % of the limit{}", counts.governing->id,
                                                   parts::number(100.0 * counts.governing->stress_ratio(), 3),
                                                   place.empty() ? "" : " (" + place + ")"));
  }
  for (const auto& [n, spans] : counts.per_end) key.emplace_back(fmt::format("spans with {} per end", n), std::to_string(spans));
  if (counts.worse_than_undamped > 0) key.emplace_back("spans worse than undamped", std::to_string(counts.worse_than_undamped));
  page.key_figures(key);

  page.section("Rules");
  page.facts(line_rules(file));
  page.section("Figures");
  page.figure(svg(ratio_chart(rows)), "Each span's largest judged stress (at its clamps and its masses' clamps) over its "
                                      "endurance limit, without dampers and with the scheduled ones; below 1 is within the "
                                      "limit (the margin is 1 minus it). A span not converged throughout has no damped mark.");
  page.figure(svg(dampers_chart(rows)), "The dampers each span gets at each end.");
  page.section("Schedule");
  // A band column only where a span's dampers come from a measured sheet; terrain and TB 273's judgement share one
  // (the page must fit an A4 print).
  const bool any_band =
      std::any_of(rows.begin(), rows.end(), [](const line::ScheduleRow& r) { return std::isfinite(r.max_stress_high); });
  // Where a span has masses: the dampers beside them with the span's dampers per end, and where the largest stress
  // lies with it (no columns of their own: the page must fit an A4 print).
  const bool any_masses = std::any_of(rows.begin(), rows.end(), [](const line::ScheduleRow& r) {
    return r.sphere_dampers > 0 || (!r.governing_place.empty() && !r.governing_place.starts_with("span clamp"));
  });
  std::vector<std::vector<std::string>> table;
  std::vector<Tone> tones;
  for (const line::ScheduleRow& r : rows) {
    const bool trusted = r.converged == r.points;
    const std::string dampers = r.sphere_dampers > 0 ? arrangement(r) + "; " + beside_masses(r) : arrangement(r);
    std::vector<std::string> cells{r.id, parts::number(r.length), parts::number(100.0 * r.tension_fraction, 3),
                                   parts::number(r.catenary_parameter), terrain_cell(r), dampers, positions(r)};
    cells.push_back(parts::number(r.undamped_max_stress / 1e6, 3));
    std::string max = r.per_end > 0 || r.sphere_dampers > 0 ? stress_cell(r.max_stress, trusted) : "-";
    if (any_masses && trusted && !r.governing_place.empty() && max != "-") max += " at " + r.governing_place;
    cells.push_back(std::move(max));
    if (any_band)
      cells.push_back(std::isfinite(r.max_stress_high) && trusted ? parts::number(r.max_stress_high / 1e6, 3) : "-");
    cells.push_back(trusted ? parts::number(100.0 * (1.0 - r.stress_ratio()), 3) : "-");
    cells.push_back(std::isnan(r.life_years) ? "-" : std::isinf(r.life_years) ? "unlimited" : parts::number(r.life_years, 3));
    cells.emplace_back(span::verdict_name(r.verdict));
    table.push_back(std::move(cells));
    tones.push_back(parts::verdict_tone(r.verdict));
  }
  std::vector<std::string> header{"span", "length (m)", "tension (% RTS)", "H/w (m)", "terrain (TB 273)", "dampers per end",
                                  "positions (m)"};
  header.emplace_back("undamped max (MPa)");
  header.emplace_back("max (MPa)");
  if (any_band) header.emplace_back("band top (MPa)");
  for (const char* name : {"margin (%)", "life (years)", "verdict"}) header.emplace_back(name);
  page.table(header, table, tones);
  page.section("Bill of materials");
  std::vector<std::vector<std::string>> bill_rows;
  for (const line::BillLine& b : bill) {
    bill_rows.push_back({b.damper_type, std::to_string(b.dampers), std::to_string(b.spans),
                         b.mass ? parts::number(*b.mass, 4) : "-", b.price ? parts::number(*b.price, 6) : "-"});
  }
  page.table({"damper type", "dampers", "spans", "mass (kg)", "price"}, bill_rows);
  page.section("Assumptions");
  bool lives = false;
  for (const line::ScheduleRow& r : rows) lives = lives || !std::isnan(r.life_years) || !std::isnan(r.undamped_life_years);
  std::vector<std::string> caveats = parts::span_caveats(lives);
  caveats.push_back("Each span is scheduled alone, its ends clamped (no suspension-point coupling with its neighbours); "
                    "positions are the same at both ends, measured from the clamp.");
  page.list(caveats);
  page.section("Warnings");
  std::vector<std::string> warnings = context.warnings;
  for (const std::string& w : line::grouped_warnings(rows)) warnings.push_back(w);
  page.list(warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
