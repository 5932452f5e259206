#pragma once
// Reading a measured damper impedance (CSV, as `stockbridge impedance` writes it, or
// from a shaker test or a vendor's damper sheet): one row per point, columns
//
//   frequency_hz                      Hz, > 0
//   velocity_m_s  or displacement_m   the clamp's amplitude, > 0 (velocity preferred
//                                     where both are present)
//   re_z_n_s_m, im_z_n_s_m  or  abs_z_n_s_m, phase_deg   Z, nonzero
//
// others ignored; several amplitudes in one file (the curves are grouped by the
// amplitude, identification::measured_curves).
//
// Every value is checked where it is read, a bad one named by the file, its line and
// column: frequencies and amplitudes > 0, |Z| > 0, a phase within -360 to 360
// degrees; each curve (the rows of one amplitude) two frequencies or more, none
// twice. A shaker test's values lie within the typical ranges (core/typical_ranges.hpp:
// frequency, velocity or displacement, |Z|): one outside is refused
// (SlipPolicy::refuse: UnusualValueError, "z.csv:3: column 'velocity_m_s' = 50:
// outside ... (in mm/s? ...)"), or under SlipPolicy::warn accepted with a warning
// each column naming its first such line. A phase_deg column whose values all lie
// within +-pi while they vary over more than a few tenths (radians, not degrees)
// gets a warning.
#include <filesystem>
#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/identification/impedance_identification.hpp"

namespace stockbridge::io {

/// A measured impedance as read, and its warning lines (a column outside the
/// typical ranges under SlipPolicy::warn, phases that look like radians).
struct MeasuredImpedanceFile {
  identification::ImpedanceMeasurement measurement;
  std::vector<std::string> warnings;
};

/// Throws InputError with one line naming the file, line and column, the value and
/// what was expected (a missing column names the alternatives).
MeasuredImpedanceFile load_measured_impedance(const std::filesystem::path& path,
                                              SlipPolicy policy = SlipPolicy::refuse);
/// load_measured_impedance's measurement alone.
identification::ImpedanceMeasurement read_measured_impedance(const std::filesystem::path& path,
                                                             SlipPolicy policy = SlipPolicy::refuse);

}  // namespace stockbridge::io
