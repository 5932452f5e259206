// A vibration recorder's counts read from their CSV, in either form (recorder.hpp):
// the neutral form (one row per bin) and the matrix form (Yb rows, frequency-bin
// columns), each bin's edges and count checked, a Yb in um or m refused as a slip.
#include "stockbridge/measurements/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/csv_reader.hpp"

namespace stockbridge::measurements {

namespace {

// Names here are unique among the library's files (unity batches).

/// A number filling the whole text (trimmed), or none.
std::optional<double> recorder_number(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return std::nullopt;
  const std::size_t last = text.find_last_not_of(" \t");
  const std::string s(text.substr(first, last - first + 1));
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// "low-high" (a '-' not after an exponent's e), both numbers; none otherwise.
std::optional<std::pair<double, double>> recorder_range(std::string_view text) {
  for (std::size_t p = 1; p < text.size(); ++p) {
    if (text[p] != '-' || text[p - 1] == 'e' || text[p - 1] == 'E') continue;
    const auto lo = recorder_number(text.substr(0, p));
    const auto hi = recorder_number(text.substr(p + 1));
    if (lo && hi) return std::make_pair(*lo, *hi);
    return std::nullopt;
  }
  return std::nullopt;
}

/// Judges a Yb edge (mm) against the typical range: a value in um or in m is a slip.
void judge_recorder_yb(const std::string& where, std::string_view column, double value_mm, SlipPolicy policy,
                       std::vector<std::string>& warnings) {
  if (value_mm == 0.0) return;  // a lowest bin from zero
  TypicalRange range = typical::recorder_yb;
  if (value_mm < range.min) range.slip = {1e3, "m"};
  if (const std::optional<UnusualValue> u = unusual(std::string(column), value_mm, range)) {
    judge_unusual(*u, where + ": ", policy, warnings);
  }
}

/// Checks a bin's edges and count; `where` names its place.
void check_recorder_bin(const RecorderBin& b, const std::string& where, std::string_view yb_column,
                        std::string_view frequency_column, std::string_view cycles_column) {
  if (!(b.yb_low >= 0.0) || !(b.yb_high > b.yb_low)) {
    throw InputError(fmt::format("{}: {} = {} to {} mm: an inverted or empty Yb bin; expected 0 <= low < high",
                                 where, yb_column, format_value(1e3 * b.yb_low), format_value(1e3 * b.yb_high)));
  }
  if (!(b.frequency_low > 0.0) || !(b.frequency_high > b.frequency_low)) {
    throw InputError(fmt::format("{}: {} = {} to {} Hz: an inverted or empty frequency bin; expected 0 < low < high",
                                 where, frequency_column, format_value(b.frequency_low),
                                 format_value(b.frequency_high)));
  }
  if (!(b.cycles >= 0.0)) {
    throw InputError(fmt::format("{}: {} = {}: a negative count; expected cycles >= 0", where, cycles_column,
                                 format_value(b.cycles)));
  }
}

bool recorder_overlap(double a_lo, double a_hi, double b_lo, double b_hi) {
  return std::max(a_lo, b_lo) < std::min(a_hi, b_hi);
}

/// The distinct frequency bins, increasing; InputError where two overlap without being the same.
std::vector<std::pair<double, double>> recorder_bands(const std::vector<RecorderBin>& bins) {
  std::vector<std::pair<double, double>> bands;
  for (const RecorderBin& b : bins) {
    const std::pair<double, double> band{b.frequency_low, b.frequency_high};
    if (std::find(bands.begin(), bands.end(), band) != bands.end()) continue;
    for (const auto& other : bands) {
      if (recorder_overlap(band.first, band.second, other.first, other.second)) {
        throw InputError(fmt::format("{}: frequency bin {} to {} Hz overlaps the bin {} to {} Hz of another row; "
                                     "expected one set of disjoint frequency bins",
                                     b.where, format_value(band.first), format_value(band.second),
                                     format_value(other.first), format_value(other.second)));
      }
    }
    bands.push_back(band);
  }
  std::sort(bands.begin(), bands.end());
  return bands;
}

RecorderCounts read_neutral_counts(const std::filesystem::path& path, SlipPolicy policy) {
  const std::string file = path.string();
  const io::CsvRows rows = io::read_csv_rows(
      path, {"yb_pp_mm_low", "yb_pp_mm_high", "frequency_hz_low", "frequency_hz_high", "cycles"}, 1);
  RecorderCounts counts;
  std::vector<RecorderBin> all;
  for (std::size_t i = 0; i < rows.lines.size(); ++i) {
    RecorderBin b{1e-3 * rows.columns[0][i], 1e-3 * rows.columns[1][i], rows.columns[2][i], rows.columns[3][i],
                  rows.columns[4][i], fmt::format("{}:{}", file, rows.lines[i])};
    judge_recorder_yb(b.where, "yb_pp_mm_low", rows.columns[0][i], policy, counts.warnings);
    judge_recorder_yb(b.where, "yb_pp_mm_high", rows.columns[1][i], policy, counts.warnings);
    check_recorder_bin(b, b.where, "yb_pp_mm_low, yb_pp_mm_high", "frequency_hz_low, frequency_hz_high", "cycles");
    for (const RecorderBin& other : all) {
      if (recorder_overlap(b.yb_low, b.yb_high, other.yb_low, other.yb_high) &&
          recorder_overlap(b.frequency_low, b.frequency_high, other.frequency_low, other.frequency_high)) {
        throw InputError(fmt::format("{}: the bin Yb {} to {} mm, {} to {} Hz overlaps the bin of line {}; expected "
                                     "disjoint bins, each counted once",
                                     b.where, format_value(1e3 * b.yb_low), format_value(1e3 * b.yb_high),
                                     format_value(b.frequency_low), format_value(b.frequency_high),
                                     other.where.substr(file.size() + 1)));
      }
    }
    all.push_back(b);
  }
  counts.bands = recorder_bands(all);
  for (RecorderBin& b : all) {
    if (b.cycles > 0.0) counts.bins.push_back(std::move(b));
  }
  return counts;
}

RecorderCounts read_matrix_counts(const std::filesystem::path& path, SlipPolicy policy) {
  const std::string file = path.string();
  const io::CsvCells cells = io::read_csv_cells(path);
  RecorderCounts counts;
  counts.matrix_form = true;
  if (cells.header.size() < 2) {
    throw InputError(fmt::format("{}: header: only the column yb_pp_mm; expected frequency bins as further columns, "
                                 "e.g. '5-10 hz'",
                                 file));
  }
  if (cells.rows.empty()) throw InputError(fmt::format("{}: no rows: expected one row per Yb bin", file));
  std::vector<std::pair<double, double>> columns;
  for (std::size_t j = 1; j < cells.header.size(); ++j) {
    std::string text = cells.header[j];
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    std::optional<std::pair<double, double>> band;
    if (lower.size() > 2 && lower.ends_with("hz")) band = recorder_range(std::string_view(lower).substr(0, lower.size() - 2));
    if (!band || !(band->first > 0.0) || !(band->second > band->first)) {
      throw InputError(fmt::format("{}: header, column {} '{}': expected a frequency bin as 'low-high hz' with 0 < "
                                   "low < high, e.g. '5-10 hz'",
                                   file, j + 1, printable(text)));
    }
    for (std::size_t k = 0; k < columns.size(); ++k) {
      if (recorder_overlap(band->first, band->second, columns[k].first, columns[k].second)) {
        throw InputError(fmt::format("{}: header, column {} '{}': overlaps column {} '{}'; expected disjoint "
                                     "frequency bins",
                                     file, j + 1, printable(text), k + 2, printable(cells.header[k + 1])));
      }
    }
    columns.push_back(*band);
  }
  std::vector<std::pair<double, double>> rows_yb;
  for (std::size_t i = 0; i < cells.rows.size(); ++i) {
    const std::vector<std::string>& row = cells.rows[i];
    const std::string where = fmt::format("{}:{}", file, cells.lines[i]);
    const std::optional<std::pair<double, double>> yb = recorder_range(row[0]);
    if (!yb) {
      throw InputError(fmt::format("{}, column yb_pp_mm: '{}': expected a Yb bin as 'low-high' in mm, e.g. "
                                   "'0.1-0.2'",
                                   where, printable(row[0])));
    }
    judge_recorder_yb(where, "yb_pp_mm (low)", yb->first, policy, counts.warnings);
    judge_recorder_yb(where, "yb_pp_mm (high)", yb->second, policy, counts.warnings);
    for (std::size_t k = 0; k < rows_yb.size(); ++k) {
      if (recorder_overlap(yb->first, yb->second, rows_yb[k].first, rows_yb[k].second)) {
        throw InputError(fmt::format("{}, column yb_pp_mm: the Yb bin {} overlaps that of line {}; expected disjoint "
                                     "Yb bins",
                                     where, printable(row[0]), cells.lines[k]));
      }
    }
    rows_yb.push_back(*yb);
    for (std::size_t j = 1; j < row.size(); ++j) {
      const std::string at = fmt::format("{}, column '{}'", where, printable(cells.header[j]));
      double cycles = 0.0;
      if (!row[j].empty()) {
        const std::optional<double> n = recorder_number(row[j]);
        if (!n) throw InputError(fmt::format("{}: '{}': expected a count of cycles (a number >= 0; empty: 0)", at, printable(row[j])));
        cycles = *n;
      }
      RecorderBin b{1e-3 * yb->first, 1e-3 * yb->second, columns[j - 1].first, columns[j - 1].second, cycles, at};
      check_recorder_bin(b, at, "yb_pp_mm", "the column's bin", "cycles");
      if (b.cycles > 0.0) counts.bins.push_back(std::move(b));
    }
  }
  counts.bands = columns;
  std::sort(counts.bands.begin(), counts.bands.end());
  return counts;
}

}  // namespace

RecorderCounts read_recorder_counts(const std::filesystem::path& path, SlipPolicy policy) {
  const std::vector<std::string> header = io::read_csv_header(path);
  const bool neutral = std::find(header.begin(), header.end(), "yb_pp_mm_low") != header.end();
  RecorderCounts counts;
  if (neutral) {
    counts = read_neutral_counts(path, policy);
  } else if (!header.empty() && header.front() == "yb_pp_mm") {
    counts = read_matrix_counts(path, policy);
  } else {
    throw InputError(fmt::format("{}: header '{}': expected the neutral form's columns yb_pp_mm_low, yb_pp_mm_high, "
                                 "frequency_hz_low, frequency_hz_high, cycles, or the matrix form's first column "
                                 "yb_pp_mm followed by frequency bins 'low-high hz'",
                                 path.string(), printable(header.empty() ? std::string() : header.front())));
  }
  if (counts.bins.empty()) {
    throw InputError(fmt::format("{}: no cycles counted in any bin; expected at least one bin with cycles > 0",
                                 path.string()));
  }
  return counts;
}

}  // namespace stockbridge::measurements
