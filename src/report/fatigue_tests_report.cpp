#include "stockbridge/report/fatigue_tests_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "report_parts.hpp"
#include "stockbridge/report/svg_chart.hpp"

namespace stockbridge::report {

namespace {

/// The cycles axis's ends: a decade beyond the tests on each side.
std::pair<double, double> fatigue_cycles_range(const measurements::FatigueTestsResult& r) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const measurements::FatigueTest& t : r.tests) lo = std::min(lo, t.cycles), hi = std::max(hi, t.cycles);
  return {std::pow(10.0, std::floor(std::log10(lo))), std::pow(10.0, std::ceil(std::log10(hi)))};
}

Chart fatigue_sn_chart(const measurements::FatigueTestsResult& r) {
  Chart chart("S-N: the tests, the fit and the Safe Border Line", Axis("cycles N", true),
              Axis("Poffenberger-Swart stress, zero-to-peak (MPa)", true));
  Series failed{"failures", {}, {}, LineStyle::markers, 0};
  Series runout{"runouts (censored)", {}, {}, LineStyle::ring, 0};
  Series below{"failures below the Safe Border Line", {}, {}, LineStyle::square, 3};
  for (std::size_t i = 0; i < r.tests.size(); ++i) {
    Series& s = r.tests[i].failed ? failed : runout;
    s.x.push_back(r.tests[i].cycles);
    s.y.push_back(r.points[i].stress / 1e6);
    if (r.points[i].below_sbl) below.x.push_back(r.tests[i].cycles), below.y.push_back(r.points[i].stress / 1e6);
  }
  const auto [n_lo, n_hi] = fatigue_cycles_range(r);
  const measurements::BasquinFit& f = r.fit;
  Series mean{fmt::format("Basquin fit log10 N = {:.3f} {:+.3f} log10 sigma", f.a, f.b), {}, {}, LineStyle::solid, 1};
  Series design{fmt::format("design curve (mean - 2 s, s = {:.3f})", f.scatter), {}, {}, LineStyle::dashed, 1};
  constexpr int kSamples = 41;
  for (int k = 0; k < kSamples; ++k) {
    const double n = n_lo * std::pow(n_hi / n_lo, static_cast<double>(k) / (kSamples - 1));
    if (f.b < 0.0) {
      mean.x.push_back(n), mean.y.push_back(std::pow(10.0, (std::log10(n) - f.a) / f.b));
      design.x.push_back(n), design.y.push_back(std::pow(10.0, (std::log10(n) - f.design_a()) / f.b));
    }
  }
  chart.series = {failed, runout};
  if (!below.x.empty()) chart.series.push_back(below);
  chart.series.push_back(mean);
  chart.series.push_back(design);
  std::set<int> layers;
  for (const measurements::FatigueTest& t : r.tests) layers.insert(t.conductor.aluminium_layers == 1 ? 1 : 2);
  int colour = 2;
  for (int n : layers) {
    const span::SnCurve sbl = span::safe_border_curve(n);
    Series line{sbl.name(), {}, {}, LineStyle::dotted, colour++};
    for (int k = 0; k < kSamples; ++k) {
      const double cycles = n_lo * std::pow(n_hi / n_lo, static_cast<double>(k) / (kSamples - 1));
      line.x.push_back(cycles), line.y.push_back(sbl.endurance_limit(cycles) / 1e6);
    }
    chart.series.push_back(line);
  }
  return chart;
}

}  // namespace

std::string fatigue_tests_report(const requests::FatigueTestsOutcome& outcome, const ReportContext& context) {
  const measurements::FatigueTestsResult& r = outcome.result;
  const measurements::BasquinFit& f = r.fit;
  using parts::number;
  std::set<std::string> conductors;
  for (const measurements::FatigueTest& t : r.tests) conductors.insert(t.conductor_name);
  std::string names;
  for (const std::string& c : conductors) names += (names.empty() ? "" : ", ") + c;
  HtmlPage page({"Conductor fatigue tests: " + names, context.generated_at, context.command});
  const std::size_t below = r.below_sbl.size();
  page.verdict(below > 0 ? "failures below the Safe Border Line" : "above the Safe Border Line",
               below > 0 ? fmt::format("{} of {} failures ({} %) came before the CIGRE Safe Border Line's cycles: it is "
                                       "not a safe bound for these tests",
                                       below, f.failures, number(100.0 * r.below_sbl_fraction(), 3))
                         : fmt::format("every one of the {} failures came after the Safe Border Line's cycles", f.failures),
               below > 0 ? Tone::bad : Tone::good);
  page.key_figures({{"Basquin a", fmt::format("{} ± {}", number(f.a, 5), number(f.a_standard_error, 2))},
                    {"Basquin b", fmt::format("{} ± {}", number(f.b, 4), number(f.b_standard_error, 2))},
                    {"scatter s (log10 N)", fmt::format("{} ± {}", number(f.scatter, 3), number(f.scatter_standard_error, 2))},
                    {"design a (a - 2 s)", number(f.design_a(), 5)},
                    {"tests", fmt::format("{} failures, {} runouts", f.failures, f.runouts)},
                    {"below the Safe Border Line", fmt::format("{} of {} failures", below, f.failures)}});
  page.section("Tests");
  page.facts({{"file", outcome.file},
              {"conductors", names + (outcome.conductor ? fmt::format(" (the rows of {} kept)", *outcome.conductor) : "")},
              {"stress", "Poffenberger-Swart sigma = K(T) Yb, Yb peak-to-peak 89 mm from the clamp, zero-to-peak"},
              {"fit", fmt::format("log10 N = a + b log10 sigma_MPa, normal scatter s in log10 N, runouts right-censored, "
                                  "maximum likelihood ({} Newton steps, log-likelihood {}); standard errors from the "
                                  "observed information",
                                  f.iterations, number(f.log_likelihood, 6))},
              {"design curve", fmt::format("log10 N = {} {:+.4f} log10 sigma_MPa (the mean minus 2 s, about the 2.3 % "
                                           "quantile)",
                                           number(f.design_a(), 5), f.b)}});
  page.figure(svg(fatigue_sn_chart(r)),
              "Failures (dots) and runouts (rings, censored at their cycles) at their Poffenberger-Swart stress; the "
              "censored Basquin fit, its design curve, and the Safe Border Line of each layer count present; failures "
              "before the Safe Border Line's cycles squared.");
  page.section("The tests");
  std::vector<std::vector<std::string>> rows;
  std::vector<Tone> tones;
  for (std::size_t i = 0; i < r.tests.size(); ++i) {
    const measurements::FatigueTest& t = r.tests[i];
    const measurements::FatigueTestPoint& p = r.points[i];
    rows.push_back({t.test, t.conductor_name, number(t.tension / 1e3, 4), number(1e3 * t.yb_pp, 4), number(t.cycles, 4),
                    t.failed ? "failed" : "runout", number(p.stress / 1e6, 4), number(p.microstrain_pp, 4),
                    number(p.sbl_cycles, 4), p.below_sbl ? "below" : ""});
    tones.push_back(p.below_sbl ? Tone::bad : Tone::neutral);
  }
  page.table({"test", "conductor", "tension (kN)", "Yb pp (mm)", "cycles", "", "stress (MPa)", "microstrain pp",
              "SBL cycles", "SBL"},
             rows, tones);
  page.section("Assumptions");
  page.list({"Yb is the peak-to-peak displacement 89 mm from the clamp's last point of contact (IEEE 1966), as the "
             "benches measure it; K(T) uses the catalogue's (or the conductor file's) EI_min, outer wire and modulus.",
             "A runout (failed = false) tells only that the conductor lasts longer: the fit censors it at its cycles, "
             "never counts it as a failure.",
             "The scatter is normal in log10 N and the same at every stress; the design curve (mean - 2 s) lies below "
             "about 97.7 % of the failures the fit describes.",
             "The Safe Border Line is CIGRE's for one aluminium layer or several; a failure below it counts when its "
             "cycles fall short of the line's at its stress."});
  page.section("Warnings");
  page.list(context.warnings, true);
  return page.html();
}

}  // namespace stockbridge::report
