#include "stockbridge/requests/design_request.hpp"

#include <algorithm>
#include <cctype>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "record_text.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/damper_file.hpp"

namespace stockbridge::requests {

void validate(const DesignRequest& request) {
  if (request.samples) require_in_range("samples", *request.samples, 1, 1000000);
  if (request.polish) require_in_range("polish", *request.polish, 0, 10000);
  require_in_range("threads", request.threads, 1, 256);
  require_in_range("round_digits", request.round_digits, 1, 15);
}

design::SearchOptions search_options(const design::SearchOptions& file, const DesignRequest& request) {
  validate(request);
  design::SearchOptions options = file;
  if (request.samples) options.samples = *request.samples;
  if (request.polish) options.polish = *request.polish;
  return options;
}

namespace {

/// The objective as reported: the stress ratio, or the shortest life in years.
double reported_objective(design::Objective objective, const design::Evaluation& e) {
  if (!e.converged()) return kNoValue;
  return objective == design::Objective::life ? e.shortest_life_years : e.max_stress_ratio;
}

io::JsonObject design_figures(const design::DesignStudy& study, const design::Evaluation& e) {
  io::JsonObject variables;
  for (std::size_t d = 0; d < study.variables().size(); ++d) variables.add(study.variables()[d].name, e.x[d]);
  io::JsonObject o;
  o.add("objective", reported_objective(study.objective(), e))
      .add("max_stress_ratio", e.max_stress_ratio)
      .add("max_stress_mpa", megapascal_of(e.max_stress))
      .add("frequency_at_max_hz", e.frequency_at_max_hz)
      .add("total_mass_kg", e.total_mass)
      .add("messenger_curvature_max_per_m", e.messenger_curvature_max)
      .add("shortest_life_years", e.shortest_life_years)
      .add("feasible", e.feasible());
  if (const auto position = study.position_of(e.x)) {
    o.add("position_m", *position);
  } else {
    o.add_null("position_m");
  }
  o.add("variables", variables);
  if (e.converged()) {
    std::vector<io::JsonObject> spans;
    std::vector<std::string> worse;
    for (std::size_t k = 0; k < e.spans.size(); ++k) {
      const design::SpanFigures& f = e.spans[k];
      const std::string& name = study.spans()[k].name;
      spans.push_back(io::JsonObject()
                          .add("span", name)
                          .add("stress_ratio", f.max_stress_ratio)
                          .add("max_stress_mpa", megapascal_of(f.max_stress))
                          .add("undamped_max_stress_mpa", megapascal_of(f.undamped_max_stress))
                          .add("life_years", f.life_years)
                          .add("governing_place", f.governing_place)
                          .add("worse_than_undamped", f.worse_than_undamped()));
      if (f.worse_than_undamped()) worse.push_back(name);
    }
    o.add("governing_span", study.spans().at(e.span_at_max).name)
        .add("governing_place", e.place_at_max)
        .add("spans", spans)
        .add("spans_worse_than_undamped", worse);
  }
  if (!e.converged() && e.termination != Termination::not_run) {
    o.add("termination", termination_name(e.termination)).add("note", e.failure);
  } else if (!e.infeasibility.empty()) {
    o.add("note", e.infeasibility);
  }
  return o;
}

}  // namespace

namespace {

using DesignQuantity = Quantity<design::StudyEvaluation>;

/// A figure of a converged candidate (NaN otherwise).
DesignQuantity design_figure(std::string name, std::string unit, std::string meaning,
                             double (*value)(const design::Evaluation&)) {
  return {std::move(name), std::move(unit), std::move(meaning), ColumnKind::number,
          [value](const design::StudyEvaluation& s, std::size_t) {
            return s.evaluation.converged() ? value(s.evaluation) : kNoValue;
          },
          {}};
}

}  // namespace

namespace {

/// The per-span columns' prefixes: the spans' names where every one is unique and
/// made of letters, digits and '_', else span1, span2, ...
std::vector<std::string> design_span_prefixes(const design::DesignStudy& study) {
  std::vector<std::string> names;
  bool usable = true;
  for (const design::DesignSpan& s : study.spans()) {
    usable = usable && !s.name.empty() && std::all_of(s.name.begin(), s.name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    usable = usable && std::find(names.begin(), names.end(), s.name) == names.end();
    names.push_back(s.name);
  }
  if (!usable) {
    for (std::size_t k = 0; k < names.size(); ++k) names[k] = fmt::format("span{}", k + 1);
  }
  return names;
}

double span_figure(const design::Evaluation& e, std::size_t k, double design::SpanFigures::*member) {
  return k < e.spans.size() ? e.spans[k].*member : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

Table<design::StudyEvaluation> design_table(const design::DesignStudy& study) {
  using S = design::StudyEvaluation;
  using E = design::Evaluation;
  using F = design::SpanFigures;
  const design::Objective objective = study.objective();
  std::vector<std::string> variables;
  for (const design::DesignVariable& v : study.variables()) variables.push_back(v.name);
  std::vector<std::string> span_names;
  for (const design::DesignSpan& s : study.spans()) span_names.push_back(s.name);
  return Table<S>(
      {
          {"stage", "", "`base`, `sample` or `polish`", ColumnKind::label, {},
           [](const S& s, std::size_t) { return std::string(design::stage_name(s.stage)); }},
          {"governing_span", "", "the span of the largest stress ratio (empty unless converged)", ColumnKind::label, {},
           [span_names](const S& s, std::size_t) {
             return s.evaluation.converged() ? span_names.at(s.evaluation.span_at_max) : std::string();
           }},
          {"governing_place", "",
           "where on that span the largest stress lies: span clamp 1, span clamp 2 or a mass's clamp (sphere at 120 m)",
           ColumnKind::label, {},
           [](const S& s, std::size_t) { return s.evaluation.converged() ? s.evaluation.place_at_max : std::string(); }},
          {"run", "", "the sample's index, or the polish's (0 for the base)", ColumnKind::count,
           [](const S& s, std::size_t) { return static_cast<double>(s.run); }, {}},
          {"<variable>", "as the damper file", "each variable by its name (`arm.left.mass`, `position`): the candidate",
           ColumnKind::number, [](const S& s, std::size_t d) { return s.evaluation.x[d]; }, {}},
          {"objective", "", "`max_stress_ratio` (objective `max_stress`) or `shortest_life_years` (`life`)",
           ColumnKind::number,
           [objective](const S& s, std::size_t) { return reported_objective(objective, s.evaluation); },
           {}},
          design_figure("max_stress_ratio", "", "largest fymax stress / endurance limit over the spans and bands",
                        [](const E& e) { return e.max_stress_ratio; }),
          design_figure("max_stress_mpa", "MPa", "that largest stress",
                        [](const E& e) { return megapascal_of(e.max_stress); }),
          design_figure("frequency_at_max_hz", "Hz", "where the ratio is largest",
                        [](const E& e) { return e.frequency_at_max_hz; }),
          {"total_mass_kg", "kg", "clamp and arms", ColumnKind::number,
           [](const S& s, std::size_t) { return s.evaluation.total_mass; }, {}},
          design_figure("messenger_curvature_max_per_m", "1/m",
                        "largest clamp-section curvature amplitude of the arms",
                        [](const E& e) { return e.messenger_curvature_max; }),
          design_figure("shortest_life_years", "years", "objective `life` only",
                        [](const E& e) { return e.shortest_life_years; }),
          {"converged", "", "1 when every point of every span balanced", ColumnKind::flag,
           [](const S& s, std::size_t) { return s.evaluation.converged() ? 1.0 : 0.0; }, {}},
          {"feasible", "", "1 when converged and within the constraints", ColumnKind::flag,
           [](const S& s, std::size_t) { return s.evaluation.feasible() ? 1.0 : 0.0; }, {}},
          {"<span>_stress_ratio", "", "each span's largest fymax stress / its endurance limit", ColumnKind::number,
           [](const S& s, std::size_t k) { return span_figure(s.evaluation, k, &F::max_stress_ratio); }, {}},
          {"<span>_max_stress_mpa", "MPa", "each span's largest fymax stress", ColumnKind::number,
           [](const S& s, std::size_t k) { return megapascal_of(span_figure(s.evaluation, k, &F::max_stress)); }, {}},
          {"<span>_undamped_max_stress_mpa", "MPa", "the same span's without dampers", ColumnKind::number,
           [](const S& s, std::size_t k) {
             return megapascal_of(span_figure(s.evaluation, k, &F::undamped_max_stress));
           }, {}},
          {"<span>_life_years", "years", "each span's life (with its climate)", ColumnKind::number,
           [](const S& s, std::size_t k) { return span_figure(s.evaluation, k, &F::life_years); }, {}},
          {"<span>_worse_than_undamped", "", "1 where the candidate raises the span's largest stress above its undamped one",
           ColumnKind::flag,
           [](const S& s, std::size_t k) {
             return k < s.evaluation.spans.size() ? (s.evaluation.spans[k].worse_than_undamped() ? 1.0 : 0.0)
                                                   : std::numeric_limits<double>::quiet_NaN();
           },
           {}},
      },
      {{"<variable>", variables}, {"<span>", design_span_prefixes(study)}});
}

io::JsonObject design_summary(const design::DesignStudy& study, const design::DesignResult& result,
                              const DesignRun& run) {
  int converged = 0, feasible = 0;
  for (const design::StudyEvaluation& e : result.evaluations) {
    converged += e.evaluation.converged() ? 1 : 0;
    feasible += e.evaluation.feasible() ? 1 : 0;
  }
  std::vector<io::JsonObject> polishes;
  for (const SolverSummary& p : result.polishes) {
    polishes.push_back(io::JsonObject()
                           .add("termination", termination_name(p.termination))
                           .add("evaluations", p.evaluations)
                           .add("reason", p.converged() ? std::string() : brief_report(p)));
  }
  io::JsonObject o;
  o.add("objective", design::objective_name(study.objective()))
      .add("evaluations", static_cast<int>(result.evaluations.size()))
      .add("converged", converged)
      .add("feasible", feasible)
      .add("base", design_figures(study, result.evaluations[result.base].evaluation));
  if (result.best) {
    const design::Evaluation& best = result.evaluations[*result.best].evaluation;
    o.add("best", design_figures(study, best))
        .add("best_stage", design::stage_name(result.evaluations[*result.best].stage))
        .add("improved", design::better(best, result.evaluations[result.base].evaluation));
  } else {
    o.add_null("best").add("improved", false);
  }
  if (run.rounded) {
    o.add("rounded", design_figures(study, *run.rounded));
  } else {
    o.add_null("rounded");
  }
  o.add("polishes", polishes)
      .add("samples", run.samples)
      .add("polish", run.polish)
      .add("ranks", run.ranks)
      .add("threads", run.threads)
      .add("round_digits", run.round_digits);
  return o;
}

std::optional<design::Evaluation> rounded_best(const design::DesignStudy& study, const design::DesignResult& result,
                                               int digits) {
  if (!result.best) return std::nullopt;
  return design::evaluate(study, design::rounded_candidate(study, result.evaluations[*result.best].evaluation.x, digits));
}

std::optional<std::string> best_damper_file(const design::DesignStudy& study, const design::DesignResult& result,
                                            std::string_view design_file, const design::Evaluation* rounded) {
  if (!result.best) return std::nullopt;
  const design::Evaluation& optimum = result.evaluations[*result.best].evaluation;
  const bool built = rounded && rounded->feasible();
  const design::Evaluation& best = built ? *rounded : optimum;
  const design::Evaluation& base = result.evaluations[result.base].evaluation;
  std::string comment = fmt::format("The best design of {} (stockbridge design){}, {} {} (base {}).", design_file,
                                    built ? ", rounded to build" : "",
                                    design::objective_name(study.objective()), reported_objective(study.objective(), best),
                                    reported_objective(study.objective(), base));
  if (const auto position = study.position_of(best.x)) {
    comment += fmt::format("\nposition = {} m from the span clamp: place the spans' dampers there", *position);
  } else if (study.position_on(0, best.x)) {
    comment += "\nthe first damper's position on each span (a fraction of its shortest loop):";
    for (std::size_t k = 0; k < study.spans().size(); ++k) {
      comment += fmt::format("\n  {}: {:.3g} m", study.spans()[k].name, *study.position_on(k, best.x));
    }
  }
  for (std::size_t d = 0; d < study.variables().size(); ++d) {
    comment += fmt::format("\n{} = {}", study.variables()[d].name, best.x[d]);
  }
  if (built) {
    comment += fmt::format("\nThese are the optimum's values rounded to build; the optimum itself, {} {}:",
                           design::objective_name(study.objective()), reported_objective(study.objective(), optimum));
    for (std::size_t d = 0; d < study.variables().size(); ++d) {
      comment += fmt::format("\n  {} = {}", study.variables()[d].name, optimum.x[d]);
    }
  } else if (rounded) {
    comment += fmt::format("\nThe optimum rounded to build is not feasible ({}): these are the optimum's own values.",
                           rounded->converged() ? rounded->infeasibility : rounded->failure);
  }
  return io::damper_file_toml(study.damper_of(best.x), comment);
}

namespace {

/// candidate-v2: the governing place added (the study's and each span's). A record of
/// an earlier tag is not a candidate record (the candidate is evaluated again).
constexpr std::string_view kEvaluationTag = "candidate-v2";

}  // namespace

std::string evaluation_record(const design::Evaluation& e) {
  using record_text::escaped;
  std::string out = fmt::format("{}\t{}", kEvaluationTag, e.x.size());
  for (const double v : e.x) out += fmt::format("\t{}", v);
  out += fmt::format("\t{}", static_cast<int>(e.termination));
  for (const double v : {e.objective, e.max_stress_ratio, e.max_stress, e.frequency_at_max_hz, e.total_mass,
                         e.messenger_curvature_max, e.shortest_life_years}) {
    out += fmt::format("\t{}", v);
  }
  out += fmt::format("\t{}\t", e.span_at_max);
  out += escaped(e.place_at_max);
  out += fmt::format("\t{}", e.spans.size());
  for (const design::SpanFigures& f : e.spans) {
    out += fmt::format("\t{}\t{}\t{}\t{}\t", f.max_stress_ratio, f.max_stress, f.undamped_max_stress, f.life_years);
    out += escaped(f.governing_place);
  }
  out += '\t';
  out += escaped(e.failure);
  out += '\t';
  out += escaped(e.infeasibility);
  out += "\tend";
  return out;
}

design::Evaluation parse_evaluation_record(std::string_view record) {
  record_text::RecordFields f(record);
  if (f.text() != kEvaluationTag) record_text::bad_record("not a candidate record");
  design::Evaluation e;
  const long long n = f.integer();
  if (n < 0 || n > 1000) record_text::bad_record("a count of variables out of range");
  for (long long k = 0; k < n; ++k) e.x.push_back(f.number());
  const long long termination = f.integer();
  if (termination < 0 || termination > static_cast<long long>(Termination::no_root)) {
    record_text::bad_record("a termination out of range");
  }
  e.termination = static_cast<Termination>(termination);
  for (double* v : {&e.objective, &e.max_stress_ratio, &e.max_stress, &e.frequency_at_max_hz, &e.total_mass,
                    &e.messenger_curvature_max, &e.shortest_life_years}) {
    *v = f.number();
  }
  e.span_at_max = static_cast<std::size_t>(f.integer());
  e.place_at_max = f.text();
  const long long spans = f.integer();
  if (spans < 0 || spans > 100000) record_text::bad_record("a count of spans out of range");
  e.spans.resize(static_cast<std::size_t>(spans));
  for (design::SpanFigures& s : e.spans) {
    for (double* v : {&s.max_stress_ratio, &s.max_stress, &s.undamped_max_stress, &s.life_years}) *v = f.number();
    s.governing_place = f.text();
  }
  e.failure = f.text();
  e.infeasibility = f.text();
  if (f.text() != "end" || !f.done()) record_text::bad_record("no end mark");
  return e;
}

std::string design_fingerprint(const std::vector<std::filesystem::path>& inputs, std::string_view design_text) {
  return record_text::input_fingerprint(design_text, inputs);
}

}  // namespace stockbridge::requests
