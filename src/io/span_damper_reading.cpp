#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "sheet_fit.hpp"
#include "span_reading.hpp"
#include "toml_reader.hpp"

// The dampers a span file (and a line file's damper types) names: a damper file's
// model, a measured impedance sheet, or a damper fitted to a sheet from its drawing,
// each file read once and listed among the inputs, its warnings kept once.
namespace stockbridge::io::span_reading {

/// The warnings of a file a span file reads, each once.
void span_add_warnings(SpanReading& reading, std::vector<std::string> warnings) {
  for (std::string& warning : warnings) {
    if (std::find(reading.warnings.begin(), reading.warnings.end(), warning) == reading.warnings.end()) {
      reading.warnings.push_back(std::move(warning));
    }
  }
}

/// A measured damper: its sheet (one per file, shared by the [[damper]] entries that name it).
std::shared_ptr<const span::ImpedanceSheet> read_sheet(const TomlTable& table, const std::string& file,
                                                       const std::filesystem::path& base_directory,
                                                       SpanReading& reading) {
  const std::filesystem::path path =
      span_input_file(table, "impedance", file, base_directory, "measured impedance CSV file");
  for (const auto& [read, sheet] : reading.sheets) {
    if (read == path) return sheet;
  }
  MeasuredImpedanceFile loaded = load_measured_impedance(path, reading.policy);
  span_add_warnings(reading, std::move(loaded.warnings));
  reading.inputs.push_back(path);
  try {
    auto sheet = std::make_shared<const span::ImpedanceSheet>(std::move(loaded.measurement), path.stem().string());
    reading.sheets.emplace_back(path, sheet);
    return sheet;
  } catch (const InvalidParameter& e) {
    table.fail("impedance", fmt::format("\"{}\"{}", printable(file), e.detail()));
  }
}

/// A measured sheet's damper fitted from its drawing (`fit_from`, with `free`).
DamperSource fitted_damper_source(const TomlTable& table, const std::string& measured, const std::string& start,
                                  const std::filesystem::path& base_directory, SpanReading& reading) {
  const std::vector<std::string> free = table.optional_string_array("free").value_or(std::vector<std::string>{});
  const std::filesystem::path sheet =
      span_input_file(table, "impedance", measured, base_directory, "measured impedance CSV file");
  const std::filesystem::path drawing = span_input_file(table, "fit_from", start, base_directory, "damper file");
  FittedSheet fitted = [&] {
    try {
      return fit_damper_to_sheet(sheet, measured, drawing, start, free, fit_cache_directory(base_directory),
                                 reading.policy);
    } catch (const InvalidParameter& e) {  // a number of `free` the drawing does not have
      table.fail("free", e.what());
    }
  }();
  reading.inputs.insert(reading.inputs.end(), fitted.inputs.begin(), fitted.inputs.end());
  span_add_warnings(reading, std::move(fitted.warnings));
  DamperSource source;
  source.path = sheet;
  source.damper = std::move(fitted.damper);
  source.fit = std::move(fitted.fit);
  source.fit_from = drawing;
  source.name = sheet.stem().string() + " (fitted)";
  return source;
}

DamperSource read_damper_source(const TomlTable& table, const std::filesystem::path& base_directory,
                                SpanReading& reading, const std::string& missing) {
  const std::optional<std::string> model = table.optional_string("file");
  const std::optional<std::string> measured = table.optional_string("impedance");
  const std::optional<std::string> fit_from = table.optional_string("fit_from");
  if (model.has_value() == measured.has_value()) {
    if (model) table.fail("impedance", "given beside file: expected a damper file or a measured sheet, one of the two");
    throw InputError(table.location("file") + missing);
  }
  if (fit_from && !measured) {
    table.fail("fit_from", "given beside file: fit_from fits the damper file's model to impedance = a measured sheet");
  }
  if (!fit_from && table.present("free")) table.fail("free", "given without fit_from: the numbers free in the fit to a sheet");
  if (fit_from) return fitted_damper_source(table, *measured, *fit_from, base_directory, reading);
  DamperSource source;
  if (measured) {
    source.path = span_input_file(table, "impedance", *measured, base_directory, "measured impedance CSV file");
    source.sheet = read_sheet(table, *measured, base_directory, reading);
    source.name = source.sheet->name();
    return source;
  }
  source.path = span_input_file(table, "file", *model, base_directory, "damper file");
  DamperFile loaded = load_damper_file(source.path, reading.policy);
  reading.inputs.push_back(source.path);
  reading.inputs.insert(reading.inputs.end(), loaded.cable_files.begin(), loaded.cable_files.end());
  span_add_warnings(reading, std::move(loaded.warnings));
  source.damper = std::move(loaded.damper);
  source.name = source.path.stem().string();
  return source;
}

}  // namespace stockbridge::io::span_reading
