#include "stockbridge/io/span_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/input_file.hpp"
#include "stockbridge/io/measured_impedance_file.hpp"
#include "stockbridge/io/sn_curve_file.hpp"
#include "stockbridge/io/span_names.hpp"
#include "stockbridge/span/stranded_conductor.hpp"
#include "stockbridge/span/tension_figures.hpp"
#include "sheet_fit.hpp"
#include "span_reading.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {

namespace span_reading {

std::filesystem::path span_resolve(const std::filesystem::path& file, const std::filesystem::path& base_directory) {
  return file.is_absolute() ? file : base_directory / file;
}

/// Where a span's relative paths start, as messages say it.
std::string span_base(const TomlTable& table, const std::filesystem::path& base_directory) {
  if (table.has_lines()) return "the file's folder";
  if (base_directory.empty()) return "the working directory (the text has no folder)";
  return fmt::format("{} (the text's base folder)", printable(base_directory.string(), 300));
}

/// A file the span file names at `key` (a conductor file, a damper file, a measured
/// sheet), resolved against the span's folder and found.
std::filesystem::path span_input_file(const TomlTable& table, std::string_view key, const std::string& file,
                                      const std::filesystem::path& base_directory, std::string_view what) {
  const std::filesystem::path path = span_resolve(file, base_directory);
  std::error_code absolute;
  existing_input_file(table.where(key), {file, std::filesystem::absolute(path, absolute), what,
                                         span_base(table, base_directory)});
  return path;
}

/// A name the model parses (a law): its InvalidParameter at the key's line, named by the key's full path.
template <class Parse>
auto span_parsed_name(const TomlTable& table, std::string_view key, const std::string& text, Parse parse) {
  try {
    return parse(text);
  } catch (const InvalidParameter& e) {
    throw InputError(table.location(key) + e.within(table.key_path()).what());
  }
}

/// The conductor a [conductor] table's `type` names: the catalogue's entry, its
/// InvalidParameter (an unknown type, with the known ones) at the key's line.
span::StrandedConductor span_catalogue_conductor(const TomlTable& table, const std::string& type) {
  try {
    return io::catalogue_conductor(type);
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}{}, or file = a conductor file", table.location("type"),
                                 e.within(table.key_path()).what()));
  }
}

/// The conductor of a [conductor] table's `file`, relative to the span file's folder
/// (span text: its base folder); the file's own errors name it and its line.
span::StrandedConductor span_conductor_file(const TomlTable& table, const std::string& file,
                                            const std::filesystem::path& base_directory, SpanReading& reading) {
  const std::filesystem::path path = span_input_file(table, "file", file, base_directory, "conductor file");
  span::StrandedConductor conductor = read_conductor_file(path);
  reading.inputs.push_back(path);
  return conductor;
}

/// The outer wires' material a [conductor] table gives (outer_wire_material), if it does.
std::optional<span::WireMaterial> read_outer_wire_material(const TomlTable& table) {
  const std::optional<std::string> name = table.optional_string("outer_wire_material");
  if (!name) return std::nullopt;
  return span_parsed_name(table, "outer_wire_material", *name,
                          [](const std::string& text) { return span::parse_wire_material(text, "outer_wire_material"); });
}

/// aluminium_layers' least value: 1 where the outer wires are aluminium (it picks the
/// Safe Border Line), 0 for an earth wire of steel or aluminium-clad steel.
int fewest_aluminium_layers(span::WireMaterial outer) { return span::is_aluminium(outer) ? 1 : 0; }

/// The [conductor] table: every key given (mass_per_length ... aluminium_layers), or
/// `type` (the catalogue's conductor) or `file` (a conductor file), whose derived
/// values (span::conductor_of) the keys given beside it override.
span::Conductor read_conductor(const TomlTable& table, const std::filesystem::path& base_directory, SpanReading& reading) {
  table.accept_only({"type", "file", "name", "mass_per_length", "diameter", "rated_tensile_strength", "ei_min",
                           "ei_max", "outer_wire_diameter", "outer_wire_modulus", "aluminium_layers",
                           "outer_wire_material"});
  const std::optional<span::WireMaterial> outer = read_outer_wire_material(table);
  const std::optional<std::string> type = table.optional_string("type");
  const std::optional<std::string> file = table.optional_string("file");
  if (type && file) {
    table.fail("file", fmt::format("given beside {}: expected one of type (a conductor of the catalogue) and file (a "
                                   "conductor file)",
                                   table.qualified("type")));
  }
  span::Conductor c;
  if (!type && !file) {
    // Without type or file every key is given: a key missing names the two
    // alternatives too (a deleted type line leaves a table of overrides).
    constexpr std::string_view kRequired[] = {"mass_per_length", "diameter", "rated_tensile_strength", "ei_min",
                                              "outer_wire_diameter", "outer_wire_modulus", "aluminium_layers"};
    const span::WireMaterial outer_material = outer.value_or(span::WireMaterial::aluminium);
    for (const std::string_view key : kRequired) {
      if (table.present(key) || (key == "aluminium_layers" && !span::is_aluminium(outer_material))) continue;
      throw InputError(fmt::format("{}missing key '{}' in [{}]: expected type = a conductor of the catalogue (e.g. "
                                   "\"ACSR Drake\"), file = a conductor file, or every one of mass_per_length, diameter, "
                                   "rated_tensile_strength, ei_min, outer_wire_diameter, outer_wire_modulus and "
                                   "aluminium_layers",
                                   table.location(key), key, table.key_path()));
    }
    c.name = table.optional_string("name").value_or("");
    c.mass_per_length = table.number("mass_per_length");
    c.diameter = table.number("diameter");
    c.rated_tensile_strength = table.number("rated_tensile_strength");
    c.ei_min = table.number("ei_min");
    c.ei_max = table.optional_number("ei_max").value_or(0.0);
    c.outer_wire_diameter = table.number("outer_wire_diameter");
    c.outer_wire_modulus = table.number("outer_wire_modulus");
    c.outer_wire_material = outer_material;
    c.aluminium_layers = static_cast<int>(  // Conductor::validate's range
        table.optional_integer("aluminium_layers", fewest_aluminium_layers(outer_material), 10).value_or(0));
    c.source = "the [conductor] keys";
    return c;
  }
  c = span::conductor_of(type ? span_catalogue_conductor(table, *type)
                              : span_conductor_file(table, *file, base_directory, reading));
  c.source = type ? fmt::format("the catalogue's {}", *type) : fmt::format("the conductor file {}", *file);
  std::string given;
  for (const std::string_view key : {"name", "mass_per_length", "diameter", "rated_tensile_strength", "ei_min", "ei_max",
                                     "outer_wire_diameter", "outer_wire_modulus", "outer_wire_material", "aluminium_layers"}) {
    if (table.contains(key)) given += fmt::format("{}{}", given.empty() ? "" : ", ", key);
  }
  if (!given.empty()) c.source += fmt::format("; {} given beside it", given);
  c.name = table.optional_string("name").value_or(c.name);
  c.mass_per_length = table.optional_number("mass_per_length").value_or(c.mass_per_length);
  c.diameter = table.optional_number("diameter").value_or(c.diameter);
  c.rated_tensile_strength = table.optional_number("rated_tensile_strength").value_or(c.rated_tensile_strength);
  c.ei_min = table.optional_number("ei_min").value_or(c.ei_min);
  c.ei_max = table.optional_number("ei_max").value_or(c.ei_max);
  c.outer_wire_diameter = table.optional_number("outer_wire_diameter").value_or(c.outer_wire_diameter);
  c.outer_wire_modulus = table.optional_number("outer_wire_modulus").value_or(c.outer_wire_modulus);
  c.outer_wire_material = outer.value_or(c.outer_wire_material);
  if (const auto n = table.optional_integer("aluminium_layers", fewest_aluminium_layers(c.outer_wire_material), 10)) {
    c.aluminium_layers = static_cast<int>(*n);
  }
  return c;
}

void read_span_table(const TomlTable& table, SpanReading& reading) {
  table.accept_only(
      {"length", "tension", "tension_fraction", "catenary_parameter", "terrain", "wind_law_by_terrain", "ends"});
  if (const auto ends = table.optional_string("ends")) {
    reading.time.ends = span_parsed_name(table, "ends", *ends, span::parse_beam_ends);
  }
  reading.wind_law_by_terrain = table.optional_boolean("wind_law_by_terrain").value_or(false);
  reading.length = table.number("length");
  reading.tension = table.optional_number("tension");
  reading.tension_fraction = table.optional_number("tension_fraction");
  reading.catenary_parameter = table.optional_number("catenary_parameter");
  if (const auto terrain = table.optional_integer("terrain", 1, 4)) reading.terrain = static_cast<int>(*terrain);
  std::vector<std::string_view> given;  // the forms of the tension given, in this order
  for (const auto& [form, value] : {std::pair{"tension", &reading.tension}, {"tension_fraction", &reading.tension_fraction},
                                    {"catenary_parameter", &reading.catenary_parameter}}) {
    if (value->has_value()) given.push_back(form);
  }
  if (given.empty()) {
    throw InputError(fmt::format("{}missing key 'tension' in [span]: expected one of tension (N), tension_fraction (of "
                                 "the rated tensile strength) and catenary_parameter (H/w, m)",
                                 table.location("tension")));
  }
  if (given.size() > 1) {
    table.fail(given[1], fmt::format("given beside span.{}: expected one of tension (N), tension_fraction and "
                                     "catenary_parameter (H/w, m)",
                                     given[0]));
  }
}

/// The [time] table: the mesh, step and length of a run in time.
void read_time_table(const TomlTable& table, span::TimeSettings& time) {
  table.accept_only({"elements_per_wavelength", "steps_per_period", "duration"});
  if (const auto n = table.optional_integer("elements_per_wavelength", 4, 1000)) {
    time.elements_per_wavelength = static_cast<int>(*n);
  }
  if (const auto n = table.optional_integer("steps_per_period", 8, 100000)) time.steps_per_period = static_cast<int>(*n);
  if (const auto d = table.optional_number("duration", [](std::string_view key, double value) {
        require_positive(key, value, "s");
      })) {
    time.duration_s = *d;
  }
}

/// The [wake] table: the wake oscillator's parameters (span::WakeParameters).
void read_wake_table(const TomlTable& table, span::WakeParameters& wake) {
  table.accept_only({"epsilon", "coupling", "lift_coefficient", "air_density"});
  const auto positive = [](std::string_view key, double value) { require_positive(key, value, ""); };
  wake.epsilon = table.optional_number("epsilon", positive).value_or(wake.epsilon);
  wake.coupling = table.optional_number("coupling", positive).value_or(wake.coupling);
  wake.lift_coefficient = table.optional_number("lift_coefficient", positive).value_or(wake.lift_coefficient);
  wake.air_density = table.optional_number("air_density", positive).value_or(wake.air_density);
}

void read_wind(const TomlTable& table, const std::filesystem::path& base_directory, SpanReading& reading) {
  table.accept_only({"law", "strouhal", "speed_min", "speed_max", "turbulence_intensity", "table", "power_scale"});
  span::WindModel& wind = reading.wind;
  const std::string law =
      table.required_string("law", "a string: cigre, foti, diana-falco, rawlins-1983, brika-laneville or table");
  wind.law = span_parsed_name(table, "law", law, span::parse_wind_law);
  if (const auto v = table.optional_number("strouhal")) wind.strouhal = *v;
  if (const auto v = table.optional_number("speed_min")) wind.speed_min = *v;
  if (const auto v = table.optional_number("speed_max")) wind.speed_max = *v;
  if (const auto v = table.optional_number("power_scale")) wind.power_scale = *v;
  if (const auto v = table.optional_number("turbulence_intensity")) {
    wind.turbulence_intensity = *v;
    reading.turbulence_given = true;
  }
  const std::optional<std::string> file = table.optional_string("table");
  if (wind.law != span::WindLaw::table) {
    if (file) {
      table.fail("table", fmt::format("\"{}\": only law = \"table\" uses a table (law is \"{}\")", printable(*file),
                                      printable(law)));
    }
    return;
  }
  if (!file) {
    throw InputError(fmt::format("{}missing key 'table' in [wind]: expected the CSV file of law = \"table\" "
                                 "(columns y_over_d,fnc; relative paths start at the span file's folder)",
                                 table.location("table")));
  }
  const std::filesystem::path path = existing_input_file(
      table.where("table"), {*file, span_resolve(*file, base_directory), "CSV file", "the span file's folder"});
  const CsvRows rows = read_csv_rows(path, {"y_over_d", "fnc"}, 2);
  for (std::size_t i = 0; i < rows.lines.size(); ++i) {
    const double y = rows.columns[0][i];
    const auto at = [&](std::string_view column, double value, std::string_view expected) {
      return InputError(fmt::format("{}:{}: column '{}' = {}: expected {}", path.string(), rows.lines[i], column,
                                    format_value(value), expected));
    };
    if (!(y >= 0.0) || y > 10.0) throw at("y_over_d", y, "an amplitude over the diameter from 0 to 10");
    if (i > 0 && !(y > rows.columns[0][i - 1])) {
      throw at("y_over_d", y, fmt::format("more than the row before's {} (increasing)", format_value(rows.columns[0][i - 1])));
    }
    if (std::abs(rows.columns[1][i]) > 1e3) {
      throw at("fnc", rows.columns[1][i], "a reduced wind power within +-1000 W/(m Hz^3 m^4) (the published curves lie below 10)");
    }
    wind.table.push_back({y, rows.columns[1][i]});
  }
  reading.inputs.push_back(path);
}

span::SelfDampingModel read_self_damping(const TomlTable& table) {
  table.accept_only({"law", "k", "l", "m", "n", "limit_curvature"});
  span::SelfDampingModel model;
  const std::string law = table.required_string("law", "a string: a named law (noiseux-1991, ...), power or foti");
  model.law = span_parsed_name(table, "law", law, span::parse_self_damping_law);
  model.k = table.optional_number("k");
  model.l = table.optional_number("l");
  model.m = table.optional_number("m");
  model.n = table.optional_number("n");
  model.limit_curvature = table.optional_number("limit_curvature");
  return model;
}

/// A span damper's name in tables and messages: its damper file's (or sheet's) stem.
span::SpanDamper read_span_damper(const TomlTable& table, const std::filesystem::path& base_directory,
                                  SpanReading& reading) {
  table.accept_only({"file", "impedance", "fit_from", "free", "position", "ends", "positions"});
  std::vector<double> along;
  if (table.present("positions")) {
    if (table.present("position")) {
      table.fail("positions", "given beside position: expected position (m from each end's clamp, with ends) or "
                              "positions = [..] (m from end 1, anywhere along the span), one of the two");
    }
    if (table.present("ends")) {
      table.fail("ends", "given beside positions: positions are measured from end 1 along the whole span");
    }
    along = table.number_array("positions");
  }
  const double position = along.empty() ? table.number("position") : 0.0;
  bool both_ends = along.empty();
  if (const auto ends = table.optional_string("ends")) {
    if (*ends != "both" && *ends != "one") {
      table.fail("ends", fmt::format("\"{}\": expected \"both\" (a damper at each end of the span) or \"one\" "
                                     "(at one end)",
                                     printable(*ends)));
    }
    both_ends = *ends == "both";
  }
  DamperSource source = read_damper_source(
      table, base_directory, reading,
      fmt::format("missing key 'file' in [{}]: expected the damper file (relative to the span file), or impedance = a "
                  "measured impedance CSV file",
                  table.key_path()));
  return span::SpanDamper{std::move(source.damper), position,           both_ends,
                          std::move(source.name),   std::move(source.sheet), std::move(source.fit),
                          std::move(along)};
}

/// A [[mass]] entry: a rigid mass at one or more positions (m from end 1).
span::SpanMass read_span_mass(const TomlTable& table, std::size_t index) {
  table.accept_only({"name", "mass", "positions", "stress_factor"});
  span::SpanMass mass;
  mass.name = table.optional_string("name").value_or(fmt::format("mass {}", index + 1));
  mass.mass = table.number("mass");
  mass.positions = table.number_array("positions");
  mass.stress_factor = table.optional_number("stress_factor").value_or(mass.stress_factor);
  return mass;
}

/// The criterion, named or told by the one limit given: cycles (the Safe Border
/// Line), endurance_limit_mpa or endurance_limit (Pa: a stress), limit_pp_microstrain.
span::FatigueCriterion read_criterion(const TomlTable& table, const span::FatigueSpec& fatigue) {
  if (const auto name = table.optional_string("criterion")) {
    return span_parsed_name(table, "criterion", *name, span::parse_fatigue_criterion);
  }
  if (fatigue.endurance_limit) return span::FatigueCriterion::stress;
  if (fatigue.limit_pp_microstrain) return span::FatigueCriterion::microstrain;
  if (!fatigue.cycles) {
    throw InputError(fmt::format("{}missing key 'cycles' in [fatigue]: expected cycles (the Safe Border Line at that "
                                 "many cycles), endurance_limit_mpa (a given endurance limit), limit_pp_microstrain, "
                                 "or criterion = \"safe-border-line\", \"microstrain\" or \"stress\"",
                                 table.location("cycles")));
  }
  return span::FatigueCriterion::safe_border_line;
}

span::FatigueSpec read_fatigue(const TomlTable& table, const std::filesystem::path& base_directory,
                               SpanReading& reading) {
  table.accept_only({"criterion", "cycles", "endurance_limit", "endurance_limit_mpa", "limit_pp_microstrain",
                     "wind_weibull", "aeolian_fraction", "yb_distance", "curve"});
  span::FatigueSpec fatigue;
  if (const auto curve = table.optional_string("curve")) {
    const std::filesystem::path path = span_input_file(table, "curve", *curve, base_directory, "S-N curve file");
    fatigue.curve = read_sn_curve_file(path);
    reading.inputs.push_back(path);
  }
  fatigue.cycles = table.optional_number("cycles");
  fatigue.endurance_limit = table.optional_number("endurance_limit");
  const std::optional<double> mpa = table.optional_number("endurance_limit_mpa");
  if (mpa) {
    if (fatigue.endurance_limit) {
      table.fail("endurance_limit_mpa", "given beside endurance_limit (Pa): expected one of the two");
    }
    fatigue.endurance_limit = *mpa * 1e6;
  }
  fatigue.limit_pp_microstrain = table.optional_number("limit_pp_microstrain");
  fatigue.criterion = read_criterion(table, fatigue);
  // FatigueSpec::validate names the model's endurance_limit: a limit given in MPa is
  // refused here, at its own key.
  if (mpa && fatigue.criterion != span::FatigueCriterion::stress) {
    table.fail("endurance_limit_mpa", fmt::format("given beside criterion = \"{}\", which does not use it",
                                                  span::fatigue_criterion_name(fatigue.criterion)));
  }
  fatigue.yb_distance = table.optional_number("yb_distance").value_or(fatigue.yb_distance);
  const std::optional<TomlTable> weibull = table.optional_table("wind_weibull");
  const std::optional<double> fraction = table.optional_number("aeolian_fraction");
  if (weibull.has_value() != fraction.has_value()) {
    const std::string_view missing = weibull ? "aeolian_fraction" : "wind_weibull";
    throw InputError(fmt::format("{}missing key '{}' in [fatigue]: the life estimate needs wind_weibull = {{ shape, "
                                 "scale }} (m/s) and aeolian_fraction (the share of the year with steady low wind), "
                                 "both or neither",
                                 table.location(missing), missing));
  }
  if (weibull) {
    weibull->accept_only({"shape", "scale"});
    span::LifeModel life;
    life.wind_weibull.shape = weibull->number("shape");
    life.wind_weibull.scale = weibull->number("scale");
    life.aeolian_fraction = *fraction;
    fatigue.life = life;
  }
  return fatigue;
}

/// The optional [balance] table: how the span is balanced (span::BalanceOptions, whose
/// defaults stand for every key left out; the model checks the ranges).
span::BalanceOptions read_balance(const std::optional<TomlTable>& table) {
  span::BalanceOptions options;
  if (!table) return options;
  table->accept_only({"damper_model", "polish", "polish_tolerance", "max_polish_evaluations",
                            "amplitude_min_over_diameter", "amplitude_max_over_diameter", "table"});
  if (const auto model = table->optional_string("damper_model")) {
    options.damper_model = span_parsed_name(*table, "damper_model", *model, io::parse_damper_model);
  }
  options.polish = table->optional_boolean("polish").value_or(options.polish);
  options.polish_tolerance = table->optional_number("polish_tolerance").value_or(options.polish_tolerance);
  if (const auto n = table->optional_integer("max_polish_evaluations", 1, 1000)) options.max_polish_evaluations = static_cast<int>(*n);
  options.amplitude_min_over_diameter =
      table->optional_number("amplitude_min_over_diameter").value_or(options.amplitude_min_over_diameter);
  options.amplitude_max_over_diameter =
      table->optional_number("amplitude_max_over_diameter").value_or(options.amplitude_max_over_diameter);
  if (const std::optional<TomlTable> t = table->optional_table("table")) {
    t->accept_only({"velocities", "velocity_min", "velocity_max", "column_ratio"});
    span::ImpedanceTableOptions& o = options.table;
    if (const auto n = t->optional_integer("velocities", 2, 1000)) o.velocities = static_cast<int>(*n);
    o.velocity_min = t->optional_number("velocity_min").value_or(o.velocity_min);
    o.velocity_max = t->optional_number("velocity_max").value_or(o.velocity_max);
    o.column_ratio = t->optional_number("column_ratio").value_or(o.column_ratio);
  }
  return options;
}

SpanReading read_span_document(const TomlTable& top, const std::filesystem::path& base_directory, SlipPolicy policy) {
  top.accept_only({"conductor", "span", "wind", "self_damping", "damper", "mass", "fatigue", "balance", "time",
                   "wake"});
  SpanReading reading;
  reading.policy = policy;
  reading.conductor = read_conductor(top.table("conductor"), base_directory, reading);
  read_span_table(top.table("span"), reading);
  read_wind(top.table("wind"), base_directory, reading);
  reading.self_damping = read_self_damping(top.table("self_damping"));
  for (const TomlTable& table : top.table_array("damper", false)) {
    reading.dampers.push_back(read_span_damper(table, base_directory, reading));
  }
  for (const TomlTable& table : top.table_array("mass", false)) {
    reading.masses.push_back(read_span_mass(table, reading.masses.size()));
  }
  reading.fatigue = read_fatigue(top.table("fatigue"), base_directory, reading);
  reading.balance = read_balance(top.optional_table("balance"));
  if (const auto time = top.optional_table("time")) read_time_table(*time, reading.time);
  if (const auto wake = top.optional_table("wake")) read_wake_table(*wake, reading.time.wake);
  return reading;
}

/// The span file's own values outside their typical ranges (a diameter in mm, a mass
/// per length in g/m, a length in km, a tension in kN), each at its line, after the
/// dampers' warnings.
void add_span_warnings(const SpanReading& reading, const toml::table& document, const TomlSource& source,
                       std::vector<std::string>& warnings, bool with_span) {
  std::vector<UnusualValue> unusual;
  const auto check = [&unusual](std::string field, const std::optional<double>& value, const TypicalRange& range) {
    if (value) check_typical(unusual, std::move(field), *value, range);
  };
  const span::Conductor& c = reading.conductor;
  check("conductor.diameter", c.diameter, typical::conductor_diameter);
  check("conductor.mass_per_length", c.mass_per_length, typical::conductor_mass_per_length);
  check("conductor.rated_tensile_strength", c.rated_tensile_strength, typical::rated_tensile_strength);
  check("conductor.ei_min", c.ei_min, typical::conductor_ei_min);
  if (c.ei_max != 0.0) check("conductor.ei_max", c.ei_max, typical::conductor_ei_max);
  check("conductor.outer_wire_diameter", c.outer_wire_diameter, typical::outer_wire_diameter);
  check("conductor.outer_wire_modulus", c.outer_wire_modulus, typical::outer_wire_modulus);
  if (with_span) {
    check("span.length", reading.length, typical::span_length);
    check("span.tension", reading.tension, typical::span_tension);
    check("span.tension_fraction", reading.tension_fraction, typical::tension_fraction);
    check("span.catenary_parameter", reading.catenary_parameter, typical::catenary_parameter);
  }
  const span::WindModel& w = reading.wind;
  check("wind.strouhal", w.strouhal, typical::strouhal);
  check("wind.speed_min", w.speed_min, typical::wind_speed);
  check("wind.speed_max", w.speed_max, typical::wind_speed);
  check("wind.turbulence_intensity", w.turbulence_intensity, typical::turbulence_intensity);
  const span::SelfDampingModel& sd = reading.self_damping;
  check("self_damping.l", sd.l, typical::self_damping_l);
  check("self_damping.m", sd.m, typical::self_damping_m);
  check("self_damping.n", sd.n, typical::self_damping_n);
  for (std::size_t j = 0; j < reading.dampers.size(); ++j) {
    if (!reading.dampers[j].in_span()) {
      check(fmt::format("damper[{}].position", j), reading.dampers[j].position, typical::damper_position);
    }
  }
  for (std::size_t m = 0; m < reading.masses.size(); ++m) {
    check(fmt::format("mass[{}].mass", m), reading.masses[m].mass, typical::attachment_mass);
  }
  const span::FatigueSpec& f = reading.fatigue;
  check("fatigue.cycles", f.cycles, typical::fatigue_cycles);
  if (document.at_path("fatigue.endurance_limit_mpa")) {
    check("fatigue.endurance_limit_mpa", f.endurance_limit ? std::optional(*f.endurance_limit / 1e6) : std::nullopt,
          typical::endurance_limit_mpa);
  } else {
    check("fatigue.endurance_limit", f.endurance_limit, typical::endurance_limit);
  }
  check("fatigue.limit_pp_microstrain", f.limit_pp_microstrain, typical::limit_pp_microstrain);
  check("fatigue.yb_distance", f.yb_distance, typical::yb_distance);
  if (f.life) {
    check("fatigue.wind_weibull.shape", f.life->wind_weibull.shape, typical::weibull_shape);
    check("fatigue.wind_weibull.scale", f.life->wind_weibull.scale, typical::weibull_scale);
    check("fatigue.aeolian_fraction", f.life->aeolian_fraction, typical::aeolian_fraction);
  }
  for (const UnusualValue& u : unusual) {
    judge_unusual(u, field_location(document, source, u.field), reading.policy, warnings);
  }
}

void judge_span_tension(const span::Conductor& conductor, double length, double tension, const std::string& location,
                        std::string_view key, double given, SlipPolicy policy, std::vector<std::string>& warnings) {
  if (const std::optional<std::string> why = span::implausible_tension(conductor, length, tension)) {
    judge_implausible(fmt::format("{}{} = {}: {}", location, key, format_value(given), *why), policy, warnings);
  }
}

SpanFile build_span(const toml::table& document, const TomlSource& source, const std::filesystem::path& base_directory,
                    SlipPolicy policy) {
  SpanReading reading = read_span_document(TomlTable(document, source, ""), base_directory, policy);
  add_span_warnings(reading, document, source, reading.warnings);
  const auto [key, given] = reading.tension              ? std::pair{"tension", *reading.tension}
                            : reading.catenary_parameter ? std::pair{"catenary_parameter", *reading.catenary_parameter}
                                                         : std::pair{"tension_fraction", *reading.tension_fraction};
  const double tension = build_from_file(document, source, [&] {
    within_field("conductor", [&] { reading.conductor.validate(); });
    require_plausible("span.length", reading.length, "m");
    return within_field("span", [&] {
      if (reading.tension) return *reading.tension;
      if (reading.catenary_parameter) {
        return span::tension_from_catenary_parameter(reading.conductor, *reading.catenary_parameter);
      }
      return span::tension_from_fraction(reading.conductor, *reading.tension_fraction);
    });
  });
  const std::string field = fmt::format("span.{}", key);
  judge_span_tension(reading.conductor, reading.length, tension, field_location(document, source, field), field, given,
                     policy, reading.warnings);
  span::Span built = build_from_file(document, source, [&] {
    within_field("balance", [&] { reading.balance.validate(); });
    reading.wind = within_field("span", [&] {
      return span::terrain_wind(std::move(reading.wind), reading.terrain, reading.wind_law_by_terrain,
                                reading.turbulence_given);
    });
    return span::Span(std::move(reading.conductor), reading.length, tension, std::move(reading.wind),
                      std::move(reading.self_damping), std::move(reading.dampers), std::move(reading.fatigue),
                      reading.terrain, std::move(reading.masses));
  });
  return SpanFile{std::move(built), reading.balance, std::move(reading.inputs), std::move(reading.warnings), reading.time};
}

}  // namespace span_reading

using span_reading::build_span;

SpanFile load_span_file(const std::filesystem::path& path, SlipPolicy policy) {
  return build_span(parse_toml_file(path), TomlSource{path.string(), true}, path.parent_path(), policy);
}

SpanFile load_span_text(std::string_view text, std::string_view source, const std::filesystem::path& base_directory,
                        SlipPolicy policy) {
  return build_span(parse_toml_text(text, source), TomlSource{std::string(source), false}, base_directory, policy);
}

}  // namespace stockbridge::io
