#include "sheet_fit.hpp"

#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "cable_table.hpp"
#include "damper_reading.hpp"
#include "stockbridge/core/digest.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/identification/impedance_identification.hpp"
#include "stockbridge/io/atomic_file.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/version.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace {

/// The cache's key: the program's version, the sheet's and the drawing's bytes (and
/// its cable files'), the numbers fitted.
std::string fit_digest(const std::filesystem::path& sheet, const std::filesystem::path& start,
                       const std::vector<std::filesystem::path>& cable_files, const std::vector<std::string>& free) {
  ContentDigest d;
  d.add(version_string).add_file(sheet).add_file(start);
  for (const std::filesystem::path& cable : cable_files) d.add_file(cable);
  for (const std::string& number : free) d.add(number);
  return d.hex();
}

/// The cache file: [fit] (the figures) and [damper] (the fitted damper's tables).
std::string cache_text(const span::SheetFit& fit, const damper::DamperDescription& fitted) {
  toml::table fit_table;
  fit_table.insert("sheet", fit.sheet);
  fit_table.insert("start", fit.start);
  toml::array free;
  for (const std::string& number : fit.free) free.push_back(number);
  fit_table.insert("free", std::move(free));
  fit_table.insert("rms_relative_error", fit.rms_relative_error);
  fit_table.insert("points", static_cast<std::int64_t>(fit.points));
  fit_table.insert("poor_fit", fit.poor_fit);
  fit_table.insert("lack_of_fit", fit.lack_of_fit);
  toml::table document;
  document.insert("fit", std::move(fit_table));
  document.insert("damper", parse_toml_text(damper_file_toml(fitted, ""), "the fitted damper"));
  std::ostringstream out;
  out << toml_comment_lines(fmt::format("The damper {} fitted to {} (identify impedance --free): a cache of "
                                        "stockbridge's, safe to delete (the next run fits again).",
                                        fit.start, fit.sheet))
      << toml::toml_formatter(document, toml::toml_formatter::default_flags & ~toml::format_flags::allow_literal_strings)
      << "\n";
  return out.str();
}

/// The cache's fit where it is there and reads (a damaged one is fitted again).
std::optional<FittedSheet> read_cache(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  try {
    const toml::table document = parse_toml_file(path);
    const TomlSource source{path.string(), true};
    const toml::table* fit_table = document["fit"].as_table();
    const toml::table* damper = document["damper"].as_table();
    if (!fit_table || !damper) return std::nullopt;
    const TomlTable fit(*fit_table, source, "fit");
    // The program's own numbers: a fitted value outside the typical ranges was warned of when fitted.
    FittedSheet out{build_damper(*damper, source, path.parent_path(), SlipPolicy::warn).damper, {}, {}, {}};
    out.fit.rms_relative_error = fit.number("rms_relative_error");
    out.fit.points = static_cast<int>(fit.integer("points", 1, 1000000));
    out.fit.poor_fit = fit.optional_boolean("poor_fit").value_or(true);
    out.fit.lack_of_fit = fit.optional_boolean("lack_of_fit").value_or(true);
    out.fit.cached = true;
    return out;
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace

std::filesystem::path fit_cache_directory(const std::filesystem::path& base_directory) {
  return base_directory / ".stockbridge-cache";
}

FittedSheet fit_damper_to_sheet(const std::filesystem::path& sheet, const std::string& sheet_name,
                                const std::filesystem::path& start, const std::string& start_name,
                                const std::vector<std::string>& free, const std::filesystem::path& cache,
                                SlipPolicy policy) {
  MeasuredImpedanceFile measured = load_measured_impedance(sheet, policy);
  DamperFile drawing = load_damper_file(start, policy);
  const std::filesystem::path cached = cache / fmt::format("fit-{}.toml", fit_digest(sheet, start, drawing.cable_files, free));
  std::optional<FittedSheet> out = read_cache(cached);
  if (!out) {
    identification::ImpedanceIdentificationOptions options;
    options.free = free;
    options.threads = 2;
    const identification::ImpedanceIdentification fit =
        identification::identify_impedance(drawing.damper.description(), measured.measurement, options);
    out.emplace(FittedSheet{damper::Damper(fit.damper), {}, {}, {}});
    out->fit.rms_relative_error = fit.rms_relative_error;
    out->fit.points = static_cast<int>(measured.measurement.points.size());
    out->fit.poor_fit = fit.poor_fit;
    out->fit.lack_of_fit = fit.lack_of_fit.significant;
    out->fit.sheet = sheet_name;
    out->fit.start = start_name;
    out->fit.free = free;
    try {
      std::filesystem::create_directories(cache);
      write_file_atomically(cached, cache_text(out->fit, fit.damper));
    } catch (const std::exception& e) {
      out->warnings.push_back(fmt::format("the fit of {} could not be kept for the next run ({}): it is fitted again "
                                          "each run",
                                          sheet_name, printable(e.what(), 200)));
    }
  }
  out->fit.sheet = sheet_name;
  out->fit.start = start_name;
  out->fit.free = free;
  out->inputs.push_back(sheet);
  out->inputs.push_back(start);
  out->inputs.insert(out->inputs.end(), drawing.cable_files.begin(), drawing.cable_files.end());
  out->warnings.insert(out->warnings.begin(), measured.warnings.begin(), measured.warnings.end());
  out->warnings.insert(out->warnings.begin(), drawing.warnings.begin(), drawing.warnings.end());
  if (out->fit.poor_fit || out->fit.lack_of_fit) {
    out->warnings.push_back(fmt::format("the damper fitted to {} from {} does not follow the sheet (RMS {:.3g} % of |Z|{}): "
                                        "check the drawing's fixed numbers (identify impedance --free ... prints which "
                                        "may be wrong) before trusting its span",
                                        sheet_name, start_name, 100.0 * out->fit.rms_relative_error,
                                        out->fit.lack_of_fit ? ", beyond a 1 % scatter" : ""));
  }
  return *out;
}

}  // namespace stockbridge::io
