// stockbridge line as a user runs it: the schedule the same on one thread, two, two
// MPI ranks and after an interruption (Ctrl-C or a killed process) resumed; each
// row reproduced by `stockbridge span` on the span file --details writes; a journal
// of other inputs refused; bad spans named by file and line.

#include <algorithm>
#include <csignal>
#include <fstream>
#include <map>
#include <sstream>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/csv_table.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::testing {
namespace {

/// A small line: four spans of two conductors, tensions in all three forms, one
/// damper type, coarse frequency grids (the line's cost, not its figures, is tried).
std::string small_line() {
  return R"([line]
name = "test line"
points = 30
search_points = 20

[conductor]
type = "AAAC ASTER570"

[wind]
law = "cigre"
speed_min = 1.0
speed_max = 7.0

[self_damping]
law = "noiseux-1991"

[fatigue]
cycles = 5e8
wind_weibull = { shape = 2.0, scale = 4.0 }
aeolian_fraction = 0.3

[dampers]
types = [ { name = "sb1", file = ")" + kDamperExample + R"(" } ]
max_per_end = 2
position_max = 5.0

[[span]]
id = "T1-T2"
length = 300
tension_fraction = 0.12

[[span]]
id = "T2-T3"
length = 420
catenary_parameter = 1500
terrain = 2

[[span]]
id = "T3-T4"
length = 250
tension = 30000
conductor = "ACSR Drake"

[[span]]
id = "T4-T5"
length = 380
tension_fraction = 0.2
conductor = "ACSR Linnet"
)";
}

std::filesystem::path line_folder(const std::string& name, const std::string& text = small_line()) {
  const auto dir = scratch_directory(name);
  std::ofstream(dir / "line.toml") << text;
  return dir;
}

/// The schedule of the small line on one thread, made once for the tests that compare with it.
const std::string& reference_schedule() {
  static const std::string schedule = [] {
    const auto dir = line_folder("line-reference");
    const CliResult r = run_cli("line line.toml -o schedule.csv --quiet", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_text(dir / "schedule.csv");
  }();
  return schedule;
}

/// A schedule's rows by the id they begin with, each row's cells by column name.
std::map<std::string, std::map<std::string, std::string>> schedule_rows(const std::filesystem::path& path) {
  std::istringstream in(read_text(path));
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split_csv_line(line);
  std::map<std::string, std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    std::map<std::string, std::string>& row = rows[cells.at(0)];
    for (std::size_t c = 0; c < header.size() && c < cells.size(); ++c) row[header[c]] = cells[c];
  }
  return rows;
}

// The example line (44 spans, three conductors) against its schedule as stored
// (tests/cli/data/line_example_schedule.csv): a faster search must not make it
// worse. Every span the same damper type and count per end, the same verdict, and
// its largest stress within 0.5 % of the stored one or lower.
TEST(LineCli, TheExampleLinesScheduleIsTheStoredOneOrBetter) {
  const auto dir = scratch_directory("line-example");
  const CliResult r = run_cli("line '" + std::string(STOCKBRIDGE_SOURCE_DIR) +
                                  "/examples/line_example.toml' -o schedule.csv --threads 2 --quiet",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto stored = schedule_rows(std::filesystem::path(STOCKBRIDGE_SOURCE_DIR) / "tests/cli/data/line_example_schedule.csv");
  const auto made = schedule_rows(dir / "schedule.csv");
  ASSERT_EQ(stored.size(), 44u);
  ASSERT_EQ(made.size(), stored.size());
  for (const auto& [id, want] : stored) {
    ASSERT_EQ(made.count(id), 1u) << id;
    const auto& got = made.at(id);
    for (const char* column : {"dampers_per_end", "damper_type", "verdict"}) {
      EXPECT_EQ(got.at(column), want.at(column)) << id << ": " << column;
    }
    const double stress = std::stod(got.at("max_stress_mpa")), was = std::stod(want.at("max_stress_mpa"));
    EXPECT_LE(stress, was * 1.005) << id << ": the largest stress " << stress << " MPa against " << was << " stored";
  }
}

TEST(LineCli, TheScheduleIsTheSameOnOneAndTwoThreadsAndTwoRanks) {
  const std::string& one = reference_schedule();
  ASSERT_FALSE(one.empty());
  EXPECT_NE(one.find("id,conductor,undamped_verdict,damper_type,positions_m,verdict"), std::string::npos) << one;
  const auto dir = line_folder("line-threads");
  const CliResult two = run_cli("line line.toml -o schedule.csv --threads 2 --json", dir);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(read_text(dir / "schedule.csv"), one);
  EXPECT_NE(two.out.find("\"spans\": 4"), std::string::npos) << two.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "schedule_bill.csv"));
#ifdef STOCKBRIDGE_TEST_MPIRUN
  const std::string command = "cd '" + dir.string() + "' && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 '" +
                              STOCKBRIDGE_TEST_MPIRUN + "' --oversubscribe -np 2 '" + STOCKBRIDGE_CLI +
                              "' line line.toml --quiet -o ranks.csv > ranks.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir / "ranks.log");
  EXPECT_EQ(read_text(dir / "ranks.csv"), one);
#endif
}

TEST(LineCli, EveryRowIsReproducedBySpanOnItsDetailsFile) {
  const auto dir = line_folder("line-details");
  const CliResult r = run_cli("line line.toml -o schedule.csv --details spans --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string schedule = read_text(dir / "schedule.csv");
  const std::vector<std::string> rows = lines_of(schedule);
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::string id = rows[i].substr(0, rows[i].find(','));
    const CliResult span = run_cli("span spans/" + id + ".toml --points 30 -o again.csv --json", dir);
    ASSERT_EQ(span.exit_code, 0) << id << ": " << span.err;
    const std::string key = "\"max_stress_fymax_mpa\": ";
    const std::size_t at = span.out.find(key);
    ASSERT_NE(at, std::string::npos) << span.out;
    const double from_span = std::stod(span.out.substr(at + key.size()));
    EXPECT_NEAR(from_span, std::stod(csv_cell(schedule, i, "max_stress_mpa")), 1e-9 * from_span) << id;
    EXPECT_EQ(read_text(dir / "again.csv"), read_text(dir / ("spans/" + id + ".csv"))) << id;
  }
}

TEST(LineCli, AKilledRunResumedGivesTheSameSchedule) {
  const auto dir = line_folder("line-killed");
  // Killed (no chance to clean up) once two spans are in the journal.
  const int status = run_cli_stopped("line line.toml -o schedule.csv --quiet", dir, dir / "schedule.csv.journal", 2, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed";
  EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv"));
  const int kept = journal_records(dir / "schedule.csv.journal");
  EXPECT_GE(kept, 2);
  const CliResult resumed = run_cli("line line.toml -o schedule.csv --resume", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(kept) + " of 4 spans in schedule.csv.journal"), std::string::npos)
      << resumed.err;
  EXPECT_EQ(read_text(dir / "schedule.csv"), reference_schedule());
}

TEST(LineCli, CtrlCStopsCleanlyWithStatus130AndTheJournalResumes) {
  const auto dir = line_folder("line-interrupted");
  const int status = run_cli_stopped("line line.toml -o schedule.csv", dir, dir / "schedule.csv.journal", 1, SIGINT);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << read_text(dir / "run.err");
  EXPECT_NE(read_text(dir / "run.err").find("run again with --resume"), std::string::npos) << read_text(dir / "run.err");
  EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "schedule_bill.csv"));
  const CliResult resumed = run_cli("line line.toml -o schedule.csv --resume --quiet", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_text(dir / "schedule.csv"), reference_schedule());
  // Resuming a finished run computes nothing and writes the same again.
  const CliResult again = run_cli("line line.toml -o schedule.csv --resume", dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("4 of 4 spans in schedule.csv.journal, 0 to compute"), std::string::npos) << again.err;
  EXPECT_EQ(read_text(dir / "schedule.csv"), reference_schedule());
}

// A damper type known by a measured sheet: nothing solved, so the sanitizer builds
// run a whole line (two threads taking spans) in a second.
TEST(LineCli, AMeasuredDamperTypeOnTwoThreads) {
  std::string text = small_line();
  const std::string model = "{ name = \"sb1\", file = \"" + kDamperExample + "\" }";
  text.replace(text.find(model), model.size(),
               "{ name = \"vendor\", impedance = \"" + std::string(STOCKBRIDGE_SOURCE_DIR) +
                   "/examples/vendor_sheet.csv\", mass = 2.4 }");
  text.replace(text.find("points = 30\nsearch_points = 20"), 31, "points = 12\nsearch_points = 10");
  const auto dir = line_folder("line-sheet", text);
  const CliResult two = run_cli("line line.toml -o two.csv --threads 2 --quiet", dir);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const CliResult one = run_cli("line line.toml -o one.csv --quiet", dir);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(read_text(dir / "two.csv"), read_text(dir / "one.csv"));
  EXPECT_NE(read_text(dir / "one.csv").find("vendor"), std::string::npos);
  EXPECT_NE(read_text(dir / "one_bill.csv").find("damper_type,dampers,spans,mass_kg"), std::string::npos)
      << read_text(dir / "one_bill.csv");
}

TEST(LineCli, AJournalOfOtherInputsIsRefused) {
  const auto dir = line_folder("line-other-journal");
  std::ofstream(dir / "schedule.csv.journal") << "stockbridge line journal 0123456789abcdef\n";
  const CliResult r = run_cli("line line.toml -o schedule.csv --resume", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("schedule.csv.journal was written for other inputs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("run without --resume to start again"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv"));
}

// An output in a folder that does not exist is refused before anything is read or
// computed: one line naming the option and the folder, no journal, no folder made.
TEST(LineCli, AnOutputInAMissingFolderIsRefusedBeforeAnythingIsWritten) {
  const auto dir = line_folder("line-missing-folder");
  const CliResult r = run_cli("line line.toml -o missing_folder/x.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "stockbridge: -o missing_folder/x.csv: the folder missing_folder does not exist: expected an output "
                   "file in an existing folder\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(std::filesystem::exists(dir / "missing_folder"));
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "line.toml" || name == "stdout.txt" || name == "stderr.txt") << name << " written";
  }
}

TEST(LineCli, BadSpansAreNamedByFileLineAndKey) {
  struct Case {
    std::string csv;
    std::string message;
  };
  const std::vector<Case> cases{
      {"id,length_m,tension_fraction\nA,300,0.15\nB,400,\n", "spans.csv:3: span \"B\": no tension"},
      {"id,length_m,tension_n,tension_fraction\nA,300,30000,0.15\n", "spans.csv:2: span \"A\": tension_fraction given beside tension"},
      {"id,length_m,tension_kn\nA,300,30\n", "spans.csv: column 'tension_kn' is not a spans column"},
      {"id,length_m,tension_fraction\nA,300,0.15\nA,200,0.15\n", "spans.csv:3: span[1].id = \"A\": given to an earlier span too"},
      {"id,length_m,tension_fraction\nA,300,15\n",
       "spans.csv:2: span \"A\": tension_fraction = 15: outside the typical 0.03 to 0.4 of the tension as a fraction of "
       "the rated tensile strength (a percentage? 15 % = 0.15) (--allow-unusual takes it as given)"},
      {"id,length_m,tension_n\nA,300,30.3\n", "spans.csv:2: span \"A\": tension_n = 30.3: outside the typical 1000 to "
                                             "500000 N of the conductor tension (in kN? 30.3 kN = 30300 N)"},
      {"id,length_m,tension_fraction\nA,0.3,0.15\n", "spans.csv:2: span \"A\": length_m = 0.3: outside the typical 20 "
                                                    "to 3000 m of the span length (in km? 0.3 km = 300 m)"},
      {"id,length_m,tension_n\nA,300,2000\n", "spans.csv:2: span \"A\": tension_n = 2000: H/w = 129.8 m and a sag of "
                                             "86.7 m (28.9 % of the 300 m span)"},
      {"id,length_m,tension_fraction,terrain\nA,300,0.15\n",
       "spans.csv:2: 3 cells: expected 4, as the header has (an empty cell is written as nothing between two commas)"},
      {"id,length_m,tension_fraction\nA,300,0,15\n",
       "spans.csv:2: 4 cells: expected 3, as the header has (a decimal comma?"},
      {"id,length_m,tension_fraction,conductor\nA,300,0.15,ACSR Drakee\n", "spans.csv:2: conductor"},
      {"\xEF\xBB\xBFid,length_m,tension_fraction\r\nA,-300,0.15\r\n", "spans.csv:2: span \"A\": length_m = -300"},
      {"id,length_m,tension_fraction,masses\nA,300,0.15,12.5@100;12.5\n",
       "spans.csv:2: column 'masses' = '12.5@100;12.5': '12.5' is not a mass at a position: expected <kg>@<m from end "
       "1> entries, ';'-separated (e.g. 12.5@30;12.5@90), or an empty cell for none"},
      {"id,length_m,tension_fraction,masses\nA,300,0.15,12.5@300\n",
       "spans.csv:2: span \"A\": column 'masses' = '12.5@300': a position = 300: expected a distance from end 1 > 0 "
       "and < the span's length, 300 m"},
  };
  for (const Case& c : cases) {
    std::string text = small_line();
    text = text.substr(0, text.find("[[span]]"));
    text.insert(0, "spans = \"spans.csv\"\n");
    const auto dir = line_folder("line-bad", text);
    std::ofstream(dir / "spans.csv", std::ios::binary) << c.csv;
    const CliResult r = run_cli("line line.toml -o schedule.csv", dir);
    EXPECT_EQ(r.exit_code, 2) << c.csv;
    EXPECT_EQ(r.stderr_lines(), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv"));
    EXPECT_FALSE(std::filesystem::exists(dir / "schedule.csv.journal"));
  }
}

/// The frequencies the sphere line balances a span at: fewer under the sanitizers,
/// where its search (three distances, eight dampers) is most of their run.
int sphere_line_points() { return scaled(12, 6); }

/// A line of two spans on the vendor's measured sheet (nothing solved: seconds), one
/// with three warning spheres in a [[span.mass]] table, the other plain.
std::string sphere_line() {
  return R"([line]
name = "spheres"
points = )" + std::to_string(sphere_line_points()) + R"(
search_points = )" + std::to_string(scaled(10, 6)) + R"(
[conductor]
type = "AAAC ASTER570"
[wind]
law = "cigre"
[self_damping]
law = "noiseux-1991"
[fatigue]
cycles = 5e8
[dampers]
types = [ { name = "vendor", impedance = ")" +
         std::string(STOCKBRIDGE_SOURCE_DIR) + R"(/examples/vendor_sheet.csv", mass = 2.4 } ]
max_per_end = 2
position_max = 4.0
[[span]]
id = "S"
length = 400
catenary_parameter = 1300
[[span.mass]]
name = "sphere"
mass = 12.5
positions = [100, 200, 300]
[[span]]
id = "P"
length = 300
catenary_parameter = 1300
)";
}

// The span with spheres end to end: dampers beside each sphere in its row and the
// bill; its details span file gives `stockbridge span` the row's largest stress and
// place, and the same balance CSV; the report shows them; a journal cut after the
// first span resumes to the same schedule.
TEST(LineCli, ASpanWithSpheresGetsDampersBesideThemFromScheduleToSpanFile) {
  const auto dir = line_folder("line-spheres", sphere_line());
  const CliResult r = run_cli("line line.toml -o schedule.csv --details spans --report line.html --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string schedule = read_text(dir / "schedule.csv");
  EXPECT_EQ(csv_cell(schedule, 1, "id"), "S");
  EXPECT_EQ(csv_cell(schedule, 1, "sphere_dampers"), "6");
  const std::string distance = csv_cell(schedule, 1, "sphere_damper_distance_m");
  EXPECT_TRUE(distance == "1" || distance == "2" || distance == "3") << distance;
  EXPECT_EQ(csv_cell(schedule, 2, "sphere_dampers"), "0");
  EXPECT_EQ(csv_cell(schedule, 2, "sphere_damper_distance_m"), "");
  const int per_end_s = std::stoi(csv_cell(schedule, 1, "dampers_per_end"));
  const int per_end_p = std::stoi(csv_cell(schedule, 2, "dampers_per_end"));
  const std::string bill = read_text(dir / "schedule_bill.csv");
  EXPECT_NE(bill.find("vendor," + std::to_string(2 * per_end_s + 6 + 2 * per_end_p) + ",2,"), std::string::npos) << bill;

  const CliResult span =
      run_cli("span spans/S.toml --points " + std::to_string(sphere_line_points()) + " -o again.csv --json", dir);
  ASSERT_EQ(span.exit_code, 0) << span.err;
  const std::string key = "\"max_judged_stress_mpa\": ";
  const std::size_t at = span.out.find(key);
  ASSERT_NE(at, std::string::npos) << span.out;
  const double from_span = std::stod(span.out.substr(at + key.size()));
  EXPECT_NEAR(from_span, std::stod(csv_cell(schedule, 1, "max_stress_mpa")), 1e-9 * from_span);
  const std::string place = csv_cell(schedule, 1, "governing_place");
  EXPECT_FALSE(place.empty());
  EXPECT_NE(span.out.find("\"governing_place\": \"" + place + "\""), std::string::npos) << place << "\n" << span.out;
  EXPECT_EQ(read_text(dir / "again.csv"), read_text(dir / "spans/S.csv"));
  const std::string html = read_text(dir / "line.html");
  EXPECT_NE(html.find("beside masses"), std::string::npos);
  EXPECT_NE(html.find("6 beside masses at " + distance + " m"), std::string::npos);

  // The journal cut after its first span's record: --resume computes the other.
  const std::vector<std::string> journal = lines_of(read_text(dir / "schedule.csv.journal"));
  ASSERT_EQ(journal.size(), 3u);
  std::ofstream(dir / "schedule.csv.journal", std::ios::trunc) << journal[0] << "\n" << journal[1] << "\n";
  std::filesystem::remove(dir / "schedule.csv");
  const CliResult resumed = run_cli("line line.toml -o schedule.csv --resume", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("1 of 2 spans in schedule.csv.journal, 1 to compute"), std::string::npos) << resumed.err;
  EXPECT_EQ(read_text(dir / "schedule.csv"), schedule);

  // A record of the program before the dampers beside the masses (span-v2, no
  // governing place) is no row: its span is computed again, and the run says why.
  std::string earlier = journal[1];
  earlier.replace(earlier.find("span-v3"), 7, "span-v2");
  std::ofstream(dir / "schedule.csv.journal", std::ios::trunc) << journal[0] << "\n" << earlier << "\n";
  const CliResult again = run_cli("line line.toml -o schedule.csv --resume", dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("0 of 2 spans in schedule.csv.journal (1 record(s) of an earlier program, computed again), 2 "
                           "to compute"),
            std::string::npos)
      << again.err;
  EXPECT_EQ(read_text(dir / "schedule.csv"), schedule);
}

}  // namespace
}  // namespace stockbridge::testing
