// stockbridge design: the search for the best damper of a design study (a base
// damper, the spans it serves, the numbers varied, constraints, an objective) on
// threads and MPI ranks (design/search.hpp).

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "progress.hpp"
#include "report_output.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/design_file.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/design_request.hpp"
#include "journal_file.hpp"
#include "task_runner.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

struct DesignOptions {
  std::string design_file;
  std::optional<int> samples;
  std::optional<int> polish;
  int threads = requests::DesignRequest{}.threads;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
  bool resume = false;
  std::string output;
  std::string best;
  int round_digits = requests::DesignRequest{}.round_digits;
  std::optional<std::string> report;
};

constexpr std::string_view kDesignJournalHead = "stockbridge design journal";

/// Every candidate evaluated, recorded as it completes (each rank in its own file:
/// <output>.journal for rank 0, <output>.journal.<rank> for the others), and with
/// --resume recalled from every rank's file of the interrupted run.
class DesignJournal final : public design::EvaluationJournal {
 public:
  DesignJournal(const std::string& output, const std::string& head, const Processes& processes, bool resume) {
    const std::filesystem::path base(output);
    const std::filesystem::path folder = base.parent_path().empty() ? std::filesystem::path(".") : base.parent_path();
    const std::string prefix = base.filename().string() + ".journal";
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
      const std::string name = entry.path().filename().string();
      if (name == prefix || name.starts_with(prefix + ".")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& file : files) {
      if (!resume) {
        // Another run's journals of ranks this run has not: gone, so that a later
        // --resume reads this run's alone.
        const std::string rank = file.filename().string().substr(prefix.size());
        if (processes.rank() == 0 && rank.size() > 1 && std::stoi(rank.substr(1)) >= processes.size()) {
          std::filesystem::remove(file, ec);
        }
        continue;
      }
      const JournalRecords journal = read_journal(file, head);
      cut_short_ += journal.cut_short;
      for (const std::string& record : journal.records) {
        try {
          design::Evaluation e = requests::parse_evaluation_record(record);
          std::vector<double> x = e.x;
          recalled_.insert_or_assign(std::move(x), std::move(e));
        } catch (const InvalidParameter&) {
          ++cut_short_;
        }
      }
    }
    const std::filesystem::path own =
        processes.rank() == 0 ? folder / prefix : folder / fmt::format("{}.{}", prefix, processes.rank());
    file_.emplace(own, head, resume);
  }

  std::optional<design::Evaluation> recall(const std::vector<double>& x) override {
    if (InterruptRequest::requested()) throw Interrupted("the design study was stopped");
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = recalled_.find(x);
    if (found == recalled_.end()) return std::nullopt;
    ++recalled_now_;
    return found->second;
  }

  void record(const design::Evaluation& evaluation) override {
    const std::string record = requests::evaluation_record(evaluation);
    const std::lock_guard<std::mutex> lock(mutex_);
    file_->write(record);
  }

  std::size_t kept() const { return recalled_.size(); }
  int cut_short() const { return cut_short_; }
  int recalled_now() const { return recalled_now_; }

 private:
  std::mutex mutex_;
  std::map<std::vector<double>, design::Evaluation> recalled_;
  std::optional<JournalFile> file_;
  int cut_short_ = 0;
  int recalled_now_ = 0;
};

std::string design_text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string design_value(double value) { return fmt::format("{:.4g}", value); }

void print_design_report(const design::DesignStudy& study, const design::DesignResult& result,
                         const std::optional<design::Evaluation>& rounded, int round_digits) {
  const auto line = [&](std::string_view label, const design::Evaluation& e) {
    std::string text = fmt::format("{}: ", label);
    if (!e.converged()) {
      return text + (e.termination == Termination::not_run ? "not valid (" + e.infeasibility + ")"
                                                           : "not converged (" + e.failure + ")");
    }
    text += study.objective() == design::Objective::life
                ? fmt::format("shortest life {} years", design_value(e.shortest_life_years))
                : fmt::format("largest stress {} of the endurance limit ({} MPa at {} Hz)", design_value(e.max_stress_ratio),
                              design_value(requests::megapascal_of(e.max_stress)), design_value(e.frequency_at_max_hz));
    text += fmt::format(", {} kg, messenger curvature {} 1/m", design_value(e.total_mass),
                        design_value(e.messenger_curvature_max));
    if (!e.feasible()) text += " (infeasible: " + e.infeasibility + ")";
    return text;
  };
  fmt::print("{}\n", line("base", result.evaluations[result.base].evaluation));
  if (!result.best) {
    fmt::print("best: none of the {} candidates is feasible\n", result.evaluations.size());
    return;
  }
  const design::Evaluation& best = result.evaluations[*result.best].evaluation;
  fmt::print("{}\n", line("best", best));
  for (std::size_t d = 0; d < study.variables().size(); ++d) {
    fmt::print("  {} = {}\n", study.variables()[d].name, design_value(best.x[d]));
  }
  if (rounded) {
    fmt::print("{}\n", line(fmt::format("rounded to build ({} significant digits)", round_digits), *rounded));
    for (std::size_t d = 0; d < study.variables().size(); ++d) {
      fmt::print("  {} = {}\n", study.variables()[d].name, design_value(rounded->x[d]));
    }
  }
  // Span by span, the design best.toml gives: the rounded one where it stays feasible.
  const design::Evaluation& built = rounded && rounded->feasible() ? *rounded : best;
  for (std::size_t k = 0; k < built.spans.size(); ++k) {
    const design::SpanFigures& f = built.spans[k];
    const auto position = study.position_on(k, built.x);
    fmt::print("  span {}: {:.3g} MPa, {:.3g} of its endurance limit{}{}{}\n", study.spans()[k].name,
               requests::megapascal_of(f.max_stress), f.max_stress_ratio,
               position ? fmt::format(", dampers from {:.3g} m", *position) : std::string(),
               k == built.span_at_max ? " (governs)" : "",
               f.worse_than_undamped()
                   ? fmt::format(": WORSE than undamped ({:.3g} MPa)", requests::megapascal_of(f.undamped_max_stress))
                   : std::string());
  }
  for (std::size_t j = 0; j < result.polishes.size(); ++j) {
    const SolverSummary& p = result.polishes[j];
    fmt::print("polish {}: {} after {} candidates{}\n", j, p.converged() ? "converged" : "stopped", p.evaluations,
               p.converged() ? "" : fmt::format(" ({})", termination_name(p.termination)));
  }
}

/// The HTML report: the study, the optimum and the rounded design, the objective
/// against each variable, and the design to build balanced on each span; `context`
/// the run's.
std::string design_report(const DesignOptions& options, const design::DesignStudy& study,
                          const design::DesignResult& result, const std::optional<design::Evaluation>& rounded,
                          const report::ReportContext& context) {
  report::DesignReportInput input{std::filesystem::path(options.design_file).stem().string(), &study, &result,
                                  rounded ? &*rounded : nullptr, options.round_digits, {}};
  const design::Evaluation* build = rounded && rounded->feasible() ? &*rounded
                                    : result.best                 ? &result.evaluations[*result.best].evaluation
                                                                  : nullptr;
  if (build) {
    const damper::Damper damper(study.damper_of(build->x));
    requests::SpanRequest request;
    request.points = study.points();
    request.threads = options.threads;
    for (std::size_t k = 0; k < study.spans().size(); ++k) {
      const span::Span s = study.span_with(k, damper, study.position_on(k, build->x));
      input.best_spans.push_back(requests::run_span(s, study.spans()[k].balance, requests::check_span_request(request)));
    }
  }
  return report::design_report(input, context);
}

/// On stderr, as the span command does for its points: which candidates did not
/// converge, and why (the span, the frequency, the solver's report); then which
/// could not be built (a damper or span that is not valid).
void print_unconverged_candidates(const design::DesignResult& result, const std::string& output) {
  std::vector<const design::StudyEvaluation*> unconverged, invalid;
  for (const design::StudyEvaluation& e : result.evaluations) {
    if (e.evaluation.converged()) continue;
    (e.evaluation.termination == Termination::not_run ? invalid : unconverged).push_back(&e);
  }
  if (!unconverged.empty()) {
    fmt::print(stderr, "design: {} candidate(s) did not converge (converged = 0, numbers left empty in {}):\n",
               unconverged.size(), output);
    for (const design::StudyEvaluation* e : unconverged) {
      fmt::print(stderr, "  {} {}: {}\n", design::stage_name(e->stage), e->run, e->evaluation.failure);
    }
  }
  if (!invalid.empty()) {
    fmt::print(stderr, "design: {} candidate(s) not valid, not evaluated (converged = 0, feasible = 0 in {}):\n",
               invalid.size(), output);
    for (const design::StudyEvaluation* e : invalid) {
      fmt::print(stderr, "  {} {}: {}\n", design::stage_name(e->stage), e->run, e->evaluation.infeasibility);
    }
  }
}

int run_design_command(const DesignOptions& options, Invocation& invocation) {
  Processes processes;
  if (processes.mpirun_without_mpi()) {
    fmt::print(stderr, "warning: started by mpirun, but this stockbridge was built without MPI: every process runs "
                       "the whole study\n");
  }
  requests::DesignRequest request;
  request.samples = options.samples;
  request.polish = options.polish;
  request.threads = options.threads;
  request.round_digits = options.round_digits;
  requests::validate(request);
  check_report_path(options.report);
  const io::DesignFile file = read_design_input(
      invocation, options.design_file,
      {{"-o", options.output}, {"--best", options.best}, {"--report", options.report.value_or("")}},
      slip_policy(options.allow_unusual));
  const design::SearchOptions search = requests::search_options(file.search, request);

  const auto start = std::chrono::steady_clock::now();
  ProgressReport progress(invocation, "design", options.quiet || processes.rank() != 0, "candidates");
  const std::unique_ptr<design::TaskRunner> runner = processes.runner(options.threads);
  const std::string head =
      fmt::format("{} {}", kDesignJournalHead, requests::design_fingerprint(file.inputs, design_text_of(options.design_file)));
  DesignJournal journal(options.output, head, processes, options.resume);
  if (options.resume && !options.quiet && processes.rank() == 0) {
    fmt::print(stderr, "design: resuming: {} candidate(s) in the journal{}\n", journal.kept(),
               journal.cut_short() > 0 ? fmt::format(" ({} record(s) cut short, computed again)", journal.cut_short()) : "");
  }
  std::optional<design::DesignResult> searched;
  {
    const InterruptRequest interrupt;
    try {
      searched.emplace(design::run_search(file.study, search, *runner, std::ref(progress), &journal));
    } catch (const Interrupted&) {
      fmt::print(stderr, "design: interrupted; {}.journal keeps every candidate evaluated: run again with --resume to "
                         "go on (nothing else written)\n",
                 options.output);
      return kInterrupted;
    }
  }
  const design::DesignResult& result = *searched;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (processes.rank() != 0) return result.best ? kSuccess : kNotConverged;

  const std::optional<design::Evaluation> rounded = requests::rounded_best(file.study, result, options.round_digits);
  const std::string report =
      options.report ? design_report(options, file.study, result, rounded, invocation.report_context()) : std::string();
  requests::write_csv_file(options.output, requests::design_table(file.study), result.evaluations);
  const auto best = requests::best_damper_file(file.study, result, std::filesystem::path(options.design_file).filename().string(),
                                               rounded ? &*rounded : nullptr);
  if (best) io::write_file_atomically(options.best, *best);
  if (options.report) io::write_file_atomically(*options.report, report);
  if (options.json) {
    fmt::print("{}\n", requests::design_summary(file.study, result,
                                                {search.samples, search.polish, processes.size(), options.threads,
                                                 options.round_digits, rounded ? &*rounded : nullptr})
                           .add("seconds", seconds)
                           .str());
  } else {
    print_design_report(file.study, result, rounded, options.round_digits);
  }
  fmt::print(stderr, "design: {} candidates in {:.1f} s on {} rank(s) x {} thread(s){}\n", result.evaluations.size(),
             seconds, processes.size(), options.threads,
             options.resume ? fmt::format(", {} recalled from the journal", journal.recalled_now()) : "");
  print_unconverged_candidates(result, options.output);
  if (best) return kSuccess;
  fmt::print(stderr, "design: no candidate is feasible ({} written, {} not)\n", options.output, options.best);
  return kNotConverged;
}

}  // namespace

void add_design_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<DesignOptions>();
  CLI::App* sub = app.add_subcommand(
      "design", "Search the best damper for spans and their wind band (a design file): on threads and MPI ranks");
  sub->add_option("design", options->design_file, "Design study (TOML)")->required();
  sub->add_option("--samples", options->samples, "Space-filling candidates (instead of the file's samples)");
  sub->add_option("--polish", options->polish, "Best candidates polished locally (instead of the file's polish; 0: none)");
  sub->add_option("--threads", options->threads, "Candidates evaluated at once (per MPI rank)")->capture_default_str();
  sub->add_flag("--resume", options->resume,
                "Go on from the journal (<output>.journal) of an interrupted run: candidates evaluated there are not "
                "evaluated again");
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout instead of the report");
  sub->add_flag("--quiet", options->quiet, "No progress on stderr (a bar on a terminal; else a line every 10 s after 10 s)");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  sub->add_option("-o,--output", options->output, "Output CSV file: every candidate evaluated")->required();
  sub->add_option("--best", options->best, "Output damper file: the best design (rounded to --round-digits where that "
                                           "stays feasible)")->required();
  sub->add_option("--round-digits", options->round_digits,
                  "Significant digits the best design is rounded to for building, and evaluated again")
      ->capture_default_str();
  add_report_option(*sub, options->report,
                    "the study, the optimum and the design to build, the objective against each variable, its curves");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_design_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
