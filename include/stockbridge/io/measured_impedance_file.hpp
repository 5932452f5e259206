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
// Values outside the typical ranges (core/typical_ranges.hpp: frequency, velocity or
// displacement, |Z|) are accepted with a warning each column, naming the file, the
// first such line, the column, the value and the likely slip ("velocity_m_s = 50:
// ... (mm/s?)"); so is a phase_deg column whose values all lie within +-pi while
// they vary over more than a few tenths (radians, not degrees).
#include <filesystem>
#include <string>
#include <vector>

#include "stockbridge/identification/impedance_identification.hpp"

namespace stockbridge::io {

/// A measured impedance as read, and a warning line for each column whose values
/// lie outside the typical ranges ("z.csv:3: velocity_m_s = 50: outside ...").
struct MeasuredImpedanceFile {
  identification::ImpedanceMeasurement measurement;
  std::vector<std::string> warnings;
};

/// Throws InputError with one line naming the file, line and column, the value and
/// what was expected (a missing column names the alternatives).
MeasuredImpedanceFile load_measured_impedance(const std::filesystem::path& path);
/// load_measured_impedance's measurement alone.
identification::ImpedanceMeasurement read_measured_impedance(const std::filesystem::path& path);

}  // namespace stockbridge::io
