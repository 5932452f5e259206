#pragma once
// The span file's table readers (private to the library), shared by the span file
// (span_file.cpp) and the line file (line_file.cpp), whose shared tables are a
// span file's: [conductor], [wind], [self_damping], [fatigue], [balance].

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stockbridge/io/span_file.hpp"
#include "stockbridge/span/stranded_conductor.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io::span_reading {

/// A span file's contents before the model validates them.
struct SpanReading {
  /// What the readers do with a value a unit slip explains (typical_ranges.hpp).
  SlipPolicy policy = SlipPolicy::refuse;
  span::Conductor conductor;
  double length = 0.0;
  std::optional<double> tension;
  std::optional<double> tension_fraction;
  std::optional<double> catenary_parameter;
  std::optional<int> terrain;
  bool wind_law_by_terrain = false;  ///< [span] wind_law_by_terrain
  span::WindModel wind;
  bool turbulence_given = false;     ///< [wind] turbulence_intensity given
  span::SelfDampingModel self_damping;
  std::vector<span::SpanDamper> dampers;
  std::vector<span::SpanMass> masses;
  span::FatigueSpec fatigue;
  span::BalanceOptions balance;
  span::TimeSettings time;           ///< [span] ends, [time]
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> warnings;
  /// The measured sheets read, by path.
  std::vector<std::pair<std::filesystem::path, std::shared_ptr<const span::ImpedanceSheet>>> sheets;
};

/// A file the table names at `key`, resolved against `base_directory` and found;
/// InputError at the key's line otherwise, `what` naming the kind of file.
std::filesystem::path span_input_file(const TomlTable& table, std::string_view key, const std::string& file,
                                      const std::filesystem::path& base_directory, std::string_view what);
/// The catalogue's conductor `type`; its InvalidParameter at the table's `type` line.
span::StrandedConductor span_catalogue_conductor(const TomlTable& table, const std::string& type);
/// A conductor file (the table's `file` key), listed among the inputs.
span::StrandedConductor span_conductor_file(const TomlTable& table, const std::string& file,
                                            const std::filesystem::path& base_directory, SpanReading& reading);
span::Conductor read_conductor(const TomlTable& table, const std::filesystem::path& base_directory, SpanReading& reading);
void read_wind(const TomlTable& table, const std::filesystem::path& base_directory, SpanReading& reading);
span::SelfDampingModel read_self_damping(const TomlTable& table);
/// The [fatigue] table; its `curve` (an S-N curve file, relative to `base_directory`)
/// read and listed among the inputs.
span::FatigueSpec read_fatigue(const TomlTable& table, const std::filesystem::path& base_directory,
                               SpanReading& reading);
span::BalanceOptions read_balance(const std::optional<TomlTable>& table);
/// A [[mass]] entry (name, mass, positions, stress_factor); its name "mass <index + 1>"
/// where not given. The model checks its values.
span::SpanMass read_span_mass(const TomlTable& table, std::size_t index);
/// A measured sheet named at the table's `impedance` key (one per file).
std::shared_ptr<const span::ImpedanceSheet> read_sheet(const TomlTable& table, const std::string& file,
                                                       const std::filesystem::path& base_directory,
                                                       SpanReading& reading);
/// A damper a table gives as `file` (a damper file: its model) or `impedance` (a
/// measured sheet), one of the two, read and its files listed among the inputs; its
/// name the damper file's stem or the sheet's. InputError at the table otherwise:
/// `missing` is the message when neither is given (the table's own words: where
/// its paths start).
struct DamperSource {
  std::optional<damper::Damper> damper;              ///< the model (none: the sheet)
  std::shared_ptr<const span::ImpedanceSheet> sheet;  ///< the measured sheet, where there is no model
  std::filesystem::path path;                        ///< the file read
  std::string name;
  std::optional<span::SheetFit> fit;                 ///< the model fitted to the sheet (fit_from)
  std::filesystem::path fit_from;                    ///< the drawing it was fitted from
};
DamperSource read_damper_source(const TomlTable& table, const std::filesystem::path& base_directory,
                                SpanReading& reading, const std::string& missing);

/// A file's warnings added, each once.
void span_add_warnings(SpanReading& reading, std::vector<std::string> warnings);
/// The values outside their typical ranges, each at its line: the shared tables', and
/// the [span] table's and the dampers' where `with_span` (a line's spans are checked
/// where they are given); one a unit slip explains refused (UnusualValueError) where
/// the reading's policy says so.
void add_span_warnings(const SpanReading& reading, const toml::table& document, const TomlSource& source,
                       std::vector<std::string>& warnings, bool with_span = true);
/// A span's tension (N) judged against how spans hang (span::implausible_tension):
/// `location` and `key` name it as given (the [span] table's key or a CSV column),
/// `given` its value there; refused or a warning by `policy`.
void judge_span_tension(const span::Conductor& conductor, double length, double tension, const std::string& location,
                        std::string_view key, double given, SlipPolicy policy, std::vector<std::string>& warnings);

}  // namespace stockbridge::io::span_reading
