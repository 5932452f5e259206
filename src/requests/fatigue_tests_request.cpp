#include "stockbridge/requests/fatigue_tests_request.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/sn_curve_file.hpp"
#include "stockbridge/measurements/fatigue_tests_file.hpp"

namespace stockbridge::requests {

namespace {

/// Whether a row's conductor is the one asked for: the same text, or the same catalogue type.
bool fatigue_conductor_matches(const std::string& query, const std::string& given) {
  return query == given || io::conductor_type_matches(query, given);
}

}  // namespace

FatigueTestsOutcome run_fatigue_tests(const FatigueTestsRequest& request) {
  measurements::FatigueTestsFile file = measurements::read_fatigue_tests_file(request.file, request.policy);
  FatigueTestsOutcome out;
  out.file = request.file.string();
  out.conductor = request.conductor;
  out.inputs = std::move(file.inputs);
  out.warnings = std::move(file.warnings);
  std::vector<measurements::FatigueTest> tests;
  std::set<std::string> known;
  for (measurements::FatigueTest& t : file.tests) {
    known.insert(t.conductor_name);
    if (!request.conductor || fatigue_conductor_matches(*request.conductor, t.conductor_name)) tests.push_back(std::move(t));
  }
  if (tests.empty()) {
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InvalidParameter("conductor", fmt::format(" = '{}': no test of {} is of that conductor: expected one of {}",
                                                    printable(*request.conductor), out.file, list));
  }
  try {
    out.result = measurements::analyse_fatigue_tests(std::move(tests));
  } catch (const InvalidParameter& e) {  // too few failures: the file's (or the rows kept)
    throw InputError(fmt::format("{}: {}{}", out.file, e.what(),
                                 request.conductor ? fmt::format(" (the rows of {})", printable(*request.conductor)) : ""));
  }
  return out;
}

Table<FatigueTestRow> fatigue_tests_table() {
  using R = FatigueTestRow;
  using K = ColumnKind;
  return Table<R>({
      {"test", "", "the test's name", K::label, {}, [](const R& r, std::size_t) { return r.test->test; }},
      {"conductor", "", "the conductor as the file names it (a catalogue type or a conductor file)", K::label, {},
       [](const R& r, std::size_t) { return r.test->conductor_name; }},
      {"tension_n", "N", "the test's tension", K::number, [](const R& r, std::size_t) { return r.test->tension; }, {}},
      {"yb_pp_mm", "mm", "Yb, the peak-to-peak displacement 89 mm from the clamp", K::number,
       [](const R& r, std::size_t) { return 1e3 * r.test->yb_pp; }, {}},
      {"cycles", "", "the cycles reached: to the failure, or where a runout stopped", K::number,
       [](const R& r, std::size_t) { return r.test->cycles; }, {}},
      {"failed", "", "1: the conductor broke; 0: a runout (censored in the fit)", K::flag,
       [](const R& r, std::size_t) { return r.test->failed ? 1.0 : 0.0; }, {}},
      {"stress_ps_mpa", "MPa", "the Poffenberger-Swart stress K(T) Yb, zero-to-peak", K::number,
       [](const R& r, std::size_t) { return megapascal_of(r.point->stress); }, {}},
      {"microstrain_pp", "microstrain", "the outer wires' peak-to-peak bending strain 2 sigma / E_a", K::number,
       [](const R& r, std::size_t) { return r.point->microstrain_pp; }, {}},
      {"sbl_cycles", "", "the CIGRE Safe Border Line's cycles at that stress, for the conductor's aluminium layers",
       K::number, [](const R& r, std::size_t) { return r.point->sbl_cycles; }, {}},
      {"below_sbl", "", "1: a failure before the Safe Border Line's cycles", K::flag,
       [](const R& r, std::size_t) { return r.point->below_sbl ? 1.0 : 0.0; }, {}},
  });
}

TableValues fatigue_tests_values(const measurements::FatigueTestsResult& result) {
  std::vector<FatigueTestRow> rows;
  for (std::size_t i = 0; i < result.tests.size(); ++i) rows.push_back({&result.tests[i], &result.points[i]});
  return fatigue_tests_table().values(rows);
}

std::string fatigue_tests_curve_name(const FatigueTestsOutcome& outcome) {
  std::set<std::string> conductors;
  for (const measurements::FatigueTest& t : outcome.result.tests) conductors.insert(t.conductor_name);
  const std::string what = conductors.size() == 1 ? *conductors.begin() : fmt::format("{} conductors'", conductors.size());
  return fmt::format("{} fatigue tests, mean - 2 s", what);
}

std::string fatigue_tests_curve_toml(const FatigueTestsOutcome& outcome) {
  const measurements::SnTable table = measurements::design_curve_table(outcome.result.fit);
  const measurements::BasquinFit& f = outcome.result.fit;
  return io::sn_curve_toml(fatigue_tests_curve_name(outcome),
                           fmt::format("{}{}: censored Basquin fit log10 N = {:.6g} {:+.6g} log10 sigma_MPa, s = {:.4g} "
                                       "({} failures, {} runouts); design curve a - 2 s = {:.6g}",
                                       outcome.file, outcome.conductor ? " (" + *outcome.conductor + ")" : "", f.a, f.b,
                                       f.scatter, f.failures, f.runouts, f.design_a()),
                           table.stress_mpa, table.cycles);
}

io::JsonObject fatigue_tests_summary(const FatigueTestsOutcome& outcome) {
  const measurements::FatigueTestsResult& r = outcome.result;
  const measurements::BasquinFit& f = r.fit;
  std::vector<std::string> below;
  for (std::size_t i : r.below_sbl) below.push_back(r.tests[i].test);
  io::JsonObject fit;
  fit.add("a", f.a)
      .add("b", f.b)
      .add("scatter", f.scatter)
      .add("a_standard_error", f.a_standard_error)
      .add("b_standard_error", f.b_standard_error)
      .add("scatter_standard_error", f.scatter_standard_error)
      .add("failures", f.failures)
      .add("runouts", f.runouts)
      .add("log_likelihood", f.log_likelihood)
      .add("iterations", f.iterations)
      .add("design_a", f.design_a())
      .add("design_b", f.b)
      .add("below_sbl", io::JsonObject()
                            .add("count", static_cast<int>(r.below_sbl.size()))
                            .add("fraction", r.below_sbl_fraction())
                            .add("tests", below));
  std::set<int> layers;
  for (const measurements::FatigueTest& t : r.tests) layers.insert(t.conductor.aluminium_layers == 1 ? 1 : 2);
  std::vector<io::JsonObject> lines;
  for (int n : layers) {
    const span::SnCurve curve = span::safe_border_curve(n);
    std::vector<io::JsonObject> branches;
    for (const span::SnBranch& b : curve.branches()) {
      branches.push_back(io::JsonObject().add("a", b.a).add("b", b.b).add("until", b.until));
    }
    lines.push_back(io::JsonObject().add("aluminium_layers", n).add("name", curve.name()).add("branches", branches));
  }
  io::JsonObject json;
  json.add("file", outcome.file);
  if (outcome.conductor) {
    json.add("conductor", *outcome.conductor);
  } else {
    json.add_null("conductor");
  }
  json.add("tests", static_cast<int>(r.tests.size())).add("fit", fit).add("safe_border_lines", lines);
  return json;
}

}  // namespace stockbridge::requests
