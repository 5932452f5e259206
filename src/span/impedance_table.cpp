#include "stockbridge/span/impedance_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

void ImpedanceTableOptions::validate() const {
  require_positive("velocity_min", velocity_min, "m/s");
  if (!(velocity_max > velocity_min)) throw_invalid("velocity_max", velocity_max, "a value > velocity_min (m/s)");
  require_in_range("velocities", velocities, 2, 1000);
  if (!(column_ratio >= 1.0 && column_ratio <= 10.0)) throw_invalid("column_ratio", column_ratio, "a factor from 1 to 10");
  require_in_range("threads", threads, 1, 256);
  solver.validate();
}

ImpedanceTableOptions ImpedanceTableOptions::for_position_search() const {
  ImpedanceTableOptions options = *this;
  options.velocities = std::max(velocities, 25);
  options.column_ratio = std::min(column_ratio, 1.2);
  return options;
}

namespace {

/// Fritsch-Carlson slope at an interior node of one real component: zero at a local
/// extremum, else the weighted harmonic mean of the neighbouring secants (no overshoot).
double monotone_slope(double h0, double d0, double h1, double d1) {
  if (d0 * d1 <= 0.0) return 0.0;
  const double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
  return (w0 + w1) / (w0 / d0 + w1 / d1);
}

double table_hermite(double t, double h, double y0, double y1, double m0, double m1) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * h * m0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * h * m1;
}

/// d/du of table_hermite, u = u_k + t h.
double table_hermite_slope(double t, double h, double y0, double y1, double m0, double m1) {
  const double t2 = t * t;
  return ((6 * t2 - 6 * t) * y0 + (-6 * t2 + 6 * t) * y1) / h + (3 * t2 - 4 * t + 1) * m0 + (3 * t2 - 2 * t) * m1;
}

}  // namespace

ImpedanceTable::Column ImpedanceTable::make_column(const std::vector<double>& log_v,
                                                   const std::vector<std::optional<std::complex<double>>>& z) {
  Column c;
  bool gap = false;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (!z[i]) {
      gap = !c.log_v.empty();
      continue;
    }
    if (!c.log_v.empty()) c.gap_after.push_back(gap);
    gap = false;
    c.log_v.push_back(log_v[i]);
    c.z.push_back(*z[i]);
  }
  const std::size_t n = c.log_v.size();
  c.slope.assign(n, 0.0);
  if (n < 2) return c;
  std::vector<double> h(n - 1);
  std::vector<std::complex<double>> d(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = c.log_v[i + 1] - c.log_v[i];
    d[i] = (c.z[i + 1] - c.z[i]) / h[i];
  }
  c.slope.front() = d.front();
  c.slope.back() = d.back();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    c.slope[i] = {monotone_slope(h[i - 1], d[i - 1].real(), h[i], d[i].real()),
                  monotone_slope(h[i - 1], d[i - 1].imag(), h[i], d[i].imag())};
  }
  return c;
}

ImpedanceTable::ImpedanceTable(const damper::Damper& damper, std::vector<double> frequencies,
                               const ImpedanceTableOptions& options, const damper::SweepProgress& progress)
    : frequencies_(std::move(frequencies)) {
  options.validate();
  velocities_ = damper::log_spaced(options.velocity_min, options.velocity_max, options.velocities);
  solved_ = solved_frequencies(frequencies_, options.column_ratio);
  damper::SweepSpec spec;
  for (const std::size_t i : solved_) spec.frequencies.push_back(frequencies_[i]);
  spec.amplitudes = velocities_;
  spec.solver = options.solver;
  spec.threads = options.threads;
  const std::vector<damper::SweepRun> runs = damper::run_sweep(damper, spec, progress);
  std::vector<double> log_v(velocities_.size());
  std::transform(velocities_.begin(), velocities_.end(), log_v.begin(), [](double v) { return std::log(v); });
  for (std::size_t i = 0; i < solved_.size(); ++i) {
    std::vector<std::optional<std::complex<double>>> z(velocities_.size());
    for (std::size_t a = 0; a < runs.size(); ++a) {
      const damper::ImpedancePoint& p = runs[a].points[i];
      if (p.converged()) {
        z[a] = p.impedance;
      } else {
        ++failed_;
      }
    }
    columns_.push_back(make_column(log_v, z));
  }
  place_frequencies();
}

ImpedanceTable::ImpedanceTable(const ImpedanceSheet& sheet, std::vector<double> frequencies)
    : frequencies_(std::move(frequencies)) {
  for (std::size_t i = 0; i < frequencies_.size(); ++i) {
    std::vector<double> log_v;
    std::vector<std::optional<std::complex<double>>> z;
    for (const SheetNode& node : sheet.nodes_at(frequencies_[i])) {
      log_v.push_back(std::log(node.velocity));
      z.emplace_back(node.impedance);
    }
    solved_.push_back(i);
    columns_.push_back(make_column(log_v, z));
  }
  place_frequencies();
}

void ImpedanceTable::place_frequencies() {
  places_.reserve(frequencies_.size());
  for (std::size_t i = 0; i < frequencies_.size(); ++i) {
    const auto k = static_cast<std::size_t>(std::lower_bound(solved_.begin(), solved_.end(), i) - solved_.begin());
    if (solved_[k] == i) {
      places_.push_back({k, true, 0.0});
      continue;
    }
    const double t = std::log(frequencies_[i] / frequencies_[solved_[k - 1]]) /
                     std::log(frequencies_[solved_[k]] / frequencies_[solved_[k - 1]]);
    places_.push_back({k, false, t});
  }
}

std::optional<Interval> ImpedanceTable::velocity_range(std::size_t i) const {
  if (i >= frequencies_.size()) throw std::out_of_range("ImpedanceTable::velocity_range: no such frequency");
  const Place& place = places_[i];
  const auto range_of = [this](std::size_t column) -> std::optional<Interval> {
    const Column& c = columns_[column];
    if (c.log_v.size() < 2) return std::nullopt;
    return Interval{std::exp(c.log_v.front()), std::exp(c.log_v.back())};
  };
  const std::optional<Interval> hi = range_of(place.column);
  if (place.solved || !hi) return hi;
  const std::optional<Interval> lo = range_of(place.column - 1);
  if (!lo) return std::nullopt;
  return Interval{std::max(lo->lo, hi->lo), std::min(lo->hi, hi->hi)};
}

std::vector<std::size_t> ImpedanceTable::solved_frequencies(const std::vector<double>& frequencies, double column_ratio) {
  std::vector<std::size_t> solved;
  if (frequencies.empty()) return solved;
  solved.push_back(0);
  while (solved.back() + 1 < frequencies.size()) {
    std::size_t next = solved.back() + 1;
    while (next + 1 < frequencies.size() && frequencies[next + 1] <= column_ratio * frequencies[solved.back()]) ++next;
    solved.push_back(next);
  }
  return solved;
}

std::optional<std::complex<double>> ImpedanceTable::at(std::size_t i, double velocity) const {
  const std::optional<TableImpedance> z = at_with_slope(i, velocity);
  if (!z) return std::nullopt;
  return z->z;
}

std::optional<TableImpedance> ImpedanceTable::at_with_slope(std::size_t i, double velocity) const {
  if (i >= frequencies_.size()) throw std::out_of_range("ImpedanceTable::at: no such frequency");
  const Place& place = places_[i];
  const double u = std::log(velocity);
  if (place.solved) return column_at(place.column, u);
  const auto lo = column_at(place.column - 1, u), hi = column_at(place.column, u);
  if (!lo || !hi) return std::nullopt;
  const double t = place.t;
  return TableImpedance{(1.0 - t) * lo->z + t * hi->z, (1.0 - t) * lo->slope + t * hi->slope};
}

std::optional<TableImpedance> ImpedanceTable::column_at(std::size_t column, double u) const {
  const Column& c = columns_[column];
  const std::size_t n = c.log_v.size();
  if (n < 2) return std::nullopt;
  if (u <= c.log_v.front()) return TableImpedance{c.z.front(), 0.0};
  if (u >= c.log_v.back()) return TableImpedance{c.z.back(), 0.0};
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(c.log_v.begin(), c.log_v.end(), u) - c.log_v.begin()) - 1;
  if (c.gap_after[k]) return std::nullopt;
  const double h = c.log_v[k + 1] - c.log_v[k], t = (u - c.log_v[k]) / h;
  const auto part = [&](auto component) {
    return std::pair{table_hermite(t, h, component(c.z[k]), component(c.z[k + 1]), component(c.slope[k]), component(c.slope[k + 1])),
                     table_hermite_slope(t, h, component(c.z[k]), component(c.z[k + 1]), component(c.slope[k]),
                                         component(c.slope[k + 1]))};
  };
  const auto [re, re_slope] = part([](std::complex<double> q) { return q.real(); });
  const auto [im, im_slope] = part([](std::complex<double> q) { return q.imag(); });
  return TableImpedance{{re, im}, {re_slope, im_slope}};
}

}  // namespace stockbridge::span
