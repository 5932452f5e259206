#pragma once
// The request layer for a line's damper schedule (`stockbridge line`, Python's
// line): the schedule's rows as the CSV columns every front end shows, the bill of
// materials, the JSON summary, and a row as one journal record (a line of text that
// gives the row back bit for bit: what MPI ranks send and --resume reads).

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/io/line_file.hpp"
#include "stockbridge/line/schedule.hpp"
#include "stockbridge/requests/output_table.hpp"

namespace stockbridge::requests {

/// The schedule CSV, a row per span (docs/line.md): id, conductor, verdicts, the
/// damper type, positions_m (one end's, ';'-separated, increasing), warnings; then
/// length_m, tension_n, tension_percent_rts, catenary_parameter_m,
/// span_parameter_m3_kg, terrain, endurance_limit_mpa, the undamped and damped
/// largest stress and life, dampers_per_end, stress_ratio, margin_percent, converged,
/// converged_points, points, search_balances. A stress or life is empty unless every
/// point of its balance converged.
Table<line::ScheduleRow> schedule_table();
/// The bill of materials: damper_type, dampers, spans, mass_kg.
Table<line::BillLine> bill_table();

/// A line's schedule: a row for every span in the line's order, and its bill of
/// materials (built once, for the CSV, the summary and the report).
struct LineSchedule {
  std::vector<line::ScheduleRow> rows;
  std::vector<line::BillLine> bill;
};
/// The schedule of `rows` (a row per span of the line, by index; InvalidParameter
/// naming the first span without one).
LineSchedule line_schedule(const io::LineFile& file, std::map<std::size_t, line::ScheduleRow> rows);

/// The JSON summary of a schedule: the line's name, spans, spans_safe, spans_unsafe,
/// spans_unknown, spans_not_converged, spans_worse_than_undamped, dampers_per_end
/// (spans with 0, 1, 2, ...), the bill, the governing span (the largest stress
/// ratio), and `seconds` where given.
io::JsonObject line_summary(const io::LineFile& file, const LineSchedule& schedule);

/// A row as one line of text (no line break): tab-separated fields, numbers in their
/// shortest round-trip form, text escaped.
std::string schedule_record(const line::ScheduleRow& row);
/// The row of a record; InvalidParameter naming "record" where it is not one (a
/// record cut short by an interruption).
line::ScheduleRow parse_schedule_record(std::string_view record);

/// What a journal's first line holds: a digest of everything the schedule depends on
/// (the line file's bytes or text, every file it reads, the program's version), so
/// that a journal of other inputs is never resumed.
std::string line_fingerprint(const io::LineFile& file, std::string_view line_text);

/// A row for a span whose scheduling threw (an error the span's own data caused):
/// verdict unknown, nothing converged, the message as its warning.
line::ScheduleRow failed_row(const io::LineFile& file, std::size_t index, std::string_view message);

}  // namespace stockbridge::requests
