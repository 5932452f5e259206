#pragma once
// A damper's clamp impedance Z(f, v) for the span balance: the balance asks for Z
// at its frequencies and at whatever clamp velocity amplitude the fixed point
// tries, many times over. The table solves the damper once per (frequency,
// velocity) node by this project's sweeps (warm-started harmonic balance along the
// frequencies at each velocity of a log grid) and interpolates in log v at each
// frequency: monotone cubic (Fritsch-Carlson) in Re Z and Im Z between converged
// nodes, held at the grid's ends (below its lowest velocity the cable sticks
// throughout and Z no longer depends on v). How close that is to solving the
// damper directly is tested (tests/unit/span) and given in docs/span.md.

#include <complex>
#include <optional>
#include <vector>

#include "stockbridge/damper/sweep.hpp"
#include "stockbridge/span/impedance_sheet.hpp"

namespace stockbridge::span {

/// A table's Z at one clamp velocity amplitude, and its change along ln v there: the
/// interpolant's own derivative (zero where Z is held beyond the nodes).
struct TableImpedance {
  std::complex<double> z;      ///< N s/m
  std::complex<double> slope;  ///< dZ / d(ln v), N s/m
};

struct ImpedanceTableOptions {
  double velocity_min = 1e-3;  ///< m/s, lowest node
  double velocity_max = 3.0;   ///< m/s, highest node
  /// Log-spaced nodes, >= 2. The polished balance takes only its start from the
  /// table (docs/span.md): a coarse one serves it; a balance on the table alone
  /// (the position search) wants a finer one (for_position_search()).
  int velocities = 9;
  /// The frequencies solved (columns) lie at most this factor apart (the first and
  /// last always solved; 1 solves every frequency); between them Z is interpolated
  /// linearly in log f.
  double column_ratio = 1.5;
  damper::SolverOptions solver;
  int threads = 1;

  void validate() const;
  /// The finer table a balance on the table alone wants: at least 25 velocities,
  /// columns at most a factor 1.2 apart (Z within a few percent of the direct
  /// solution away from the damper's resonances: docs/span.md); the rest as here.
  ImpedanceTableOptions for_position_search() const;
};

class ImpedanceTable {
 public:
  /// Solves the damper at every frequency (Hz, strictly increasing) and node velocity.
  ImpedanceTable(const damper::Damper& damper, std::vector<double> frequencies, const ImpedanceTableOptions& options,
                 const damper::SweepProgress& progress = {});

  /// A measured sheet's Z at every frequency: each column the sheet's curves there
  /// (ImpedanceSheet::nodes_at), interpolated in log v as the solved tables are; a
  /// frequency with fewer than two curves has no Z. Nothing is solved (nodes() is 0).
  ImpedanceTable(const ImpedanceSheet& sheet, std::vector<double> frequencies);

  const std::vector<double>& frequencies() const { return frequencies_; }
  const std::vector<double>& velocities() const { return velocities_; }
  /// Z (N s/m) at frequency `frequencies()[i]` and clamp velocity amplitude v (m/s);
  /// none where fewer than two nodes of that frequency converged, or v lies between
  /// two converged nodes with a failed node between them.
  std::optional<std::complex<double>> at(std::size_t i, double velocity) const;
  /// at(i, velocity) with its slope dZ/d(ln v): exact for the interpolant (the
  /// fixed points' Newton steps on the table take it).
  std::optional<TableImpedance> at_with_slope(std::size_t i, double velocity) const;
  /// Nodes that did not converge, of all.
  int failed_nodes() const { return failed_; }
  int nodes() const { return static_cast<int>(solved_.size() * velocities_.size()); }
  /// The lowest and highest clamp velocity with a Z at frequency `frequencies()[i]`
  /// (m/s; Z is held beyond them); none where Z is not known there.
  std::optional<Interval> velocity_range(std::size_t i) const;
  /// The indices of the frequencies solved of `frequencies` (increasing): the fewest
  /// that lie at most `column_ratio` apart.
  static std::vector<std::size_t> solved_frequencies(const std::vector<double>& frequencies, double column_ratio);

 private:
  struct Column {  // one frequency: the converged nodes in log v, with their slopes
    std::vector<double> log_v;
    std::vector<std::complex<double>> z;
    std::vector<std::complex<double>> slope;
    std::vector<bool> gap_after;  ///< a failed node lies between node i and i + 1
  };
  static Column make_column(const std::vector<double>& log_v, const std::vector<std::optional<std::complex<double>>>& z);

  /// Where each frequency lies among the columns: its own, or between `column - 1`
  /// and `column` at `t` in log f.
  struct Place {
    std::size_t column;
    bool solved;
    double t;
  };
  void place_frequencies();
  /// Z and its slope in a column at u = ln v.
  std::optional<TableImpedance> column_at(std::size_t column, double u) const;

  std::vector<double> frequencies_;
  std::vector<double> velocities_;
  std::vector<std::size_t> solved_;  ///< the frequencies (indices) solved, increasing: columns_[k] is solved_[k]'s
  std::vector<Column> columns_;
  std::vector<Place> places_;  ///< one per frequency
  int failed_ = 0;
};

}  // namespace stockbridge::span
