#pragma once
// Charts as inline SVG, for reports that must open without a network: x-y curves
// on linear or logarithmic axes, reference lines (an endurance limit), markers,
// a legend below the plot (it never hides a curve), and secondary axes that carry
// a quantity proportional to an axis's (the wind speed on top of a frequency axis,
// microstrain beside a stress axis). A NaN in a series breaks its curve: a point
// that did not converge is left out, never drawn as a number.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace stockbridge::report {

/// How a series is drawn: a line, or a mark per point (a dot; a ring and a hollow
/// square, larger, to pick out a point among dots).
enum class LineStyle { solid, dashed, dotted, markers, ring, square };

struct Series {
  std::string label;  ///< in the legend; empty: not listed
  std::vector<double> x, y;
  LineStyle style = LineStyle::solid;
  int colour = -1;  ///< an index in the palette; -1: the series' own index
};

/// A shaded band between two curves over the same x (an uncertainty's low and high
/// ends), drawn under the curves; broken where either end is missing.
struct Band {
  std::string label;  ///< in the legend; empty: not listed
  std::vector<double> x, low, high;
  int colour = 0;  ///< an index in the palette
};

/// A horizontal line across the plot at y, labelled at its right end.
struct ReferenceLine {
  std::string label;
  double y = 0.0;
};

/// A cell of a heat map: a rectangle in data coordinates and its value.
struct HeatCell {
  double x_low = 0.0, x_high = 0.0, y_low = 0.0, y_high = 0.0;
  double value = 0.0;
};

/// Rectangles coloured by their value (a recorder's count matrix), drawn under the
/// curves, with a colour bar below the plot; cells of value <= 0 (on a log scale)
/// or NaN are left out.
struct HeatMap {
  std::string label;  ///< the colour bar's ("cycles")
  std::vector<HeatCell> cells;
  bool log = true;    ///< colours by log10 of the value
};

struct Axis {
  Axis(std::string label_ = {}, bool log_ = false) : label(std::move(label_)), log(log_) {}
  std::string label;  ///< with its unit: "frequency (Hz)"
  bool log = false;
  std::optional<double> min, max;  ///< the data's range where not given
  bool integer = false;            ///< ticks at whole numbers only (counts)
};

/// A second scale on the opposite side of an axis: value = scale * the axis's value.
struct SecondaryAxis {
  std::string label;
  double scale = 1.0;
};

struct Chart {
  Chart(std::string title_ = {}, Axis x_ = {}, Axis y_ = {}) : title(std::move(title_)), x(std::move(x_)), y(std::move(y_)) {}
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  std::vector<Band> bands;
  std::vector<ReferenceLine> references;
  std::optional<HeatMap> heat;         ///< under everything else
  std::optional<SecondaryAxis> top;    ///< proportional to x
  std::optional<SecondaryAxis> right;  ///< proportional to y
  /// Tick labels for x = 0, 1, 2, ... (span ids); empty: numbers.
  std::vector<std::string> x_categories;
};

/// The chart as an <svg> element (a viewBox, so that it scales to its container;
/// text in the page's font). A chart with no point to show (every point missing, or
/// none positive on a log axis) is drawn empty and says so. Throws InvalidParameter
/// where a series' x and y differ in length.
std::string svg(const Chart& chart);

/// "Nice" tick values covering [lo, hi]: multiples of 1, 2 or 5 times a power of ten
/// on a linear axis; on a log axis decades, with 2 and 5 between (then 3, then 1.5,
/// 4, 6 and 8) until at least four ticks label the range.
std::vector<double> ticks(double lo, double hi, bool log);

}  // namespace stockbridge::report
