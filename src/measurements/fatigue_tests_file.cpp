#include "stockbridge/measurements/fatigue_tests_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <string_view>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/span/stranded_conductor.hpp"

namespace stockbridge::measurements {

namespace {

constexpr std::array<std::string_view, 6> kFatigueTestColumns{"test", "conductor", "tension_n",
                                                              "yb_pp_mm", "cycles", "failed"};

/// A cell's number, > 0: InputError at the row naming the column otherwise.
double fatigue_test_number(const std::string& cell, const std::string& where, std::string_view column,
                           std::string_view what) {
  if (cell.empty()) throw InputError(fmt::format("{}column '{}' is empty: expected {}", where, column, what));
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value)) {
    throw InputError(fmt::format("{}column '{}' = '{}': expected a number ('.' as decimal separator): {}", where, column,
                                 printable(cell), what));
  }
  if (!(value > 0.0)) {
    throw InputError(fmt::format("{}column '{}' = {}: expected a number > 0: {}", where, column, format_value(value), what));
  }
  return value;
}

bool fatigue_test_failed(const std::string& cell, const std::string& where) {
  std::string lower = cell;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "true" || lower == "1") return true;
  if (lower == "false" || lower == "0") return false;
  throw InputError(fmt::format("{}column 'failed' = '{}': expected true (the conductor broke) or false (a runout)", where,
                               printable(cell)));
}

/// The tests are set against the CIGRE Safe Border Line, stated for aluminium outer
/// wires only: a conductor of steel or aluminium-clad steel outer wires is refused.
span::Conductor with_aluminium_outer_wires(span::Conductor conductor, const std::string& name, const std::string& where) {
  if (conductor.safe_border_line_applies()) return conductor;
  throw InputError(fmt::format("{}column 'conductor' = '{}': outer wires of {}: expected a conductor with aluminium or "
                               "aluminium-alloy outer wires (the tests are set against the CIGRE Safe Border Line, "
                               "stated for those only)",
                               where, printable(name), span::wire_material_name(conductor.outer_wire_material)));
}

/// The row's conductor: a conductor file (*.toml, relative to the CSV's folder) or the catalogue's type.
span::Conductor fatigue_test_conductor(const std::string& name, const std::filesystem::path& base,
                                       const std::string& where, std::vector<std::filesystem::path>& inputs) {
  if (name.empty()) {
    throw InputError(where + "column 'conductor' is empty: expected a catalogue type (stockbridge conductors) or a "
                             "conductor file (*.toml)");
  }
  if (name.size() > 5 && name.ends_with(".toml")) {
    const std::filesystem::path path = std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : base / name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      throw InputError(fmt::format("{}column 'conductor' = '{}': expected an existing conductor file (looked for {}; "
                                   "relative paths start at the CSV file's folder) or a catalogue type",
                                   where, printable(name), printable(path.string(), 300)));
    }
    inputs.push_back(path);
    return with_aluminium_outer_wires(span::conductor_of(io::read_conductor_file(path)), name, where);
  }
  const span::StrandedConductor* entry = nullptr;
  try {
    entry = &io::catalogue_conductor(name);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}column 'conductor'{}, or a conductor file (*.toml)", where, e.detail()));
  }
  return with_aluminium_outer_wires(span::conductor_of(*entry), name, where);
}

}  // namespace

FatigueTestsFile read_fatigue_tests_file(const std::filesystem::path& path, SlipPolicy policy) {
  const io::CsvCells csv = io::read_csv_cells(path);
  const std::string file = path.string();
  std::array<std::size_t, kFatigueTestColumns.size()> column{};
  for (std::size_t k = 0; k < kFatigueTestColumns.size(); ++k) {
    const auto found = std::find(csv.header.begin(), csv.header.end(), kFatigueTestColumns[k]);
    if (found == csv.header.end()) {
      throw InputError(fmt::format("{}:{}: missing column '{}': expected a header with test, conductor, tension_n, "
                                   "yb_pp_mm, cycles, failed",
                                   file, csv.lines.empty() ? 1 : csv.lines.front() - 1, kFatigueTestColumns[k]));
    }
    if (std::find(found + 1, csv.header.end(), kFatigueTestColumns[k]) != csv.header.end()) {
      throw InputError(fmt::format("{}: column '{}' appears twice", file, kFatigueTestColumns[k]));
    }
    column[k] = static_cast<std::size_t>(found - csv.header.begin());
  }
  if (csv.rows.empty()) throw InputError(fmt::format("{}: no data rows: expected one row per fatigue test", file));
  FatigueTestsFile out;
  out.inputs.push_back(path);
  std::map<std::string, span::Conductor> conductors;
  const std::filesystem::path base = path.parent_path();
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const std::vector<std::string>& row = csv.rows[r];
    const std::string where = fmt::format("{}:{}: ", file, csv.lines[r]);
    FatigueTest t;
    t.line = csv.lines[r];
    t.test = row[column[0]];
    if (t.test.empty()) throw InputError(where + "column 'test' is empty: expected the test's name");
    t.conductor_name = row[column[1]];
    if (const auto known = conductors.find(t.conductor_name); known != conductors.end()) {
      t.conductor = known->second;
    } else {
      t.conductor = fatigue_test_conductor(t.conductor_name, base, where, out.inputs);
      conductors.emplace(t.conductor_name, t.conductor);
    }
    t.tension = fatigue_test_number(row[column[2]], where, "tension_n", "the test's tension, N");
    const double yb_mm = fatigue_test_number(row[column[3]], where, "yb_pp_mm",
                                             "Yb, peak-to-peak at 89 mm from the clamp, mm");
    t.yb_pp = 1e-3 * yb_mm;
    t.cycles = fatigue_test_number(row[column[4]], where, "cycles", "the cycles reached (to the failure, or the runout's)");
    t.failed = fatigue_test_failed(row[column[5]], where);
    std::vector<UnusualValue> unusual;
    check_typical(unusual, "tension_n", t.tension, typical::span_tension);
    check_typical(unusual, "yb_pp_mm", yb_mm, typical::yb_pp_mm);
    for (const UnusualValue& u : unusual) judge_unusual(u, where + "column ", policy, out.warnings);
    out.tests.push_back(std::move(t));
  }
  return out;
}

}  // namespace stockbridge::measurements
