// `stockbridge design` as users run it: a small study end to end (CSV, best.toml,
// --json), the best design through `stockbridge span` reproducing its objective,
// the same designs.csv on 1 and 2 threads and on 1 and 2 MPI ranks, a study with
// no feasible candidate (exit 3), candidates that did not converge listed on stderr,
// and bad design files (exit 2, one line, no file).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::testing {
namespace {

const std::string kDesignExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

/// The small study's sizes (smaller under the sanitizers: the same paths).
const int kSamples = scaled(3, 1);
const int kPoints = scaled(8, 4);

/// A small study of the example's variables on the example span.
std::string small_study() {
  return "damper = \"" + kDesignExamples + "sauter2003.toml\"\n" + "spans = [\"" + kDesignExamples +
         "aster570_400m.toml\"]\n"
         "samples = " + std::to_string(kSamples) + "\npolish = 1\npolish_evaluations = " + std::to_string(scaled(4, 2)) +
         "\npoints = " + std::to_string(kPoints) + "\nseed = 3\n"
         "[[variable]]\nname = \"arm.left.mass\"\nmin = 0.5\nmax = 1.5\n"
         "[[variable]]\nname = \"position\"\nmin = 0.6\nmax = 2.0\n"
         "[[tie]]\nname = \"arm.right.mass\"\nequals = \"arm.left.mass\"\n"
         "[constraints]\ntotal_mass_max = 4.0\n";
}

std::filesystem::path study_folder(const std::string& name, const std::string& text) {
  const auto dir = scratch_directory(name);
  std::ofstream(dir / "study.toml") << text;
  return dir;
}

/// A number to 3 significant digits, as a damper file prints it.
std::string fmt_3g(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// A number as text that reads back exactly.
std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

TEST(DesignCli, ASmallStudyWritesEveryCandidateAndTheBestDamper) {
  const auto dir = study_folder("design-small", small_study());
  const CliResult r = run_cli("design study.toml --json -o designs.csv --best best.toml", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_text(dir / "designs.csv");
  EXPECT_EQ(csv.rfind("stage,governing_span,governing_place,run,arm.left.mass,position,objective,max_stress_ratio,max_stress_mpa,"
                      "frequency_at_max_hz,total_mass_kg,messenger_curvature_max_per_m,shortest_life_years,converged,"
                      "feasible,aster570_400m_stress_ratio,aster570_400m_max_stress_mpa,"
                      "aster570_400m_undamped_max_stress_mpa,aster570_400m_life_years,"
                      "aster570_400m_worse_than_undamped\n",
                      0),
            0u)
      << csv;
  EXPECT_EQ(csv.find("\nbase,aster570_400m,span clamp "), csv.find('\n')) << "the base design first, as its file gives it";
  EXPECT_NE(csv.find(",0,0.856,1,"), std::string::npos) << csv;
  EXPECT_NE(r.out.find("\"governing_span\": \"aster570_400m\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"governing_place\": \"span clamp "), std::string::npos) << r.out;
  const int rows = static_cast<int>(std::count(csv.begin(), csv.end(), '\n')) - 1;
  EXPECT_EQ(rows, static_cast<int>(json_number(r.out, "evaluations")));
  EXPECT_GE(rows, 1 + kSamples + 1);
  const std::string best = read_text(dir / "best.toml");
  EXPECT_NE(best.find("# position = "), std::string::npos) << best;
  EXPECT_NE(best.find("[[arm]]\nname = \"right\""), std::string::npos) << best;
  EXPECT_LE(json_number_after(r.out, "best", "objective"), json_number_after(r.out, "base", "objective"));
  EXPECT_NE(r.err.find("design: " + std::to_string(rows) + " candidates in "), std::string::npos) << r.err;

  // best.toml is the optimum rounded to build (3 significant digits), feasible here:
  // placed where the rounded design puts it, through `stockbridge span`, the same
  // largest stress over the endurance limit as the rounded design's, to 1e-9.
  EXPECT_EQ(json_number(r.out, "round_digits"), 3.0);
  for (const char* name : {"arm.left.mass", "position"}) {
    const double optimum = json_number_after(r.out, "best", name), rounded = json_number_after(r.out, "rounded", name);
    EXPECT_NEAR(rounded, optimum, 0.005 * optimum) << name;
    EXPECT_EQ(std::stod(fmt_3g(rounded)), rounded) << name << " has at most 3 significant digits";
  }
  EXPECT_NE(best.find("mass = " + fmt_3g(json_number_after(r.out, "rounded", "arm.left.mass")) + "   # kg"), std::string::npos)
      << best;
  EXPECT_NE(best.find("the optimum itself"), std::string::npos) << best;
  std::string span = read_text(kDesignExamples + "aster570_400m.toml");
  span.replace(span.find("file = \"sauter2003.toml\""), 24, "file = \"best.toml\"");
  const double position = json_number_after(r.out, "rounded", "position_m");
  span.replace(span.find("position = 1.0"), 14, "position = " + exact(position));
  std::ofstream(dir / "best_span.toml") << span;
  const CliResult s = run_cli("span best_span.toml --points " + std::to_string(kPoints) + " --json -o span.csv", dir);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const double ratio = json_number(s.out, "max_stress_fymax_mpa") / json_number(s.out, "endurance_limit_mpa");
  EXPECT_NEAR(ratio, json_number_after(r.out, "rounded", "objective"), 1e-9 * ratio);
}

TEST(DesignCli, RoundDigitsOutsideOneToFifteenIsRefusedBeforeAnythingIsWritten) {
  const auto dir = study_folder("design-round-digits", small_study());
  const CliResult r = run_cli("design study.toml --round-digits 0 -o designs.csv --best best.toml", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("round_digits = 0"), std::string::npos) << r.err;
  EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "designs.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "best.toml"));
}

TEST(DesignCli, ThreadsAndMpiRanksGiveTheSameDesigns) {
  const auto dir = study_folder("design-threads", small_study());
  ASSERT_EQ(run_cli("design study.toml --threads 2 -o two.csv --best two.toml", dir).exit_code, 0);
#ifdef STOCKBRIDGE_TEST_MPIRUN
  // One rank on one thread, and two ranks.
  for (const int ranks : {1, 2}) {
    const std::string out = "ranks" + std::to_string(ranks);
    const std::string command = "cd '" + dir.string() + "' && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 '" +
                                STOCKBRIDGE_TEST_MPIRUN + "' --oversubscribe -np " + std::to_string(ranks) + " '" +
                                STOCKBRIDGE_CLI + "' design study.toml --quiet -o " + out + ".csv --best " + out +
                                ".toml > " + out + ".log 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir / (out + ".log"));
    EXPECT_EQ(read_text(dir / (out + ".csv")), read_text(dir / "two.csv")) << ranks << " ranks";
    EXPECT_EQ(read_text(dir / (out + ".toml")), read_text(dir / "two.toml")) << ranks << " ranks";
    EXPECT_NE(read_text(dir / (out + ".log")).find("on " + std::to_string(ranks) + " rank(s) x 1 thread(s)"),
              std::string::npos);
  }
#else
  // Built without MPI: one thread against two.
  ASSERT_EQ(run_cli("design study.toml --threads 1 -o one.csv --best one.toml", dir).exit_code, 0);
  EXPECT_EQ(read_text(dir / "one.csv"), read_text(dir / "two.csv"));
  EXPECT_EQ(read_text(dir / "one.toml"), read_text(dir / "two.toml"));
#endif
}

TEST(DesignCli, AStudyWithNoFeasibleCandidateSaysSoAndExits3) {
  std::string text = small_study();
  text.replace(text.find("total_mass_max = 4.0"), 20, "total_mass_max = 1.0");
  const auto dir = study_folder("design-infeasible", text);
  const CliResult r = run_cli("design study.toml -o designs.csv --best best.toml", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.out.find("best: none of the " + std::to_string(1 + kSamples) + " candidates is feasible"), std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find("design: no candidate is feasible (designs.csv written, best.toml not)"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "designs.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "best.toml"));
}

// A candidate that cannot be built is listed on stderr with the reason, apart from
// those that did not converge (as the span command lists its points): here cables
// longer than twice the mirror method's specimen (mirror_length 0.3 m), which make
// the candidate damper invalid.
TEST(DesignCli, CandidatesThatAreNotValidAreListedWithTheReason) {
  std::string damper = read_text(kDesignExamples + "sauter2003.toml");
  for (std::size_t at = damper.find("sections = 40"); at != std::string::npos; at = damper.find("sections = 40", at + 1)) {
    damper.insert(at, "mirror_length = 0.3\n");
    at += 20;
  }
  const std::string study = "damper = \"damper.toml\"\nspans = [\"" + kDesignExamples +
                            "aster570_400m.toml\"]\nsamples = 4\npolish = 0\npoints = " + std::to_string(kPoints) +
                            "\nseed = 3\n"
                            "[[variable]]\nname = \"arm.left.cable.length\"\nmin = 0.1\nmax = 0.9\n"
                            "[[tie]]\nname = \"arm.right.cable.length\"\nequals = \"arm.left.cable.length\"\n";
  const auto dir = study_folder("design-unconverged", study);
  std::ofstream(dir / "damper.toml") << damper;
  const CliResult r = run_cli("design study.toml --quiet -o designs.csv --best best.toml", dir);
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.err;
  const std::string csv = read_text(dir / "designs.csv");
  int unconverged = 0;
  // converged and feasible 0, the span's figures empty
  for (std::size_t at = csv.find(",0,0,,,,,\n"); at != std::string::npos; at = csv.find(",0,0,,,,,\n", at + 1)) {
    ++unconverged;
  }
  ASSERT_GT(unconverged, 0) << csv;
  EXPECT_NE(r.err.find("design: " + std::to_string(unconverged) +
                       " candidate(s) not valid, not evaluated (converged = 0, feasible = 0 in designs.csv):\n  sample "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("did not converge"), std::string::npos) << r.err;
  int reasons = 0;
  const std::string reason = "the candidate damper is not valid: ";
  for (std::size_t at = r.err.find(reason); at != std::string::npos; at = r.err.find(reason, at + 1)) ++reasons;
  EXPECT_EQ(reasons, unconverged) << r.err;
}

struct BadStudy {
  const char* name;
  std::string from, to;  ///< replaced in the small study
  const char* expected;   ///< in the one line
};

TEST(DesignCli, BadStudiesAreOneLineAndWriteNothing) {
  const BadStudy cases[] = {
      {"unknown path", "name = \"arm.left.mass\"", "name = \"arm.left.mas\"",
       "study.toml:9: variable[0].name = \"arm.left.mas\": names no number of the damper"},
      {"min above max", "min = 0.5\nmax = 1.5", "min = 1.5\nmax = 0.5", "variable[0].max = 0.5: expected a value > min = 1.5"},
      {"tie to nothing", "equals = \"arm.left.mass\"", "equals = \"arm.left.inertia\"",
       "tie[0].equals = \"arm.left.inertia\": expected the name of a damper [[variable]]"},
      {"negative budget", "total_mass_max = 4.0", "total_mass_max = -4.0", "constraints.total_mass_max = -4"},
      {"missing span", "aster570_400m.toml\"]", "nowhere.toml\"]", "study.toml:2: spans: \""},
      {"unknown key", "seed = 3", "sed = 3", "sed"},
      {"life without a climate", "seed = 3", "seed = 3\nobjective = \"lifetime\"", "expected max_stress or life"},
  };
  for (const BadStudy& c : cases) {
    SCOPED_TRACE(c.name);
    std::string text = small_study();
    ASSERT_NE(text.find(c.from), std::string::npos);
    text.replace(text.find(c.from), c.from.size(), c.to);
    const auto dir = study_folder("design-bad", text);
    const CliResult r = run_cli("design study.toml -o designs.csv --best best.toml", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "designs.csv"));
    EXPECT_FALSE(std::filesystem::exists(dir / "best.toml"));
  }
}

}  // namespace
}  // namespace stockbridge::testing

namespace stockbridge::testing {
namespace {

/// Runs the study in `dir` and stops it with `signal` once the journal holds `records` candidates.
int design_run_stopped(const std::filesystem::path& dir, int signal, int records) {
  return run_cli_stopped("design study.toml -o designs.csv --best best.toml", dir, dir / "designs.csv.journal", records,
                         signal);
}

// Every candidate is journaled as it completes: a study killed midway, or stopped
// with Ctrl-C (status 130, nothing but the journal written), resumed with --resume
// evaluates only what is missing and writes the same files as an uninterrupted run.
TEST(DesignCli, AnInterruptedStudyResumesToTheSameDesign) {
  const auto whole = study_folder("design-whole", small_study());
  ASSERT_EQ(run_cli("design study.toml --quiet -o designs.csv --best best.toml", whole).exit_code, 0);
  const int all = journal_records(whole / "designs.csv.journal");
  ASSERT_GE(all, 1 + kSamples);

  const auto killed = study_folder("design-killed", small_study());
  ASSERT_TRUE(WIFSIGNALED(design_run_stopped(killed, SIGKILL, 2))) << "the study ended before it was killed";
  EXPECT_FALSE(std::filesystem::exists(killed / "designs.csv"));
  const CliResult resumed = run_cli("design study.toml --resume -o designs.csv --best best.toml", killed);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("design: resuming: "), std::string::npos) << resumed.err;
  EXPECT_EQ(read_text(killed / "designs.csv"), read_text(whole / "designs.csv"));
  EXPECT_EQ(read_text(killed / "best.toml"), read_text(whole / "best.toml"));

  const auto stopped = study_folder("design-ctrl-c", small_study());
  const int status = design_run_stopped(stopped, SIGINT, 1);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << read_text(stopped / "run.err");
  EXPECT_NE(read_text(stopped / "run.err").find("run again with --resume"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(stopped / "designs.csv"));
  EXPECT_FALSE(std::filesystem::exists(stopped / "best.toml"));
  const CliResult again = run_cli("design study.toml --resume --quiet -o designs.csv --best best.toml", stopped);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(read_text(stopped / "designs.csv"), read_text(whole / "designs.csv"));
  // A finished study resumed evaluates nothing again.
  const CliResult done = run_cli("design study.toml --resume -o designs.csv --best best.toml", whole);
  ASSERT_EQ(done.exit_code, 0) << done.err;
  EXPECT_NE(done.err.find(std::to_string(all) + " recalled from the journal"), std::string::npos) << done.err;
  EXPECT_EQ(journal_records(whole / "designs.csv.journal"), all);
}

TEST(DesignCli, AJournalOfAnotherStudyIsRefused) {
  const auto dir = study_folder("design-other-journal", small_study());
  std::ofstream(dir / "designs.csv.journal") << "stockbridge design journal 0000000000000000\n";
  const CliResult r = run_cli("design study.toml --resume -o designs.csv --best best.toml", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_lines(), 1) << r.err;
  EXPECT_NE(r.err.find("designs.csv.journal was written for other inputs"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stockbridge::testing
