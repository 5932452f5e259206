#include "stockbridge/io/measured_impedance_file.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
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

}  // namespace

identification::ImpedanceMeasurement read_measured_impedance(const std::filesystem::path& path) {
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
  return m;
}

}  // namespace stockbridge::io
