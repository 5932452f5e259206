// stockbridge line: the damper schedule of a line of spans (line/schedule.hpp,
// docs/line.md): for every span the fewest dampers per end and their positions
// that make it safe, on threads and MPI ranks (spans dealt as workers free up),
// recorded span by span in a journal beside the schedule so that --resume goes on
// where an interrupted run stopped.

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "input_files.hpp"
#include "option_parsing.hpp"
#include "report_output.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/line_request.hpp"
#include "stockbridge/requests/line_run.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "journal_file.hpp"
#include "task_runner.hpp"

namespace stockbridge::cli {

namespace {

// Helper names here are unique among the program's files (unity batches).

struct LineOptions {
  std::string line_file;
  std::string output;
  std::string bill;
  int threads = 1;
  bool resume = false;
  std::string details;
  bool json = false;
  bool quiet = false;
  bool allow_unusual = false;
  std::optional<std::string> report;
};

constexpr std::string_view kJournalHead = "stockbridge line journal";

std::string line_bill_path(const LineOptions& options) {
  if (!options.bill.empty()) return options.bill;
  const std::filesystem::path out(options.output);
  return (out.parent_path() / (out.stem().string() + "_bill.csv")).string();
}

/// A span's id as a file name: letters, digits, '.', '_' and '-' kept, the rest '_'.
std::string line_file_stem(const std::string& id) {
  std::string stem = id;
  for (char& c : stem) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!keep) c = '_';
  }
  return stem;
}

std::string line_text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The journal's records that are not rows: cut short (an interruption mid-write),
/// or of an earlier program (their rows lack what the schedule now writes).
struct LineJournalLeftOut {
  int cut_short = 0;
  int earlier = 0;

  /// " (3 record(s) cut short, 2 of an earlier program, computed again)", or nothing.
  std::string text() const {
    if (cut_short + earlier == 0) return {};
    std::string what = cut_short > 0 ? fmt::format("{} record(s) cut short", cut_short) : std::string();
    if (earlier > 0) what += fmt::format("{}{} record(s) of an earlier program", what.empty() ? "" : ", ", earlier);
    return fmt::format(" ({}, computed again)", what);
  }
};

/// The journal's rows of this line (the journal of other inputs refused); records
/// cut short or of an earlier program are left out: those spans are computed again.
std::map<std::size_t, line::ScheduleRow> read_line_journal(const std::filesystem::path& path,
                                                           const std::string& fingerprint, std::size_t spans,
                                                           LineJournalLeftOut& left_out) {
  JournalRecords journal = read_journal(path, fmt::format("{} {}", kJournalHead, fingerprint));
  left_out.cut_short = journal.cut_short;
  std::map<std::size_t, line::ScheduleRow> rows;
  for (const std::string& record : journal.records) {
    try {
      requests::SpanOutcome outcome = requests::parse_span_outcome(record);
      if (outcome.index < spans) rows.insert_or_assign(outcome.index, std::move(*outcome.row));
    } catch (const InvalidParameter&) {
      ++(requests::earlier_span_record(record) ? left_out.earlier : left_out.cut_short);
    }
  }
  return rows;
}

std::string line_positions(const line::ScheduleRow& row) {
  std::string out;
  for (const double x : row.positions) out += fmt::format("{}{:g}", out.empty() ? "" : "; ", x);
  return out;
}

std::string line_arrangement(const line::ScheduleRow& row) {
  if (row.per_end == 0) return "no dampers";
  const std::string beside_masses =
      row.sphere_dampers > 0 ? fmt::format(" and {} beside the masses, {:g} m from each", row.sphere_dampers, row.sphere_distance)
                             : std::string();
  return fmt::format("{} per end of {} at {} m{}", row.per_end, row.damper_type, line_positions(row), beside_masses);
}

std::string line_duration(double seconds) {
  if (seconds < 90) return fmt::format("{:.0f} s", seconds);
  if (seconds < 5400) return fmt::format("{:.0f} min", seconds / 60);
  return fmt::format("{:.1f} h", seconds / 3600);
}

void print_line_report(const io::LineFile& file, const requests::LineSchedule& schedule) {
  const std::vector<line::ScheduleRow>& rows = schedule.rows;
  const line::ScheduleCounts counts = line::schedule_counts(rows);
  const line::ScheduleRow* governing = counts.governing;
  fmt::print("line {}: {} spans, {} safe, {} unsafe, {} unknown, {} uncertain (criterion {})\n", file.name, rows.size(),
             counts.safe, counts.unsafe, counts.unknown, counts.uncertain,
             span::fatigue_criterion_name(file.line.spans().front().span.fatigue().criterion));
  for (const auto& [n, spans] : counts.per_end) fmt::print("  {} damper(s) per end: {} spans\n", n, spans);
  for (const line::BillLine& b : schedule.bill) {
    fmt::print("bill: {} x {}{}{}\n", b.dampers, b.damper_type,
               b.mass ? fmt::format(" ({:.4g} kg)", *b.mass) : std::string(),
               b.price ? fmt::format(", price {:.6g}", *b.price) : std::string());
  }
  if (governing) {
    fmt::print("governing span: {} ({}), {:.3g} MPa at {}, {:.3g} % of the endurance limit\n", governing->id,
               line_arrangement(*governing), requests::megapascal_of(governing->max_stress), governing->governing_place,
               100.0 * governing->stress_ratio());
  }
  int shown = 0;
  for (const line::ScheduleRow& r : rows) {
    if (r.verdict == span::Verdict::safe) continue;
    if (++shown > 10) {
      fmt::print("  ... (the schedule's verdict column lists every span)\n");
      break;
    }
    fmt::print("  {}: {}, {}\n", r.id, span::verdict_name(r.verdict), line_arrangement(r));
  }
  for (const std::string& w : line::grouped_warnings(rows)) fmt::print("  warning: {}\n", w);
}

/// --details: the span file and the balance CSV of a span's schedule.
void write_line_details(const std::filesystem::path& directory, const io::LineFile& file,
                        const line::ScheduleRow& row, const span::SpanAnalysis& analysis) {
  const std::string stem = line_file_stem(row.id);
  io::write_file_atomically(directory / (stem + ".toml"), io::span_file_text(file, row));
  requests::write_csv_file(directory / (stem + ".csv"), requests::span_table(analysis.span), analysis.balance.points);
}

/// The line file, its outputs checked apart from every file it reads, its warnings printed.
io::LineFile read_line_input(const LineOptions& options, const std::vector<CommandFile>& outputs,
                             Invocation& invocation) {
  require_outputs_apart(outputs, {{"the line file", options.line_file}});
  io::LineFile file = io::load_line_file(options.line_file, slip_policy(options.allow_unusual));
  std::vector<CommandFile> inputs;
  for (const auto& p : file.inputs) inputs.push_back({"a file the line file reads", p.string()});
  require_outputs_apart(outputs, inputs);
  print_warnings(invocation, file.warnings);
  return file;
}

/// --details: the folder made, every span's file name checked unique.
void prepare_line_details(const std::string& folder, const io::LineFile& file) {
  std::set<std::string> stems;
  for (const line::LineSpan& s : file.line.spans()) {
    if (!stems.insert(line_file_stem(s.id)).second) {
      throw InvalidParameter(fmt::format("--details: two spans' ids give the file name {} (ids keep letters, digits, "
                                         "'.', '_' and '-'; the rest becomes '_')",
                                         line_file_stem(s.id)));
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (!std::filesystem::is_directory(folder)) throw OutputError(fmt::format("--details {}: cannot make the folder", folder));
}

/// The schedule, the bill and the report (or JSON); the exit status.
int write_line_outputs(const LineOptions& options, const io::LineFile& file, const requests::LineSchedule& schedule,
                       const Processes& processes, double seconds, std::size_t computed, const Invocation& invocation) {
  const std::string report =
      options.report ? report::line_report(file, schedule, invocation.report_context()) : std::string();
  io::write_file_atomically(options.output, requests::schedule_table().values(schedule.rows).csv());
  if (options.report) io::write_file_atomically(*options.report, report);
  io::write_file_atomically(line_bill_path(options),
                            requests::bill_table().values(schedule.bill).csv());
  if (options.json) {
    fmt::print("{}\n", requests::line_summary(file, schedule)
                           .add("ranks", processes.size())
                           .add("threads", options.threads)
                           .add("seconds", seconds)
                           .str());
  } else {
    print_line_report(file, schedule);
  }
  int not_converged = 0;
  for (const line::ScheduleRow& r : schedule.rows) not_converged += r.converged < r.points;
  if (!options.quiet) {
    fmt::print(stderr, "line: {} spans ({} computed now) in {:.1f} s on {} rank(s) x {} thread(s)\n", schedule.rows.size(),
               computed, seconds, processes.size(), options.threads);
  }
  if (not_converged == 0) return kSuccess;
  fmt::print(stderr, "line: {} span(s) not converged throughout (converged = 0 in {}; their stresses left empty, "
                     "their verdicts unknown unless a converged point exceeds the limit)\n",
             not_converged, options.output);
  return kNotConverged;
}

int run_line_command(const LineOptions& options, Invocation& invocation) {
  Processes processes;
  const bool root = processes.rank() == 0;
  if (processes.mpirun_without_mpi()) {
    fmt::print(stderr, "warning: started by mpirun, but this stockbridge was built without MPI: every process runs "
                       "the whole line\n");
  }
  require_in_range("threads", options.threads, 1, 256);
  const std::string journal_path = options.output + ".journal";
  check_report_path(options.report);
  const io::LineFile file = read_line_input(options, {{"-o", options.output},
                                                      {"--bill", line_bill_path(options)},
                                                      {"the journal", journal_path},
                                                      {"--report", options.report.value_or("")}},
                                              invocation);
  const std::size_t spans = file.line.spans().size();
  if (!options.details.empty()) prepare_line_details(options.details, file);
  const std::string fingerprint = requests::line_fingerprint(file, line_text_of(options.line_file));
  std::map<std::size_t, line::ScheduleRow> rows;  // the journal's; the run's outcomes join them when it ends
  LineJournalLeftOut left_out;
  if (root && options.resume) rows = read_line_journal(journal_path, fingerprint, spans, left_out);
  const std::size_t resumed = rows.size();
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < spans; ++i) {
    if (!rows.contains(i)) todo.push_back(i);
  }
  std::optional<JournalFile> journal;
  if (root) journal.emplace(journal_path, fmt::format("{} {}", kJournalHead, fingerprint), options.resume);
  if (root && options.resume && !options.quiet) {
    fmt::print(stderr, "line: resuming: {} of {} spans in {}{}, {} to compute\n", rows.size(), spans, journal_path,
               left_out.text(), todo.size());
  }

  std::optional<InterruptRequest> interrupt(std::in_place);
  line::TableCache cache;
  const auto start = std::chrono::steady_clock::now();
  std::size_t done_now = 0;
  requests::LineRunOptions run;
  run.threads = options.threads;
  run.todo = todo;
  run.stop = &InterruptRequest::flag();
  if (!options.details.empty()) {
    run.on_scheduled = [&](const line::ScheduleRow& row, const span::SpanAnalysis& analysis) {
      write_line_details(options.details, file, row, analysis);
    };
  }
  run.on_outcome = [&](const requests::SpanOutcome& outcome, const std::string& record) {
    journal->write(record);
    ++done_now;
    if (!options.quiet) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const std::size_t left = todo.size() - done_now;
      fmt::print(stderr, "line: {}/{} {}: {}, {}{}\n", resumed + done_now, spans, outcome.row->id,
                 line_arrangement(*outcome.row), span::verdict_name(outcome.row->verdict),
                 left == 0 ? std::string() : fmt::format("; {} left, about {}", left,
                                                         line_duration(seconds / static_cast<double>(done_now) *
                                                                       static_cast<double>(left))));
    }
  };
  run.dealer = [&processes](int threads, const std::vector<std::size_t>& tasks,
                            const std::function<std::string(std::size_t)>& compute,
                            const std::function<void(std::size_t, const std::string&)>& pass_on,
                            const std::function<void()>&, const std::atomic<bool>& stop) {
    processes.deal(threads, tasks, compute, pass_on, stop);
  };
  requests::LineRun result = requests::run_line(file, cache, run);
  const bool interrupted = result.termination == Termination::interrupted;
  for (requests::SpanOutcome& outcome : result.outcomes) {
    if (outcome.row) rows.insert_or_assign(outcome.index, std::move(*outcome.row));  // scheduled or failed
  }
  interrupt.reset();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!root) return kSuccess;
  if (interrupted) {
    fmt::print(stderr, "line: interrupted after {} of {} spans; {} keeps them: run again with --resume to compute the "
                       "rest (nothing else written)\n",
               rows.size(), spans, journal_path);
    return kInterrupted;
  }
  const requests::LineSchedule schedule = requests::line_schedule(file, std::move(rows));
  if (!options.details.empty()) {  // spans from the journal whose details are missing: balanced again
    for (const line::ScheduleRow& row : schedule.rows) {
      const std::filesystem::path csv = std::filesystem::path(options.details) / (line_file_stem(row.id) + ".csv");
      if (std::filesystem::exists(csv) || std::isnan(row.endurance_limit)) continue;  // a span not scheduled has none
      write_line_details(options.details, file, row, line::analyse_arrangement(file.line, row, cache));
    }
  }
  return write_line_outputs(options, file, schedule, processes, seconds, done_now, invocation);
}

}  // namespace

void add_line_command(CLI::App& app, Invocation& invocation) {
  auto options = std::make_shared<LineOptions>();
  CLI::App* sub = app.add_subcommand(
      "line", "The damper schedule of a line: for every span the fewest dampers per end and their positions that "
              "make it safe (threads, MPI ranks, resumable)");
  sub->add_option("line", options->line_file, "Line description (TOML)")->required();
  sub->add_option("-o,--output", options->output, "Output schedule CSV (a journal <output>.journal beside it)")->required();
  sub->add_option("--bill", options->bill, "Output bill of materials CSV (default: <output stem>_bill.csv)");
  sub->add_option("--threads", options->threads, "Spans computed at once (per MPI rank)")->capture_default_str();
  sub->add_flag("--resume", options->resume,
                "Go on from the journal of an interrupted run: compute only the spans it lacks");
  sub->add_option("--details", options->details,
                  "Folder for each span's span file and balance CSV (<id>.toml, <id>.csv)");
  sub->add_flag("--json", options->json, "Print a JSON summary on stdout instead of the report");
  sub->add_flag("--quiet", options->quiet, "No progress on stderr");
  add_allow_unusual_flag(*sub, options->allow_unusual);
  add_report_option(*sub, options->report, "the rules, the verdicts, the margin per span, the schedule and the bill");
  sub->callback([options, &invocation] { invocation.set_exit_code(run_line_command(*options, invocation)); });
}

}  // namespace stockbridge::cli
