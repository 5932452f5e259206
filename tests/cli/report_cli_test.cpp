// The HTML reports as users make them: `span --report` restates the inputs and gives
// the verdict and figures the CSV and JSON hold, references nothing outside itself;
// `impedance --report` and `datasheet` give the damper's curves and modes; a report
// option that cannot be honoured is refused before anything is written.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.hpp"
#include "support/json_number.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::testing {
namespace {

const std::string kReportExamples = std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/";

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string report_3g(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// Nothing a browser would fetch: no source, link, import or url(); the only URL the
/// SVG namespace.
void expect_self_contained(const std::string& html) {
  for (const char* fetch : {"src=", "href=", "@import", "url(", "<link", "<script", "<iframe", "<object", "<embed"}) {
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
  }
  EXPECT_EQ(count_of(html, "http"), count_of(html, "xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_FALSE(std::regex_search(html, std::regex("\\b(nan|inf)\\b"))) << "a number not trusted is never printed";
}

TEST(ReportCli, ASpanReportRestatesTheInputsAndGivesTheVerdictAndFiguresOfTheRun) {
  const auto dir = scratch_directory("report-span");
  const std::string points = std::to_string(scaled(40, 12));
  const CliResult r = run_cli("span '" + kReportExamples + "aster570_400m.toml' --points " + points +
                                  " --json --quiet -o span.csv --report span.html",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = read_text(dir / "span.html");
  expect_self_contained(html);
  EXPECT_NE(html.find("<h1>Span energy balance: ASTER570, 400 m span</h1>"), std::string::npos);
  EXPECT_NE(html.find("--report span.html"), std::string::npos) << "the exact command";
  // The inputs: tension in its three forms, the damper and its position, laws, climate.
  for (const char* fact : {"27.8 kN = 15 % RTS; H/w = 1804 m", "damper sauter2003", "1 m from the clamp, at both ends",
                           "law cigre, Strouhal 0.185, 1 to 7 m/s", "law noiseux-1991", "Weibull wind k = 2, c = 4 m/s",
                           "CIGRE Safe Border Line at 5e+08 cycles"}) {
    EXPECT_NE(html.find(fact), std::string::npos) << fact;
  }
  // The verdict and the key figures are the run's.
  const std::size_t verdict = r.out.find("\"verdict\": \"");
  ASSERT_NE(verdict, std::string::npos);
  const std::string name = r.out.substr(verdict + 12, r.out.find('"', verdict + 12) - verdict - 12);
  EXPECT_NE(html.find("<strong>" + name + "</strong>"), std::string::npos) << name;
  EXPECT_NE(html.find(report_3g(json_number(r.out, "max_stress_fymax_mpa")) + " MPa at"), std::string::npos);
  EXPECT_NE(html.find(report_3g(json_number(r.out, "life_years")) + " years"), std::string::npos);
  EXPECT_NE(html.find("Lives are comparative"), std::string::npos);
  // Three figures, each with the wind speed on top; the stress one with microstrain and the limit.
  EXPECT_EQ(count_of(html, "<figure>"), 3u);
  EXPECT_EQ(count_of(html, ">wind speed (m/s)<"), 3u);
  EXPECT_NE(html.find(">bending strain, peak-to-peak (µε)<"), std::string::npos);
  EXPECT_NE(html.find(">endurance limit 8.73 MPa<"), std::string::npos);
}

// Points that did not converge (no balance below 0.2 D at 10 and 20 Hz) never enter
// the page's figures, life or verdict: the page says how many are missing and why.
TEST(ReportCli, PointsThatDidNotConvergeAreListedAndNeverShownAsNumbers) {
  const auto dir = scratch_directory("report-failed");
  std::ofstream(dir / "span.toml") << read_text(kReportExamples + "aster570_400m.toml")
                                   << "\n[balance]\namplitude_max_over_diameter = 0.2\n";
  std::filesystem::copy_file(kDamperExample, dir / "sauter2003.toml");
  const CliResult r = run_cli("span span.toml --no-dampers --frequencies 10,20,30,40 -o span.csv --report span.html", dir);
  ASSERT_EQ(r.exit_code, 3) << r.err;
  const std::string html = read_text(dir / "span.html");
  expect_self_contained(html);
  EXPECT_NE(html.find("<strong>unsafe</strong> the fymax stress reaches"), std::string::npos)
      << "unsafe: a converged point exceeds the limit";
  EXPECT_NE(html.find("<span>life (comparative)</span><b>unknown: 2 points missing</b>"), std::string::npos);
  EXPECT_NE(html.find("<span>points converged</span><b>2 of 4</b>"), std::string::npos);
  EXPECT_NE(html.find("<li>f = 10 Hz did not converge: no root in the range searched"), std::string::npos);
  EXPECT_NE(html.find("<li>f = 20 Hz did not converge: "), std::string::npos);
  EXPECT_NE(html.find("largest fymax stress (of the converged points)"), std::string::npos);
  // No point converged: the page is still written, its figures empty and saying so.
  const CliResult none = run_cli("span span.toml --no-dampers --frequencies 10,20 -o none.csv --report none.html", dir);
  ASSERT_EQ(none.exit_code, 3) << none.err;
  const std::string empty = read_text(dir / "none.html");
  expect_self_contained(empty);
  EXPECT_NE(empty.find("<strong>unknown</strong> 2 of 2 points did not converge"), std::string::npos);
  EXPECT_EQ(count_of(empty, "no point to show: none converged"), 3u) << "the stress, the amplitude and the powers";
}

TEST(ReportCli, AnImpedanceReportGivesEachAmplitudesCurvesAndTheModes) {
  const auto dir = scratch_directory("report-impedance");
  const CliResult r = run_cli("impedance '" + kDamperExample + "' --velocity 0.2,0.05 --fmin 5 --fmax 100 --points " +
                                  std::to_string(scaled(40, 12)) + " -o z.csv --report z.html --quiet",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = read_text(dir / "z.html");
  expect_self_contained(html);
  EXPECT_EQ(count_of(html, ">V = 0.2 m/s</text>"), 3u) << "a legend entry in each of |Z|, phase and power";
  EXPECT_EQ(count_of(html, ">V = 0.05 m/s</text>"), 3u);
  EXPECT_NE(html.find("total mass</dt><dd>2.412 kg"), std::string::npos);
  EXPECT_NE(html.find("<h2>Linear modes</h2>"), std::string::npos);
  EXPECT_NE(html.find("whole damper (clamp free)"), std::string::npos);
}

TEST(ReportCli, ADatasheetGivesTheTestVelocitiesAndTheDamperOnEachSpan) {
  const auto dir = scratch_directory("report-datasheet");
  const CliResult r = run_cli("datasheet '" + kDamperExample + "' --spans '" + kReportExamples +
                                  "aster570_400m.toml' '" + kReportExamples + "drake_300m.toml' --points " +
                                  std::to_string(scaled(40, 12)) + " --span-points " + std::to_string(scaled(30, 10)) +
                                  " -o sheet.html --quiet",
                              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = read_text(dir / "sheet.html");
  expect_self_contained(html);
  for (const char* v : {">V = 0.05 m/s</text>", ">V = 0.1 m/s</text>", ">V = 0.2 m/s</text>"}) {
    EXPECT_EQ(count_of(html, v), 3u) << v;
  }
  EXPECT_NE(html.find("<td>aster570_400m</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>drake_300m</td>"), std::string::npos);
  EXPECT_NE(html.find("sauter2003 on drake_300m: "), std::string::npos);
  EXPECT_EQ(count_of(html, "<figure>"), 3u + 2u);
}

TEST(ReportCli, AReportThatCannotBeWrittenIsRefusedBeforeAnythingIsComputed) {
  const auto dir = scratch_directory("report-refused");
  const std::string span = "span '" + kReportExamples + "aster570_400m.toml' --points 5 -o span.csv";
  for (const auto& [option, expected] :
       {std::pair<std::string, std::string>{"--report span.txt", "--report = 'span.txt': expected an HTML file name"},
        {"--report missing/span.html", "the folder 'missing' does not exist"},
        {"--report span.csv", "--report"}}) {
    const CliResult r = run_cli(span + " " + option, dir);
    EXPECT_EQ(r.exit_code, 2) << option;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(lines_of(r.err).size(), 1u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "span.csv")) << option;
  }
  // A data sheet needs the spans' damper positions, and an HTML name.
  std::ofstream(dir / "bare.toml") << "[conductor]\ntype = \"AAAC ASTER570\"\n[span]\nlength = 300\ntension_fraction = 0.2\n"
                                      "[wind]\nlaw = \"cigre\"\n[self_damping]\nlaw = \"noiseux-1991\"\n[fatigue]\ncycles = 5e8\n";
  const CliResult bare = run_cli("datasheet '" + kDamperExample + "' --spans bare.toml -o sheet.html", dir);
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("--spans bare.toml: the span file places no damper"), std::string::npos) << bare.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "sheet.html"));
  const CliResult csv = run_cli("datasheet '" + kDamperExample + "' -o sheet.csv", dir);
  EXPECT_EQ(csv.exit_code, 2);
  EXPECT_NE(csv.err.find("-o = 'sheet.csv': expected an HTML file name"), std::string::npos) << csv.err;
  const CliResult folder = run_cli("datasheet '" + kDamperExample + "' -o missing/sheet.html", dir);
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_NE(folder.err.find("-o = 'missing/sheet.html': the folder 'missing' does not exist"), std::string::npos)
      << folder.err;
}

}  // namespace
}  // namespace stockbridge::testing
