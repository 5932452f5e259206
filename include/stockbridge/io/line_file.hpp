#pragma once
// Reading line files (TOML, docs/line.md) and the spans CSV they may name, and
// writing a span file for one span of the schedule (what `stockbridge span`
// reproduces the schedule's row with).
//
//   [conductor] (or type = "ACSR Drake"), [wind], [self_damping], [fatigue], [balance]
//                                   # a span file's tables, shared by every span
//   [line]                          # optional
//   name = "Line 7"
//   points = 100                    # frequencies of each arrangement's balance
//   search_points = 40              # frequencies of the position search
//   [dampers]
//   types = [ { name = "sb1", file = "damper.toml" } ]  # or impedance = "sheet.csv", mass = kg
//   min_per_end = 0
//   max_per_end = 3
//   position_min = 0.5              # m from the clamp
//   position_max = 8.0
//   spacing_min = 0.5               # m
//   objective = "max_stress"        # or "life"
//   life_target = 80                # years (optional: safe = the life reaches it)
//   position_step = 0.01            # m
//   [[span]]                        # or spans = "spans.csv"
//   id = "T12-T13"
//   length = 420                    # m
//   tension_fraction = 0.18         # or tension = N, or catenary_parameter = m
//   terrain = 2                     # optional; conductor = "ACSR Drake" or a conductor file;
//                                   # wind = { speed_min = 1, speed_max = 7 }
//
// The spans CSV: columns id, length_m, one of tension_n, tension_fraction and
// catenary_parameter_m (a cell each row), and optionally terrain, conductor,
// wind_speed_min_m_s, wind_speed_max_m_s; a UTF-8 BOM and CRLF accepted.

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/line/schedule.hpp"

namespace stockbridge::io {

/// The line file as parsed (private to the library): the shared tables a span file
/// of one span restates.
struct LineDocument;

struct LineFile {
  line::Line line;
  std::string name;                            ///< [line] name, or the file's stem
  std::vector<std::filesystem::path> inputs;   ///< every file read beside the line file (fingerprinted by a journal)
  std::vector<std::string> warnings;           ///< values outside their typical ranges, each at its line
  std::shared_ptr<const LineDocument> document;  ///< as read
  std::filesystem::path base_directory;        ///< where the line file's relative paths start
};

/// Reads a line file; InputError naming the file (or the spans CSV), line, key,
/// value and expectation. A value a unit slip explains, and a span's tension at
/// which no span hangs, are refused (UnusualValueError) under SlipPolicy::refuse,
/// warnings under warn (as load_span_file).
LineFile load_line_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);
/// The same from TOML text (Python's line(text=...)): messages name `source`;
/// relative paths start at `base_directory` (empty: the working directory).
LineFile load_line_text(std::string_view text, std::string_view source, const std::filesystem::path& base_directory = {},
                        SlipPolicy policy = SlipPolicy::refuse);

/// A span file of span `row.index` with the row's dampers at both ends (every path
/// in it absolute): `stockbridge span` on it balances what the schedule balanced.
std::string span_file_text(const LineFile& file, const line::ScheduleRow& row);

}  // namespace stockbridge::io
