#include "stockbridge/io/measured_impedance_file.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/csv_reader.hpp"

namespace stockbridge::io {

namespace {

bool has(const std::vector<std::string>& header, const std::string& name) {
  return std::find(header.begin(), header.end(), name) != header.end();
}

/// The first of two alternatives the header has, or InputError naming both.
std::string one_of(const std::vector<std::string>& header, const std::string& first, const std::string& second,
                   const std::string& file, const std::string& what) {
  if (has(header, first)) return first;
  if (has(header, second)) return second;
  throw InputError(fmt::format("{}: missing column '{}' (or '{}'): expected {} in the header", file, first, second, what));
}

void require_positive_cell(const std::string& file, std::size_t line, const std::string& column, double value) {
  if (!(value > 0.0)) {
    throw InputError(fmt::format("{}:{}: column '{}' = {}: expected > 0", file, line, column, format_value(value)));
  }
}

/// A phase column whose values all lie within +-pi but spread over more than this
/// (as radians, 6 degrees) holds radians: a damper's phase in degrees, from the mass
/// line's 90 through its resonances, does not stay within +-3.14 degrees.
constexpr double kRadiansSpread = 0.1;

/// The likely slip of a value outside `range`, for its message.
std::string likely_slip(const TypicalRange& range, double value) {
  const bool above = value > range.max;
  if (&range == &typical::velocity) return above ? "mm/s?" : "a unit mistake?";
  if (&range == &typical::displacement) return above ? "mm?" : "a unit mistake?";
  if (&range == &typical::frequency) return above ? "rad/s, or a frequency beyond a shaker test's?" : "kHz?";
  if (&range == &typical::impedance) return above ? "N/m, a dynamic stiffness F/X, rather than N s/m?" : "kN s/m?";
  return "a unit mistake?";
}

/// One warning per column with values outside `range`: its first such line, and how many more.
void warn_column(std::vector<std::string>& warnings, const std::string& file, const std::vector<std::size_t>& lines,
                 const std::string& column, const std::vector<double>& values, const TypicalRange& range) {
  std::size_t outside = 0, first = 0;
  for (std::size_t r = 0; r < values.size(); ++r) {
    if (range.contains(values[r])) continue;
    if (outside++ == 0) first = r;
  }
  if (outside == 0) return;
  UnusualValue u{column, values[first], range, likely_slip(range, values[first])};
  const std::string more = outside > 1 ? fmt::format("; {} more row{} of the column outside it", outside - 1,
                                                     outside > 2 ? "s" : "")
                                       : "";
  warnings.push_back(fmt::format("{}:{}: {}{}", file, lines[first], u.message(), more));
}

/// A warning where the phases look like radians (kRadiansSpread).
void warn_radians(std::vector<std::string>& warnings, const std::string& file, const std::vector<std::size_t>& lines,
                  const std::vector<double>& phase) {
  const auto [low, high] = std::minmax_element(phase.begin(), phase.end());
  if (std::max(std::abs(*low), std::abs(*high)) > std::numbers::pi || *high - *low <= kRadiansSpread) return;
  const std::size_t r = static_cast<std::size_t>(std::abs(*low) > std::abs(*high) ? low - phase.begin() : high - phase.begin());
  warnings.push_back(fmt::format("{}:{}: phase_deg = {}: phase_deg looks like radians: every value lies within +-pi "
                                 "({:.3g} to {:.3g}) while they vary along the curves; expected degrees (times 180/pi)",
                                 file, lines[r], format_value(phase[r]), *low, *high));
}

}  // namespace

identification::ImpedanceMeasurement read_measured_impedance(const std::filesystem::path& path) {
  return load_measured_impedance(path).measurement;
}

MeasuredImpedanceFile load_measured_impedance(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::vector<std::string> header = read_csv_header(path);
  const std::string amplitude = one_of(header, "velocity_m_s", "displacement_m", file, "the clamp's amplitude");
  const bool polar = !has(header, "re_z_n_s_m") && has(header, "abs_z_n_s_m");
  const std::vector<std::string> names =
      polar ? std::vector<std::string>{"frequency_hz", amplitude, "abs_z_n_s_m", "phase_deg"}
            : std::vector<std::string>{"frequency_hz", amplitude, "re_z_n_s_m", "im_z_n_s_m"};
  if (!polar && !has(header, "re_z_n_s_m")) {
    throw InputError(fmt::format("{}: missing column 're_z_n_s_m' (or 'abs_z_n_s_m'): expected re_z_n_s_m,im_z_n_s_m "
                                 "or abs_z_n_s_m,phase_deg in the header",
                                 file));
  }
  const CsvRows rows = read_csv_rows(path, names, 2);
  identification::ImpedanceMeasurement m;
  m.held = amplitude == "velocity_m_s" ? damper::HeldAmplitude::velocity : damper::HeldAmplitude::displacement;
  for (std::size_t r = 0; r < rows.lines.size(); ++r) {
    const std::size_t line = rows.lines[r];
    const double f = rows.columns[0][r], a = rows.columns[1][r];
    require_positive_cell(file, line, names[0], f);
    require_positive_cell(file, line, names[1], a);
    std::complex<double> z;
    if (polar) {
      require_positive_cell(file, line, names[2], rows.columns[2][r]);
      z = std::polar(rows.columns[2][r], rows.columns[3][r] * std::numbers::pi / 180.0);
    } else {
      z = {rows.columns[2][r], rows.columns[3][r]};
      if (z == 0.0) {
        throw InputError(fmt::format("{}:{}: columns 're_z_n_s_m', 'im_z_n_s_m' = 0, 0: expected a nonzero "
                                     "impedance",
                                     file, line));
      }
    }
    const damper::Excitation e = m.held == damper::HeldAmplitude::velocity ? damper::Excitation::from_velocity(f, a)
                                                                         : damper::Excitation{f, a};
    m.points.push_back({e, z});
  }
  MeasuredImpedanceFile out{std::move(m), {}};
  warn_column(out.warnings, file, rows.lines, names[0], rows.columns[0], typical::frequency);
  warn_column(out.warnings, file, rows.lines, names[1], rows.columns[1],
              out.measurement.held == damper::HeldAmplitude::velocity ? typical::velocity : typical::displacement);
  std::vector<double> magnitudes;
  for (const identification::MeasuredImpedance& p : out.measurement.points) magnitudes.push_back(std::abs(p.impedance));
  warn_column(out.warnings, file, rows.lines, polar ? "abs_z_n_s_m" : "|Z| of re_z_n_s_m, im_z_n_s_m", magnitudes,
              typical::impedance);
  if (polar) warn_radians(out.warnings, file, rows.lines, rows.columns[3]);
  return out;
}

}  // namespace stockbridge::io
