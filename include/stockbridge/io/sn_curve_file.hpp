#pragma once
// S-N curve files (TOML): a conductor's own S-N curve as a table, e.g. the design
// curve `stockbridge fatigue-tests --curve` fits to its fatigue tests, which a span
// or line file's [fatigue] names with curve = "curve.toml" (span::SnCurve):
//
//     [sn_curve]
//     name = "ACSR Drake tests, mean - 2 s"  # how reports name it
//     source = "examples/fatigue_tests.csv"  # optional: what it was fitted to (free text)
//     stress_mpa = [40.0, 25.1, 15.8]        # zero-to-peak, strictly decreasing
//     cycles = [1e6, 1e7, 1e8]               # strictly increasing, as many (>= 2)
//
// read log-log piecewise linear, the end segments extrapolated (docs/file-formats.md).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/span/fatigue.hpp"

namespace stockbridge::io {

/// Reads an S-N curve file; the curve's name is the file's `name`, its source the
/// path as given. Throws InputError "<file>:<line>: sn_curve.<key> ...: expected ..."
/// on a missing file, a syntax error, a missing, unknown or mistyped key, or a table
/// the curve refuses (stresses not strictly decreasing, cycles not increasing, ...).
span::SnCurve read_sn_curve_file(const std::filesystem::path& path);

/// The text of an S-N curve file for the table's points (stresses in MPa).
std::string sn_curve_toml(std::string_view name, std::string_view source, const std::vector<double>& stress_mpa,
                          const std::vector<double>& cycles);

}  // namespace stockbridge::io
