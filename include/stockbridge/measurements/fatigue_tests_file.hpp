#pragma once
// Fatigue-test files (CSV; docs/measurements.md, "Fatigue tests"): one row per test,
//
//     test,conductor,tension_n,yb_pp_mm,cycles,failed
//     Dalpe_1999_angle10 #1,ACSR Drake,35000,0.8272,3412811,true
//
// `conductor` a catalogue type (`stockbridge conductors`) or a conductor file (*.toml,
// relative to the CSV's folder), `yb_pp_mm` Yb peak-to-peak at 89 mm from the clamp
// (mm), `cycles` the cycles reached, `failed` true (broken) or false (a runout).
// Other columns are ignored; a header row, ',' between cells, '.' decimals, CRLF and a
// UTF-8 byte-order mark accepted.

#include <filesystem>
#include <string>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/measurements/fatigue_tests.hpp"

namespace stockbridge::measurements {

struct FatigueTestsFile {
  std::vector<FatigueTest> tests;
  std::vector<std::filesystem::path> inputs;  ///< the CSV and the conductor files it names
  std::vector<std::string> warnings;          ///< values outside their typical ranges, each at its line
};

/// Reads a fatigue-test file. Throws InputError with one line naming the file, the
/// line and the column, the value and what was expected: a missing column, an empty
/// or non-numeric cell, a tension, Yb or cycles <= 0, `failed` other than true or
/// false, an unknown conductor; UnusualValueError for a value a unit slip explains (a
/// tension in kN, a Yb in m) under SlipPolicy::refuse, a warning under warn.
FatigueTestsFile read_fatigue_tests_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);

}  // namespace stockbridge::measurements
