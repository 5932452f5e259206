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

/// A value > 0 within the magnitudes a description may hold (core/error.hpp: one
/// outside is a unit mistake, and would overflow the arithmetic).
void require_plausible_cell(const std::string& file, std::size_t line, const std::string& column, double value) {
  if (!(value > 0.0)) {
    throw InputError(fmt::format("{}:{}: column '{}' = {}: expected > 0", file, line, column, format_value(value)));
  }
  if (value < smallest_magnitude || value > largest_magnitude) {
    throw InputError(fmt::format("{}:{}: column '{}' = {}: expected a value from {:g} to {:g}; one outside is a unit "
                                 "mistake",
                                 file, line, column, format_value(value), smallest_magnitude, largest_magnitude));
  }
}

/// A phase column whose values all lie within +-pi but spread over more than this
/// (as radians, 6 degrees) holds radians: a damper's phase in degrees, from the mass
/// line's 90 through its resonances, does not stay within +-3.14 degrees.
constexpr double kRadiansSpread = 0.1;

/// A hint for a value outside `range` that no slip of the range explains.
std::string likely_cause(const TypicalRange& range, double value) {
  const bool above = value > range.max;
  if (&range == &typical::frequency) return above ? "rad/s, or a frequency beyond a shaker test's?" : "kHz?";
  if (&range == &typical::impedance) return above ? "N/m, a dynamic stiffness F/X, rather than N s/m?" : "";
  return "";
}

/// Which of a column's values outside its range a reader refuses: any (a test's
/// frequencies and amplitudes lie within a shaker's), or those a unit slip explains
/// (|Z|: a damper at a resonance at a large amplitude may pass the typical top).
enum class Refused { outside, slips };

/// A column's values outside `range`: under SlipPolicy::refuse the first refused one
/// (`refused`) is an UnusualValueError naming the file, line and column; the rest,
/// and every one under warn, one warning naming the first and counting the rest.
void judge_column(std::vector<std::string>& warnings, const std::string& file, const std::vector<std::size_t>& lines,
                  const std::string& column, const std::vector<double>& values, const TypicalRange& range,
                  SlipPolicy policy, Refused refused = Refused::outside) {
  std::size_t outside = 0, first = 0;
  for (std::size_t r = 0; r < values.size(); ++r) {
    if (range.contains(values[r])) continue;
    if (outside++ == 0) first = r;
  }
  if (outside == 0) return;
  for (std::size_t r = first; policy == SlipPolicy::refuse && r < values.size(); ++r) {
    const UnusualValue u{fmt::format("column '{}'", column), values[r], range, likely_cause(range, values[r])};
    if (range.contains(values[r]) || (refused == Refused::slips && !u.slip_explained())) continue;
    throw UnusualValueError(fmt::format("{}:{}: {}; a measured sheet's values lie within it", file, lines[r],
                                        u.message()));
  }
  UnusualValue u{fmt::format("column '{}'", column), values[first], range, likely_cause(range, values[first])};
  const std::string more = outside > 1 ? fmt::format("; {} more row{} of the column outside it", outside - 1,
                                                     outside > 2 ? "s" : "")
                                       : "";
  warnings.push_back(fmt::format("{}:{}: {}{}", file, lines[first], u.message(), more));
}

/// A phase in degrees lies within one turn either way; a value beyond is no phase
/// (a wrong column, or a number mistyped).
void require_phase(const std::string& file, std::size_t line, double phase_deg) {
  if (!(std::abs(phase_deg) <= 360.0)) {
    throw InputError(fmt::format("{}:{}: column 'phase_deg' = {}: expected a phase in degrees, -360 to 360", file, line,
                                 format_value(phase_deg)));
  }
}

/// Each curve (the rows of one held amplitude: identification::measured_curves) has
/// two frequencies or more, none twice: a curve of one row is a mistyped amplitude,
/// a frequency twice a mistyped frequency or a row pasted twice.
void require_curves(const identification::ImpedanceMeasurement& m, const std::string& file,
                    const std::vector<std::size_t>& lines, const std::string& amplitude_column) {
  for (const std::vector<std::size_t>& curve : identification::measured_curves(m)) {
    const auto amplitude = [&](std::size_t i) {
      const damper::Excitation& e = m.points[i].excitation;
      return m.held == damper::HeldAmplitude::velocity ? e.velocity_amplitude() : e.displacement_amplitude;
    };
    // A velocity-held sheet's curves are sweeps; a displacement column may give a
    // constant-velocity sweep point by point (each row its own displacement).
    if (curve.size() == 1 && m.held == damper::HeldAmplitude::velocity) {
      throw InputError(fmt::format("{}:{}: column '{}' = {}: the only row at this amplitude (within 10 %): expected "
                                   "a curve of two frequencies or more at each amplitude (a mistyped amplitude?)",
                                   file, lines[curve[0]], amplitude_column, format_value(amplitude(curve[0]))));
    }
    for (std::size_t k = 1; k < curve.size(); ++k) {
      const damper::Excitation& a = m.points[curve[k - 1]].excitation;
      const damper::Excitation& b = m.points[curve[k]].excitation;
      if (a.frequency_hz != b.frequency_hz) continue;
      const auto [first, second] = std::minmax(lines[curve[k - 1]], lines[curve[k]]);
      throw InputError(fmt::format("{}:{}: column 'frequency_hz' = {}: given again at line {} on the same curve "
                                   "({} = {}): expected each frequency once a curve",
                                   file, second, format_value(b.frequency_hz), first, amplitude_column,
                                   format_value(amplitude(curve[k]))));
    }
  }
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

identification::ImpedanceMeasurement read_measured_impedance(const std::filesystem::path& path, SlipPolicy policy) {
  return load_measured_impedance(path, policy).measurement;
}

MeasuredImpedanceFile load_measured_impedance(const std::filesystem::path& path, SlipPolicy policy) {
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
  MeasuredImpedanceFile out;
  const std::vector<double> magnitudes = polar ? rows.columns[2] : [&] {
    std::vector<double> m;
    for (std::size_t r = 0; r < rows.lines.size(); ++r) m.push_back(std::hypot(rows.columns[2][r], rows.columns[3][r]));
    return m;
  }();
  for (std::size_t r = 0; r < rows.lines.size(); ++r) {
    require_plausible_cell(file, rows.lines[r], names[0], rows.columns[0][r]);
    require_plausible_cell(file, rows.lines[r], names[1], rows.columns[1][r]);
    if (polar) require_phase(file, rows.lines[r], rows.columns[3][r]);
    if (!polar && magnitudes[r] == 0.0) {
      throw InputError(fmt::format("{}:{}: columns 're_z_n_s_m', 'im_z_n_s_m' = 0, 0: expected a nonzero impedance",
                                   file, rows.lines[r]));
    }
    require_plausible_cell(file, rows.lines[r], polar ? names[2] : "|Z| of re_z_n_s_m, im_z_n_s_m", magnitudes[r]);
  }
  const bool velocity = amplitude == "velocity_m_s";
  judge_column(out.warnings, file, rows.lines, names[0], rows.columns[0], typical::frequency, policy);
  judge_column(out.warnings, file, rows.lines, names[1], rows.columns[1],
               velocity ? typical::velocity : typical::displacement, policy);
  judge_column(out.warnings, file, rows.lines, polar ? "abs_z_n_s_m" : "|Z| of re_z_n_s_m, im_z_n_s_m", magnitudes,
               typical::impedance, policy, Refused::slips);
  identification::ImpedanceMeasurement& m = out.measurement;
  m.held = velocity ? damper::HeldAmplitude::velocity : damper::HeldAmplitude::displacement;
  for (std::size_t r = 0; r < rows.lines.size(); ++r) {
    const double f = rows.columns[0][r], a = rows.columns[1][r];
    const std::complex<double> z = polar ? std::polar(rows.columns[2][r], rows.columns[3][r] * std::numbers::pi / 180.0)
                                         : std::complex<double>(rows.columns[2][r], rows.columns[3][r]);
    const damper::Excitation e = velocity ? damper::Excitation::from_velocity(f, a) : damper::Excitation{f, a};
    m.points.push_back({e, z});
  }
  require_curves(m, file, rows.lines, amplitude);
  if (polar) warn_radians(out.warnings, file, rows.lines, rows.columns[3]);
  return out;
}

}  // namespace stockbridge::io
