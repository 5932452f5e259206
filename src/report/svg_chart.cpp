#include "stockbridge/report/svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/report/html_page.hpp"

namespace stockbridge::report {

namespace {

constexpr double kWidth = 720.0;
constexpr double kPlotHeight = 300.0;
constexpr double kLeft = 74.0;
constexpr double kCharWidth = 6.6;  // of the 12 px labels, for layout only
constexpr std::string_view kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                         "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

/// A number as a tick label: at most four significant digits, no trailing zeros.
std::string tick_label(double v) {
  if (std::abs(v) < 1e-12) return "0";
  return fmt::format("{:.4g}", v);
}

double nice_step(double range, int wanted) {
  const double raw = range / wanted;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= raw) return m * decade;
  }
  return 10.0 * decade;
}

/// The range an axis shows: the given ends, else the data's (and a linear axis of
/// non-negative values from 0, to its outer ticks).
struct Range {
  double lo = 0.0, hi = 1.0;
};

Range axis_range(const Axis& axis, std::vector<double> values, std::string_view which) {
  std::erase_if(values, [&](double v) { return !std::isfinite(v) || (axis.log && v <= 0.0); });
  if (values.empty() && !(axis.min && axis.max)) values = axis.log ? std::vector<double>{1.0, 10.0} : std::vector<double>{0.0, 1.0};
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  Range r{axis.min.value_or(values.empty() ? 0.0 : *lo_it), axis.max.value_or(values.empty() ? 1.0 : *hi_it)};
  if (axis.log) {
    if (r.lo <= 0.0 || r.hi <= 0.0) throw InvalidParameter(fmt::format("chart: the {} axis is logarithmic and its range is not positive", which));
    if (r.hi <= r.lo) {
      r.lo /= 2.0;
      r.hi *= 2.0;
    }
    const double pad = axis.min || axis.max ? 0.0 : 0.02 * std::log10(r.hi / r.lo);
    if (!axis.min) r.lo /= std::pow(10.0, pad);
    if (!axis.max) r.hi *= std::pow(10.0, pad);
    return r;
  }
  if (r.hi <= r.lo) {
    const double half = r.lo == 0.0 ? 1.0 : 0.5 * std::abs(r.lo);
    r.lo -= half;
    r.hi += half;
  }
  if (!axis.min && r.lo >= 0.0 && r.lo < 0.5 * r.hi) r.lo = 0.0;
  const double step = nice_step(r.hi - r.lo, 5);
  if (!axis.min) r.lo = std::floor(r.lo / step + 1e-9) * step;
  if (!axis.max) r.hi = std::ceil(r.hi / step - 1e-9) * step;
  return r;
}

/// Maps a value on an axis to a pixel coordinate between p0 (at lo) and p1 (at hi).
struct Scale {
  Range range;
  bool log = false;
  double p0 = 0.0, p1 = 1.0;
  double operator()(double v) const {
    const double t = log ? std::log(v / range.lo) / std::log(range.hi / range.lo) : (v - range.lo) / (range.hi - range.lo);
    return p0 + t * (p1 - p0);
  }
  bool shows(double v) const {
    if (!std::isfinite(v) || (log && v <= 0.0)) return false;
    const double tol = 1e-9 * (log ? range.hi : std::max(std::abs(range.lo), std::abs(range.hi)));
    return v >= range.lo - tol && v <= range.hi + tol;
  }
};

std::string dash_of(LineStyle style) {
  switch (style) {
    case LineStyle::dashed: return " stroke-dasharray=\"7 4\"";
    case LineStyle::dotted: return " stroke-dasharray=\"2 3\"";
    default: return "";
  }
}

std::string_view colour_of(const Series& s, std::size_t index) {
  const std::size_t n = std::size(kPalette);
  return kPalette[(s.colour >= 0 ? static_cast<std::size_t>(s.colour) : index) % n];
}

/// The title in lines of at most `width` characters (split at spaces).
std::vector<std::string> wrap(std::string_view text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      lines.push_back(line);
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += word;
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

bool marks(LineStyle style) {
  return style == LineStyle::markers || style == LineStyle::ring || style == LineStyle::square;
}

std::string mark(LineStyle style, double px, double py, std::string_view colour) {
  switch (style) {
    case LineStyle::ring:
      return fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"7\" fill=\"none\" stroke=\"{}\" stroke-width=\"2.2\"/>",
                         px, py, colour);
    case LineStyle::square:
      return fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"11\" height=\"11\" fill=\"none\" stroke=\"{}\" "
                         "stroke-width=\"2\"/>",
                         px - 5.5, py - 5.5, colour);
    default:
      return fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.2\" fill=\"{}\"/>", px, py, colour);
  }
}

/// The curve of a series as polylines, broken where a value is missing or off the axes.
std::string curve(const Series& s, std::string_view colour, const Scale& x, const Scale& y) {
  std::string out;
  if (marks(s.style)) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!x.shows(s.x[i]) || !y.shows(s.y[i])) continue;
      out += mark(s.style, x(s.x[i]), y(s.y[i]), colour);
    }
    return out;
  }
  std::vector<std::pair<double, double>> run;
  const auto flush = [&] {
    if (run.size() == 1) {  // a lone point between gaps: a dot where it is
      out += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"2\" fill=\"{}\"/>", run[0].first, run[0].second, colour);
    } else if (run.size() > 1) {
      out += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.8\"{} points=\"", colour, dash_of(s.style));
      for (const auto& [px, py] : run) out += fmt::format("{:.1f},{:.1f} ", px, py);
      out.back() = '"';
      out += "/>";
    }
    run.clear();
  };
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (!x.shows(s.x[i]) || !y.shows(s.y[i])) {
      flush();
      continue;
    }
    run.emplace_back(x(s.x[i]), y(s.y[i]));
  }
  flush();
  return out;
}

/// The band as filled polygons, broken where an end is missing or off the axes.
std::string band_area(const Band& b, const Scale& x, const Scale& y) {
  std::string out;
  std::vector<std::size_t> run;
  const auto flush = [&] {
    if (run.size() > 1) {
      out += fmt::format("<polygon fill=\"{}\" fill-opacity=\"0.2\" stroke=\"none\" points=\"",
                         kPalette[static_cast<std::size_t>(b.colour) % std::size(kPalette)]);
      for (const std::size_t i : run) out += fmt::format("{:.1f},{:.1f} ", x(b.x[i]), y(b.high[i]));
      for (auto i = run.rbegin(); i != run.rend(); ++i) out += fmt::format("{:.1f},{:.1f} ", x(b.x[*i]), y(b.low[*i]));
      out.back() = '"';
      out += "/>";
    }
    run.clear();
  };
  for (std::size_t i = 0; i < b.x.size(); ++i) {
    if (!x.shows(b.x[i]) || !y.shows(b.low[i]) || !y.shows(b.high[i])) {
      flush();
      continue;
    }
    run.push_back(i);
  }
  flush();
  return out;
}

std::string legend_sample(const Series& s, std::string_view colour, double x, double y) {
  if (marks(s.style)) return mark(s.style, x + 12, y, colour);
  return fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"1.8\"{}/>",
                     x, y, x + 24, y, colour, dash_of(s.style));
}

}  // namespace

std::vector<double> ticks(double lo, double hi, bool log) {
  std::vector<double> out;
  if (!(hi > lo)) return {lo};
  if (log) {
    const int first = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
    const int last = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
    const int every = std::log10(hi / lo) > 8 ? 2 : 1;
    const std::vector<std::vector<double>> mantissa_sets{{1}, {1, 2, 5}, {1, 2, 3, 5}, {1, 1.5, 2, 3, 4, 5, 6, 8}};
    for (const std::vector<double>& mantissas : mantissa_sets) {
      std::vector<double> set;
      for (int d = first; d <= last; d += every) {
        for (const double m : mantissas) {
          const double v = m * std::pow(10.0, d);
          if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) set.push_back(v);
        }
      }
      if (set.size() > 12 && out.size() >= 2) break;  // the sparser set was enough
      out = std::move(set);
      if (out.size() >= 4) break;
    }
    if (out.size() >= 2) return out;
    out.clear();
  }
  const double step = nice_step(hi - lo, log ? 4 : 5);
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi * (1 + 1e-12) + 1e-12 * step; k += 1.0) {
    const double v = k * step;
    if (!log || v > 0.0) out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return out;
}

/// A colour of the heat map's scale at t in [0, 1]: from pale yellow through orange
/// and red to dark purple (readable on white, printable in grey).
std::string heat_colour(double t) {
  static constexpr double stops[][3] = {{255, 247, 188}, {254, 196, 79}, {236, 112, 20}, {204, 34, 41}, {90, 12, 90}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), 3);
  const double f = t - static_cast<double>(i);
  const auto c = [&](int k) { return static_cast<int>(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]))); };
  return fmt::format("#{:02x}{:02x}{:02x}", c(0), c(1), c(2));
}

/// The heat map's value range (log10 where log), over its shown cells.
Range heat_range(const HeatMap& h) {
  Range r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const HeatCell& c : h.cells) {
    if (!std::isfinite(c.value) || (h.log && c.value <= 0.0)) continue;
    const double v = h.log ? std::log10(c.value) : c.value;
    r.lo = std::min(r.lo, v);
    r.hi = std::max(r.hi, v);
  }
  if (!(r.hi >= r.lo)) return {0.0, 1.0};
  if (r.hi == r.lo) r.hi = r.lo + 1.0;
  return r;
}

namespace {

/// Every value the chart shows along x and along y (series, bands, reference lines,
/// heat cells); InvalidParameter for a series or band whose columns differ in length.
std::pair<std::vector<double>, std::vector<double>> shown_values(const Chart& chart) {
  std::vector<double> xs, ys;
  for (const Series& s : chart.series) {
    if (s.x.size() != s.y.size()) {
      throw InvalidParameter(fmt::format("chart '{}': series '{}' has {} x and {} y values", chart.title, s.label,
                                         s.x.size(), s.y.size()));
    }
    xs.insert(xs.end(), s.x.begin(), s.x.end());
    ys.insert(ys.end(), s.y.begin(), s.y.end());
  }
  for (const Band& b : chart.bands) {
    if (b.x.size() != b.low.size() || b.x.size() != b.high.size()) {
      throw InvalidParameter(fmt::format("chart '{}': band '{}' has {} x, {} low and {} high values", chart.title, b.label,
                                         b.x.size(), b.low.size(), b.high.size()));
    }
    ys.insert(ys.end(), b.low.begin(), b.low.end());
    ys.insert(ys.end(), b.high.begin(), b.high.end());
  }
  for (const ReferenceLine& r : chart.references) ys.push_back(r.y);
  if (chart.heat) {
    for (const HeatCell& c : chart.heat->cells) {
      xs.insert(xs.end(), {c.x_low, c.x_high});
      ys.insert(ys.end(), {c.y_low, c.y_high});
    }
  }
  return {std::move(xs), std::move(ys)};
}

/// A legend entry: a series' or a band's, where it goes (x, and the row below the axis).
struct LegendEntry {
  std::size_t index;
  bool band;
  double x, row;
};

/// The legend's entries, wrapped to the chart's width.
std::vector<LegendEntry> legend_entries(const Chart& chart) {
  std::vector<LegendEntry> entries;
  double lx = kLeft, row = 0;
  const auto add_entry = [&](std::size_t i, bool band, const std::string& label) {
    if (label.empty()) return;
    const double w = 34.0 + kCharWidth * static_cast<double>(label.size()) + 18.0;
    if (lx + w > kWidth - 10.0 && lx > kLeft) {
      lx = kLeft;
      row += 1;
    }
    entries.push_back({i, band, lx, row});
    lx += w;
  };
  for (std::size_t i = 0; i < chart.series.size(); ++i) add_entry(i, false, chart.series[i].label);
  for (std::size_t i = 0; i < chart.bands.size(); ++i) add_entry(i, true, chart.bands[i].label);
  return entries;
}

/// Where everything goes: the plot's frame, the title's lines, the tick labels'
/// band, the legend and the colour bar, and the scales of the two axes.
struct Layout {
  std::vector<std::string> title;
  bool categories = false;
  bool rotated = false;  ///< category labels turned (many of them)
  double top = 0, right = 0, bottom = 0, tick_band = 0;
  double legend_top = 0, colour_bar_top = 0, height = 0;
  Range xr, yr;
  Axis x_axis;
  std::vector<LegendEntry> entries;
};

Layout layout_of(const Chart& chart) {
  Layout l;
  const auto [xs, ys] = shown_values(chart);
  l.categories = !chart.x_categories.empty();
  l.x_axis = chart.x;
  if (l.categories) {
    l.x_axis.log = false;
    l.x_axis.min = -0.5;
    l.x_axis.max = static_cast<double>(chart.x_categories.size()) - 0.5;
  }
  l.xr = axis_range(l.x_axis, xs, "x");
  l.yr = axis_range(chart.y, ys, "y");
  l.title = wrap(chart.title, 76);
  const double title_height = 8.0 + 18.0 * static_cast<double>(l.title.size());
  l.top = title_height + (chart.top ? 44.0 : 10.0);
  l.right = chart.right ? kWidth - 74.0 : kWidth - 24.0;
  l.bottom = l.top + kPlotHeight;
  l.rotated = l.categories && chart.x_categories.size() > 12;
  std::size_t longest = 0;
  for (const std::string& c : chart.x_categories) longest = std::max(longest, c.size());
  l.tick_band = l.rotated ? 12.0 + 0.72 * kCharWidth * static_cast<double>(std::min<std::size_t>(longest, 16)) : 18.0;
  l.entries = legend_entries(chart);
  const double rows = l.entries.empty() ? 0.0 : l.entries.back().row + 1;
  l.legend_top = l.bottom + l.tick_band + 34.0;
  l.colour_bar_top = l.legend_top + 18.0 * rows + 6.0;
  l.height = l.colour_bar_top + (chart.heat ? 34.0 : 0.0);
  return l;
}

/// The grid lines and the tick labels of both primary axes (categories along x where given).
std::string grid_and_ticks(const Chart& chart, const Layout& l, const Scale& x, const Scale& y) {
  std::string out = "<g stroke=\"#e3e3e3\" stroke-width=\"1\">";
  std::string labels;
  if (l.categories) {
    const std::size_t n = chart.x_categories.size();
    const std::size_t every = n > 60 ? (n + 59) / 60 : 1;
    for (std::size_t k = 0; k < n; k += every) {
      const double px = x(static_cast<double>(k));
      out += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\"/>", px, l.top, l.bottom);
      if (l.rotated) {
        labels += fmt::format("<text transform=\"translate({:.1f},{:.1f}) rotate(-50)\" text-anchor=\"end\" font-size=\"10\">{}</text>",
                              px + 3, l.bottom + 12, escape(chart.x_categories[k]));
      } else {
        labels += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>", px, l.bottom + 16,
                              escape(chart.x_categories[k]));
      }
    }
  } else {
    for (const double t : ticks(l.xr.lo, l.xr.hi, l.x_axis.log)) {
      const double px = x(t);
      out += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\"/>", px, l.top, l.bottom);
      labels += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>", px, l.bottom + 16, tick_label(t));
    }
  }
  for (const double t : ticks(l.yr.lo, l.yr.hi, chart.y.log)) {
    if (chart.y.integer && t != std::round(t)) continue;
    const double py = y(t);
    out += fmt::format("<line x1=\"{1:.1f}\" y1=\"{0:.1f}\" x2=\"{2:.1f}\" y2=\"{0:.1f}\"/>", py, kLeft, l.right);
    labels += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>", kLeft - 6, py + 4, tick_label(t));
  }
  return out + "</g>" + labels;
}

/// The secondary axes, top and right: their own nice ticks, placed by the primary scale.
std::string secondary_axes(const Chart& chart, const Layout& l, const Scale& x, const Scale& y) {
  std::string out;
  if (chart.top && !l.categories) {
    const double s = chart.top->scale;
    out += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#444\"/>", kLeft, l.top,
                       l.right, l.top);
    for (const double t : ticks(s * l.xr.lo, s * l.xr.hi, l.x_axis.log)) {
      const double px = x(t / s);
      out += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#444\"/>"
                         "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}</text>",
                         px, l.top, l.top - 5, l.top - 9, tick_label(t));
    }
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>", 0.5 * (kLeft + l.right),
                       l.top - 27, escape(chart.top->label));
  }
  if (chart.right) {
    const double s = chart.right->scale;
    for (const double t : ticks(s * l.yr.lo, s * l.yr.hi, chart.y.log)) {
      const double py = y(t / s);
      out += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#444\"/>"
                         "<text x=\"{3:.1f}\" y=\"{4:.1f}\">{5}</text>",
                         l.right, py, l.right + 5, l.right + 8, py + 4, tick_label(t));
    }
    out += fmt::format("<text transform=\"translate({:.1f},{:.1f}) rotate(90)\" text-anchor=\"middle\">{}</text>",
                       kWidth - 14, 0.5 * (l.top + l.bottom), escape(chart.right->label));
  }
  return out;
}

/// The frame and the two axis labels.
std::string frame_and_labels(const Chart& chart, const Layout& l) {
  return fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"#444\"/>",
                     kLeft, l.top, l.right - kLeft, kPlotHeight) +
         fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>", 0.5 * (kLeft + l.right),
                     l.bottom + l.tick_band + 20, escape(chart.x.label)) +
         fmt::format("<text transform=\"translate(16,{:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>",
                     0.5 * (l.top + l.bottom), escape(chart.y.label));
}

/// The heat map's cells within the axes (`shown` set if any), and its colour bar:
/// ten steps from the least to the most.
std::string heat_map(const HeatMap& h, const Layout& l, const Scale& x, const Scale& y, bool& shown) {
  std::string out;
  const Range hr = heat_range(h);
  for (const HeatCell& c : h.cells) {
    if (!std::isfinite(c.value) || (h.log && c.value <= 0.0)) continue;
    if (!x.shows(c.x_low) || !x.shows(c.x_high) || !y.shows(c.y_low) || !y.shows(c.y_high)) continue;
    const double v = h.log ? std::log10(c.value) : c.value;
    const double px0 = x(c.x_low), px1 = x(c.x_high), py0 = y(c.y_high), py1 = y(c.y_low);
    out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\" "
                       "stroke=\"#ffffff\" stroke-width=\"0.5\"><title>{}</title></rect>",
                       px0, py0, px1 - px0, py1 - py0, heat_colour((v - hr.lo) / (hr.hi - hr.lo)),
                       escape(fmt::format("{:.4g}", c.value)));
    shown = true;
  }
  const double bar_y = l.colour_bar_top + 4.0, bar_w = 300.0;
  for (int k = 0; k < 10; ++k) {
    out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"10\" fill=\"{}\"/>",
                       kLeft + 30.0 * k, bar_y, 30.0, heat_colour((k + 0.5) / 10.0));
  }
  const auto value_at = [&](double v) { return tick_label(h.log ? std::pow(10.0, v) : v); };
  out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text><text x=\"{:.1f}\" y=\"{:.1f}\" "
                     "text-anchor=\"end\">{}</text><text x=\"{:.1f}\" y=\"{:.1f}\">{}{}</text>",
                     kLeft, bar_y + 24, value_at(hr.lo), kLeft + bar_w, bar_y + 24, value_at(hr.hi),
                     kLeft + bar_w + 12, bar_y + 10, escape(h.label), h.log ? " (colour: log scale)" : "");
  return out;
}

/// The legend: a sample of each series' line or band's fill, and its label.
std::string legend(const Chart& chart, const Layout& l) {
  std::string out;
  for (const LegendEntry& e : l.entries) {
    const double ey = l.legend_top + 18.0 * e.row;
    if (e.band) {
      const Band& b = chart.bands[e.index];
      out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"24\" height=\"10\" fill=\"{}\" fill-opacity=\"0.2\"/>",
                         e.x, ey - 9, kPalette[static_cast<std::size_t>(b.colour) % std::size(kPalette)]);
      out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>", e.x + 30, ey, escape(b.label));
      continue;
    }
    const Series& s = chart.series[e.index];
    out += legend_sample(s, colour_of(s, e.index), e.x, ey - 4);
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>", e.x + 30, ey, escape(s.label));
  }
  return out;
}

}  // namespace

std::string svg(const Chart& chart) {
  const Layout l = layout_of(chart);
  const Scale x{l.xr, l.x_axis.log, kLeft, l.right};
  const Scale y{l.yr, chart.y.log, l.bottom, l.top};
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {:.0f} {:.0f}\" width=\"100%\" role=\"img\" "
      "font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">",
      kWidth, l.height);
  out += fmt::format("<title>{}</title>", escape(chart.title));
  for (std::size_t i = 0; i < l.title.size(); ++i) {
    out += fmt::format("<text x=\"{:.0f}\" y=\"{:.0f}\" font-size=\"14\" font-weight=\"bold\">{}</text>", kLeft,
                       20.0 + 18.0 * static_cast<double>(i), escape(l.title[i]));
  }
  out += grid_and_ticks(chart, l, x, y);
  out += secondary_axes(chart, l, x, y);
  out += frame_and_labels(chart, l);
  // The heat map, bands, reference lines, then the curves on top.
  bool shown = false;
  if (chart.heat) out += heat_map(*chart.heat, l, x, y, shown);
  for (const Band& b : chart.bands) out += band_area(b, x, y);
  for (const ReferenceLine& r : chart.references) {
    if (!y.shows(r.y)) continue;
    out += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#000\" stroke-width=\"1.2\" "
                       "stroke-dasharray=\"9 3 2 3\"/><text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\" font-size=\"11\">{}</text>",
                       kLeft, y(r.y), l.right, y(r.y), l.right - 4, y(r.y) - 4, escape(r.label));
  }
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    out += curve(chart.series[i], colour_of(chart.series[i], i), x, y);
    const Series& s = chart.series[i];
    for (std::size_t k = 0; k < s.x.size() && !shown; ++k) shown = x.shows(s.x[k]) && y.shows(s.y[k]);
  }
  if (!shown) {
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" font-size=\"14\" fill=\"#8a3b00\">"
                       "no point to show: none converged</text>",
                       0.5 * (kLeft + l.right), 0.5 * (l.top + l.bottom));
  }
  out += legend(chart, l);
  out += "</svg>";
  return out;
}

}  // namespace stockbridge::report
