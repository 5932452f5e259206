// The reports' charts and pages: nice ticks, curves broken where a value is missing
// (a point that did not converge is never drawn), secondary axes placed by the
// primary scale, user text escaped, and a page that references nothing outside itself.

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/report/html_page.hpp"
#include "stockbridge/report/svg_chart.hpp"

namespace stockbridge::report {
namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ChartTicks, LinearTicksAreOneTwoOrFiveTimesAPowerOfTenAndCoverTheRange) {
  EXPECT_EQ(ticks(0.0, 10.0, false), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(ticks(0.0, 1.0, false), (std::vector<double>{0, 0.2, 0.4, 0.6000000000000001, 0.8, 1}));
  const std::vector<double> t = ticks(-3.0, 47.0, false);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 40.0);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_DOUBLE_EQ(t[i] - t[i - 1], 10.0);
}

TEST(ChartTicks, LogTicksAreDecadesWithTwoAndFiveBetweenWhenTheRangeIsShort) {
  EXPECT_EQ(ticks(5.0, 100.0, true), (std::vector<double>{5, 10, 20, 50, 100}));
  EXPECT_EQ(ticks(1e-4, 10.0, true), (std::vector<double>{1e-4, 1e-3, 1e-2, 1e-1, 1, 10}));
  // Less than a decade: linear ticks, still positive.
  const std::vector<double> t = ticks(6.0, 41.0, true);
  EXPECT_GE(t.size(), 3u);
  EXPECT_TRUE(std::all_of(t.begin(), t.end(), [](double v) { return v >= 6.0 && v <= 41.0; }));
}

// A band of the aeolian frequencies (6.5 to 46 Hz, less than a decade) still gets
// four labels or more: 1, 2 and 5 give two (10, 20), 1, 2, 3 and 5 three, so the
// finer set labels it.
TEST(ChartTicks, ANarrowLogRangeGetsAtLeastFourTicks) {
  EXPECT_EQ(ticks(6.5, 46.0, true), (std::vector<double>{8, 10, 15, 20, 30, 40}));
  EXPECT_EQ(ticks(12.0, 80.0, true), (std::vector<double>{15, 20, 30, 40, 50, 60, 80}));
  // Where 1, 2 and 5 give four already, they are kept; decades where they suffice.
  EXPECT_EQ(ticks(5.0, 100.0, true), (std::vector<double>{5, 10, 20, 50, 100}));
  EXPECT_EQ(ticks(2.0, 60.0, true), (std::vector<double>{2, 5, 10, 20, 50}));
  EXPECT_EQ(ticks(1e-4, 10.0, true), (std::vector<double>{1e-4, 1e-3, 1e-2, 1e-1, 1, 10}));
  EXPECT_EQ(ticks(1.0, 1e10, true), (std::vector<double>{1, 100, 1e4, 1e6, 1e8, 1e10}));  // every other decade
}

Chart two_curves() {
  Chart chart("A title", Axis("frequency (Hz)", true), Axis("stress (MPa)"));
  chart.series.push_back({"with dampers", {1, 2, 3, 4, 5}, {1, 2, NAN, 4, 5}, LineStyle::solid, 0});
  chart.series.push_back({"without dampers", {1, 2, 3, 4, 5}, {2, 3, 4, 5, 6}, LineStyle::dashed, 1});
  return chart;
}

TEST(Chart, AMissingValueBreaksTheCurveAndIsNeverDrawn) {
  const std::string s = svg(two_curves());
  // The first series in two pieces (1-2 and 4-5), the second whole.
  EXPECT_EQ(occurrences(s, "<polyline"), 3u);
  EXPECT_EQ(occurrences(s, "nan"), 0u);
  EXPECT_EQ(occurrences(s, "inf"), 0u);
  EXPECT_NE(s.find(">with dampers<"), std::string::npos);
  EXPECT_NE(s.find(">without dampers<"), std::string::npos);
}

TEST(Chart, ALonePointBetweenGapsIsADot) {
  Chart chart("t", Axis("x"), Axis("y"));
  chart.series.push_back({"", {1, 2, 3}, {NAN, 2, NAN}});
  const std::string s = svg(chart);
  EXPECT_EQ(occurrences(s, "<polyline"), 0u);
  EXPECT_EQ(occurrences(s, "<circle"), 1u);
}

/// The x pixel of the tick labelled `label` on the top axis (`top`) or the bottom one.
double label_x(const std::string& svg_text, const std::string& label, bool top) {
  const std::regex text("<text x=\"([0-9.]+)\" y=\"([0-9.]+)\" text-anchor=\"middle\">" + label + "</text>");
  double x = NAN, y = top ? INFINITY : -INFINITY;
  for (auto it = std::sregex_iterator(svg_text.begin(), svg_text.end(), text); it != std::sregex_iterator(); ++it) {
    const double yi = std::stod((*it)[2]);
    if (top ? yi < y : yi > y) {
      y = yi;
      x = std::stod((*it)[1]);
    }
  }
  EXPECT_FALSE(std::isnan(x)) << label;
  return x;
}

TEST(Chart, TheTopAxisIsTheBottomAxisScaled) {
  // Wind speed = 0.5 * frequency on a log axis: the 10 m/s tick sits over 20 Hz.
  Chart chart("t", Axis("frequency (Hz)", true), Axis("y"));
  chart.series.push_back({"", {5, 100}, {1, 2}});
  chart.top = SecondaryAxis{"wind speed (m/s)", 0.5};
  const std::string s = svg(chart);
  const double hz20 = label_x(s, "20", false);
  const double ms10 = label_x(s, "10", true);
  EXPECT_GT(std::abs(label_x(s, "10", false) - ms10), 100.0);  // 10 Hz is elsewhere
  EXPECT_NEAR(ms10, hz20, 0.11);
  EXPECT_NE(s.find(">wind speed (m/s)<"), std::string::npos);
}

TEST(Chart, AChartWithNothingToShowSaysSoAndMismatchedSeriesAreRefused) {
  // Nothing positive on a log axis, or every point missing (none converged): axes and a note, no curve.
  for (const std::vector<double>& y : {std::vector<double>{0, -1}, std::vector<double>{NAN, NAN}}) {
    Chart chart("t", Axis("x"), Axis("y", true));
    chart.series.push_back({"", {1, 2}, y});
    const std::string s = svg(chart);
    EXPECT_NE(s.find("no point to show: none converged"), std::string::npos);
    EXPECT_EQ(occurrences(s, "<polyline"), 0u);
    EXPECT_EQ(occurrences(s, "<circle"), 0u);
  }
  Chart chart("t", Axis("x"), Axis("y"));
  chart.series.push_back({"", {1, 2}, {1, 2}});
  EXPECT_EQ(svg(chart).find("no point to show"), std::string::npos);
  chart.series = {{"", {1, 2}, {1}}};
  EXPECT_THROW(svg(chart), InvalidParameter);
}

/// The points="..." lists of the chart's elements `tag` ("polygon", "polyline"), in order.
std::vector<std::string> points_of(const std::string& svg_text, const std::string& tag) {
  std::vector<std::string> lists;
  const std::regex element("<" + tag + " [^>]*points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg_text.begin(), svg_text.end(), element); it != std::sregex_iterator(); ++it) {
    lists.push_back((*it)[1]);
  }
  return lists;
}

/// The "x,y" pairs of a points list.
std::vector<std::string> pairs_of(const std::string& list) {
  std::vector<std::string> pairs;
  std::istringstream in(list);
  for (std::string pair; in >> pair;) pairs.push_back(pair);
  return pairs;
}

// A band is a filled polygon under the curves: along its high end, back along its low
// end, at the pixels the same values take as curves; broken where an end is missing.
TEST(Chart, ABandIsAPolygonAlongItsHighEndAndBackAlongItsLowEnd) {
  Chart chart("t", Axis("frequency (Hz)", true), Axis("stress (MPa)"));
  const std::vector<double> x{5, 10, 20, 30, 40};
  const std::vector<double> low{1, 2, 3, 2, 1}, high{2, 4, 6, 4, 2};
  chart.bands.push_back({"the sheet's band", x, low, high, 0});
  chart.series.push_back({"high", x, high, LineStyle::solid, 1});
  chart.series.push_back({"low", x, low, LineStyle::solid, 2});
  const std::string s = svg(chart);
  const std::vector<std::string> polygons = points_of(s, "polygon"), curves = points_of(s, "polyline");
  ASSERT_EQ(polygons.size(), 1u) << s;
  ASSERT_EQ(curves.size(), 2u) << s;
  std::vector<std::string> expected = pairs_of(curves[0]);
  std::vector<std::string> low_pairs = pairs_of(curves[1]);
  expected.insert(expected.end(), low_pairs.rbegin(), low_pairs.rend());
  EXPECT_EQ(pairs_of(polygons[0]), expected);
  EXPECT_LT(s.find("<polygon"), s.find("<polyline"));  // under the curves
  EXPECT_NE(s.find(">the sheet&#39;s band<"), std::string::npos) << s;  // in the legend

  // A missing low end at 20 Hz: two polygons of two points a side, 5-10 and 30-40 Hz.
  chart.bands[0].low[2] = NAN;
  const std::vector<std::string> broken = points_of(svg(chart), "polygon");
  ASSERT_EQ(broken.size(), 2u);
  const std::vector<std::string> high_pairs = pairs_of(curves[0]);
  EXPECT_EQ(pairs_of(broken[0]), (std::vector<std::string>{high_pairs[0], high_pairs[1], low_pairs[1], low_pairs[0]}));
  EXPECT_EQ(pairs_of(broken[1]), (std::vector<std::string>{high_pairs[3], high_pairs[4], low_pairs[4], low_pairs[3]}));
  EXPECT_EQ(occurrences(svg(chart), "nan"), 0u);
  // A lone point between gaps is no area.
  chart.bands[0].high[0] = NAN, chart.bands[0].high[4] = NAN;
  chart.bands[0].low[3] = NAN;
  EXPECT_EQ(points_of(svg(chart), "polygon").size(), 0u);
}

TEST(Chart, ABandOfMismatchedLengthsIsRefused) {
  Chart chart("stresses", Axis("x"), Axis("y"));
  chart.bands.push_back({"band", {1, 2, 3}, {1, 1}, {2, 2, 2}, 0});
  try {
    svg(chart);
    FAIL() << "accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(std::string(e.what()), "chart 'stresses': band 'band' has 3 x, 2 low and 3 high values");
  }
  chart.bands[0] = {"band", {1, 2, 3}, {1, 1, 1}, {2, 2}, 0};
  EXPECT_THROW(svg(chart), InvalidParameter);
}

TEST(Chart, CategoriesLabelTheXAxisAndIntegerAxesHaveWholeTicks) {
  Chart chart("t", Axis("span"), Axis("dampers per end"));
  chart.x_categories = {"T1-T2", "T2-T3", "T3-T4"};
  chart.series.push_back({"", {0, 1, 2}, {1, 2, 0}, LineStyle::markers});
  chart.y.integer = true;
  const std::string s = svg(chart);
  for (const char* id : {">T1-T2<", ">T2-T3<", ">T3-T4<"}) EXPECT_NE(s.find(id), std::string::npos) << id;
  EXPECT_EQ(s.find(">0.5<"), std::string::npos);
  EXPECT_EQ(s.find(">1.5<"), std::string::npos);
  EXPECT_EQ(occurrences(s, "r=\"3.2\""), 3u);
}

TEST(HtmlPage, UserTextIsEscapedAndThePageReferencesNothingOutsideItself) {
  HtmlPage page({"Span <script>alert(1)</script>", "2026-11-26 12:00 UTC", "stockbridge span 'a b.toml' -o x.csv"});
  page.verdict("safe", " because & <b>", Tone::good);
  page.facts({{"conductor", "\"ACSR\" <Drake>"}});
  page.table({"id"}, {{"<T1>"}}, {Tone::bad});
  page.figure(svg(two_curves()), "a caption with <tags>");
  page.list({"warning <1>"}, true);
  const std::string html = page.html();
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_NE(html.find("&lt;Drake&gt;"), std::string::npos);
  EXPECT_NE(html.find("&#39;a b.toml&#39;"), std::string::npos);
  // Self-contained: no source, link, import or url() to fetch; the only URL is SVG's namespace.
  for (const char* fetch : {"src=", "href=", "@import", "url(", "<link", "<iframe", "<object", "<embed"}) {
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
  }
  std::string rest = html;
  std::erase(rest, '\n');
  EXPECT_EQ(occurrences(rest, "http"), occurrences(rest, "xmlns=\"http://www.w3.org/2000/svg\""));
  // Printable: A4 pages, and no figure split across two.
  EXPECT_NE(html.find("@page { size: A4"), std::string::npos);
  EXPECT_NE(html.find("figure { margin: 0.8em 0; break-inside: avoid"), std::string::npos);
}

}  // namespace
}  // namespace stockbridge::report
