#pragma once
// The request layer for the linear natural frequencies (`stockbridge modes`, Python's
// modes): every element sticking and every one slipping, each arm with the clamp
// held and the whole damper with the clamp free (damper/modes.hpp); the CSV's rows
// and the JSON summary both front ends show.

#include <cstddef>
#include <string>
#include <vector>

#include "stockbridge/damper/damper.hpp"
#include "stockbridge/damper/modes.hpp"
#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

struct ModesResult {
  damper::DamperModes modes;
  double clamp_mass_kg = 0.0;
  /// The arms as the JSON names them (arm_column_prefixes).
  std::vector<std::string> arm_names;
  /// The arms as the CSV's arm column names them: arm_names, or arm1, arm2, ...
  /// for all where an arm is named as the whole damper's rows ("damper").
  std::vector<std::string> csv_arm_names;
};

ModesResult run_modes(const damper::Damper& damper);

/// One row of the CSV: a mode of an arm (clamp held) or of the whole damper.
struct ModeRow {
  std::string arm;  ///< an arm's name, or "damper"
  damper::CableLimit limit = damper::CableLimit::stick;
  std::size_t mode = 1;  ///< from 1, in increasing frequency
  double frequency_hz = 0.0;
};
/// Each arm's clamp-held modes (stick, then slip), then the whole damper's.
std::vector<ModeRow> mode_rows(const ModesResult& result);

/// The CSV's quantities: arm, state, mode, frequency_hz.
Table<ModeRow> modes_table();

/// The --json summary: {"arms": [{name, stick_hz, slip_hz}], "damper": {clamp_mass_kg,
/// stick_hz, slip_hz, stick_modes, slip_modes}}, each mode of the whole damper with
/// its frequency_hz, dominant_arm, clamp_x, clamp_energy_share and arms [{name, x,
/// phi, energy_share}].
io::JsonObject modes_summary(const ModesResult& result);

}  // namespace stockbridge::requests
