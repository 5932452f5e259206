#include "stockbridge/requests/design_request.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_writer.hpp"
#include "stockbridge/io/damper_file.hpp"

namespace stockbridge::requests {

void validate(const DesignRequest& request) {
  if (request.samples) require_in_range("samples", *request.samples, 1, 1000000);
  if (request.polish) require_in_range("polish", *request.polish, 0, 10000);
  require_in_range("threads", request.threads, 1, 256);
}

design::SearchOptions search_options(const design::SearchOptions& file, const DesignRequest& request) {
  validate(request);
  design::SearchOptions options = file;
  if (request.samples) options.samples = *request.samples;
  if (request.polish) options.polish = *request.polish;
  return options;
}

namespace {

constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

/// The objective as reported: the stress ratio, or the shortest life in years.
double reported_objective(const design::DesignStudy& study, const design::Evaluation& e) {
  if (!e.converged()) return kNotComputed;
  return study.objective() == design::Objective::life ? e.shortest_life_years : e.max_stress_ratio;
}

io::JsonObject design_figures(const design::DesignStudy& study, const design::Evaluation& e) {
  io::JsonObject variables;
  for (std::size_t d = 0; d < study.variables().size(); ++d) variables.add(study.variables()[d].name, e.x[d]);
  io::JsonObject o;
  o.add("objective", reported_objective(study, e))
      .add("max_stress_ratio", e.max_stress_ratio)
      .add("max_stress_mpa", e.max_stress / 1e6)
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
  if (!e.converged() && e.termination != Termination::not_run) {
    o.add("termination", termination_name(e.termination)).add("note", e.failure);
  } else if (!e.infeasibility.empty()) {
    o.add("note", e.infeasibility);
  }
  return o;
}

}  // namespace

std::vector<std::string> design_columns(const design::DesignStudy& study) {
  std::vector<std::string> columns{"run"};
  for (const design::DesignVariable& v : study.variables()) columns.push_back(v.name);
  for (const char* name : {"objective", "max_stress_ratio", "max_stress_mpa", "frequency_at_max_hz", "total_mass_kg",
                           "messenger_curvature_max_per_m", "shortest_life_years", "converged", "feasible"}) {
    columns.emplace_back(name);
  }
  return columns;
}

std::vector<double> design_row(const design::DesignStudy& study, const design::StudyEvaluation& evaluation) {
  const design::Evaluation& e = evaluation.evaluation;
  std::vector<double> row{static_cast<double>(evaluation.run)};
  row.insert(row.end(), e.x.begin(), e.x.end());
  const bool c = e.converged();
  for (const double v : {reported_objective(study, e), c ? e.max_stress_ratio : kNotComputed, c ? e.max_stress / 1e6 : kNotComputed,
                         c ? e.frequency_at_max_hz : kNotComputed, e.total_mass, c ? e.messenger_curvature_max : kNotComputed,
                         c ? e.shortest_life_years : kNotComputed, c ? 1.0 : 0.0, e.feasible() ? 1.0 : 0.0}) {
    row.push_back(v);
  }
  return row;
}

std::string design_csv(const design::DesignStudy& study, const design::DesignResult& result) {
  std::vector<std::string> header{std::string(kDesignStageColumn)};
  for (std::string& c : design_columns(study)) header.push_back(std::move(c));
  io::CsvWriter csv(header);
  for (const design::StudyEvaluation& e : result.evaluations) {
    const std::vector<std::string> label{std::string(design::stage_name(e.stage))};
    csv.add_row(label, design_row(study, e));
  }
  return csv.text();
}

io::JsonObject design_summary(const design::DesignStudy& study, const design::DesignResult& result) {
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
  o.add("polishes", polishes);
  return o;
}

std::optional<std::string> best_damper_file(const design::DesignStudy& study, const design::DesignResult& result,
                                            std::string_view design_file) {
  if (!result.best) return std::nullopt;
  const design::Evaluation& best = result.evaluations[*result.best].evaluation;
  const design::Evaluation& base = result.evaluations[result.base].evaluation;
  std::string comment = fmt::format("The best design of {} (stockbridge design), {} {} (base {}).", design_file,
                                    design::objective_name(study.objective()), reported_objective(study, best),
                                    reported_objective(study, base));
  if (const auto position = study.position_of(best.x)) {
    comment += fmt::format("\nposition = {} m from the span clamp: place the spans' dampers there", *position);
  }
  for (std::size_t d = 0; d < study.variables().size(); ++d) {
    comment += fmt::format("\n{} = {}", study.variables()[d].name, best.x[d]);
  }
  return io::damper_file_toml(study.damper_of(best.x), comment);
}

}  // namespace stockbridge::requests
