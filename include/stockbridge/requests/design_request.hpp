#pragma once
// The request layer for the design search (`stockbridge design`, Python's design):
// the study's evaluations as the rows every front end shows (CSV columns, Python
// arrays), the summary (the --json keys), and the best design as a damper file.

#include <filesystem>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include "stockbridge/design/search.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

/// What a user changes of a design file's settings from the command line.
struct DesignRequest {
  std::optional<int> samples;  ///< instead of the file's
  std::optional<int> polish;   ///< instead of the file's
  int threads = 1;             ///< candidates evaluated at once (per process)
  /// The best design is also given rounded to this many significant digits (what is
  /// built) and evaluated again there (design::rounded_candidate).
  int round_digits = 3;
};

/// InvalidParameter naming "samples", "polish", "threads" or "round_digits" (the command's
/// --samples, --polish and --threads, Python's keywords), as the other requests
/// name their settings.
void validate(const DesignRequest& request);
/// The file's search options with the request's changes.
design::SearchOptions search_options(const design::SearchOptions& file, const DesignRequest& request);

/// The design CSV's quantities, a row per candidate evaluated: stage (base, sample
/// or polish), run, <each variable by its name>, objective, max_stress_ratio,
/// max_stress_mpa, frequency_at_max_hz, total_mass_kg,
/// messenger_curvature_max_per_m, shortest_life_years (NaN where not converged),
/// converged, feasible. objective: max_stress_ratio (objective max_stress) or
/// shortest_life_years (life).
Table<design::StudyEvaluation> design_table(const design::DesignStudy& study);

/// How the search was run, as the summary reports it beside the result.
struct DesignRun {
  int samples = 0;
  int polish = 0;
  int ranks = 1;    ///< processes
  int threads = 1;  ///< per process
  int round_digits = 3;
  /// The best design rounded to round_digits and evaluated again (none: not made).
  const design::Evaluation* rounded = nullptr;
};

/// The best design rounded to `digits` significant digits and evaluated again (one
/// thread); none when nothing is feasible.
std::optional<design::Evaluation> rounded_best(const design::DesignStudy& study, const design::DesignResult& result,
                                               int digits);

/// The summary, as `stockbridge design --json` prints it and Python returns it:
/// objective, evaluations, converged, feasible, base and best (each: objective,
/// max_stress_ratio, max_stress_mpa, frequency_at_max_hz, total_mass_kg,
/// messenger_curvature_max_per_m, shortest_life_years, position_m, variables
/// {name: value}, and for a candidate that is not feasible its termination and a
/// note; best null when nothing is feasible), improved, polishes (each local
/// polish's termination, evaluations and reason), samples, polish, ranks, threads,
/// round_digits and rounded (the best design rounded and evaluated again, its
/// figures as best's; null where not made).
io::JsonObject design_summary(const design::DesignStudy& study, const design::DesignResult& result,
                              const DesignRun& run);

/// The best design as a complete damper file (the `impedance` and `span` commands
/// read it), its position and figures in comments; none when nothing is feasible.
/// With `rounded` (rounded_best) and that design feasible, the file is the rounded
/// design (what is built), the optimum's values and figures beside it in comments.
/// A candidate's evaluation as one line of text (a design journal's record): tab
/// separated, numbers in their shortest round-trip form; it reads back bit for bit.
std::string evaluation_record(const design::Evaluation& evaluation);
/// The evaluation of a record; InvalidParameter naming "record" where it is not one
/// (a record cut short by an interruption).
design::Evaluation parse_evaluation_record(std::string_view record);
/// The digest a design journal's first line holds: the program's version, the design
/// file's bytes (`design_text`) and every file it reads.
std::string design_fingerprint(const std::vector<std::filesystem::path>& inputs, std::string_view design_text);

std::optional<std::string> best_damper_file(const design::DesignStudy& study, const design::DesignResult& result,
                                            std::string_view design_file, const design::Evaluation* rounded = nullptr);

}  // namespace stockbridge::requests
