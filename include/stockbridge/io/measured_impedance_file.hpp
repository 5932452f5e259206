#pragma once
// Reading a measured damper impedance (CSV, as `stockbridge impedance` writes it, or
// from a shaker test): one row per point, columns
//
//   frequency_hz                      Hz, > 0
//   velocity_m_s  or displacement_m   the clamp's amplitude, > 0 (velocity preferred
//                                     where both are present)
//   re_z_n_s_m, im_z_n_s_m  or  abs_z_n_s_m, phase_deg   Z, nonzero
//
// others ignored; several amplitudes in one file (the curves are grouped by the
// amplitude, identification::measured_curves).
#include <filesystem>

#include "stockbridge/identification/impedance_identification.hpp"

namespace stockbridge::io {

/// Throws InputError with one line naming the file, line and column, the value and
/// what was expected (a missing column names the alternatives).
identification::ImpedanceMeasurement read_measured_impedance(const std::filesystem::path& path);

}  // namespace stockbridge::io
