#pragma once
// Features of a measured loop y(x) used to start identifications: slopes just after
// and just before the reversals of x, a robust average, and averages over the upper
// and the lower extremes (private to the library).

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace stockbridge::identification {

/// Least-squares slope dy/dx over the samples within `span` of x after (side +1) or
/// before (side -1) sample r (a fitted line rather than two points: robust to noise).
inline double slope_near(const std::vector<double>& x, const std::vector<double>& y, std::size_t r, int side,
                         double span) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int count = 0;
  for (std::size_t j = r;;) {
    sx += x[j];
    sy += y[j];
    sxx += x[j] * x[j];
    sxy += x[j] * y[j];
    ++count;
    if (std::abs(x[j] - x[r]) >= span || (side > 0 ? j + 1 >= x.size() : j == 0)) break;
    j = side > 0 ? j + 1 : j - 1;
  }
  const double denominator = count * sxx - sx * sx;
  return count >= 2 && denominator > 0.0 ? (count * sxy - sx * sy) / denominator
                                         : std::numeric_limits<double>::quiet_NaN();
}

/// The median of the finite values (NaN if there are none).
inline double median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double value) { return !std::isfinite(value); }), v.end());
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

/// Median slopes of the loop just after the reversals (steepest: everything sticks)
/// and just before them (flattest: everything slips), over 2 % of the range of x.
struct LoopSlopes {
  double after = 0.0;
  double before = 0.0;
};

inline LoopSlopes loop_slopes(const std::vector<double>& x, const std::vector<double>& y,
                              const std::vector<std::size_t>& turns) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double span = 0.02 * (*hi - *lo);
  std::vector<double> after, before;
  for (const std::size_t r : turns) {
    after.push_back(slope_near(x, y, r, +1, span));
    before.push_back(slope_near(x, y, r, -1, span));
  }
  return {median(after), median(before)};
}

/// Means of value(r) over the reversals r at the upper extremes of x (above its
/// mid-range) and over those at the lower extremes (0 where there are none).
struct ExtremeMeans {
  double upper = 0.0;
  double lower = 0.0;
};

template <class Value>
ExtremeMeans extreme_means(const std::vector<double>& x, const std::vector<std::size_t>& turns, Value value) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double middle = 0.5 * (*hi + *lo);
  ExtremeMeans means;
  int n_upper = 0, n_lower = 0;
  for (const std::size_t r : turns) {
    if (x[r] > middle) {
      means.upper += value(r);
      ++n_upper;
    } else {
      means.lower += value(r);
      ++n_lower;
    }
  }
  means.upper /= std::max(n_upper, 1);
  means.lower /= std::max(n_lower, 1);
  return means;
}

}  // namespace stockbridge::identification
