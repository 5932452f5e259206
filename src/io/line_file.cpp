#include "stockbridge/io/line_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <functional>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/io/conductor_file.hpp"
#include "stockbridge/io/csv_reader.hpp"
#include "stockbridge/io/span_names.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "stockbridge/io/input_file.hpp"
#include "stockbridge/span/tension_figures.hpp"
#include "line_document.hpp"
#include "span_reading.hpp"
#include "toml_reader.hpp"

namespace stockbridge::io {


namespace line_reading {

using span_reading::SpanReading;

/// One span as given (a [[span]] table or a CSV row), before the model validates it.
struct GivenSpan {
  std::string id;
  std::optional<double> length;
  std::string tension_form;
  double tension_value = 0.0;
  std::optional<int> terrain;
  std::string conductor;  ///< a catalogue type or a conductor file; empty: the line's
  std::optional<double> speed_min, speed_max;
  /// Masses along the span ([[span.mass]] tables, or the CSV's masses column grouped
  /// by their mass), and the CSV's cell as written (for messages).
  std::vector<span::SpanMass> masses;
  std::string masses_cell;
  std::string where;      ///< "file:line: " for messages
  /// The location of one of its keys or columns ("file:line: ").
  std::function<std::string(std::string_view key)> located;
  bool from_csv = false;  ///< a spans CSV's row (its keys named as columns) or a [[span]] table

  /// A key as the span was given it: the [[span]] table's key, or the CSV's column
  /// ("tension" -> "tension_n").
  std::string named(std::string_view key) const;
};

std::string GivenSpan::named(std::string_view key) const {
  if (!from_csv) return std::string(key);
  if (key == "length") return "length_m";
  if (key == "tension") return "tension_n";
  if (key == "catenary_parameter") return "catenary_parameter_m";
  if (key.starts_with("mass[")) return "masses";
  return std::string(key);
}

constexpr std::array<std::string_view, 3> kTensionForms{"tension", "tension_fraction", "catenary_parameter"};

/// The span's conductor: the line's, or its own (a catalogue type, or a conductor
/// file relative to the line file's folder).
span::Conductor span_conductor(const GivenSpan& given, const span::Conductor& line_conductor,
                               const std::filesystem::path& base, std::vector<std::filesystem::path>& inputs) {
  if (given.conductor.empty()) return line_conductor;
  const std::string& c = given.conductor;
  if (c.size() > 5 && c.ends_with(".toml")) {
    const std::filesystem::path path = existing_input_file(
        given.located("conductor") + "conductor = ",
        {c, std::filesystem::path(c).is_absolute() ? std::filesystem::path(c) : base / c, "conductor file",
         "the line file's folder", "a catalogue type"});
    inputs.push_back(path);
    span::Conductor read = span::conductor_of(read_conductor_file(path));
    read.source = fmt::format("the conductor file {}", c);
    return read;
  }
  try {
    span::Conductor read = span::conductor_of(catalogue_conductor(c));
    read.source = fmt::format("the catalogue's {}", c);
    return read;
  } catch (const InvalidParameter& e) {
    throw InputError(fmt::format("{}conductor{}, or a conductor file (*.toml)", given.located("conductor"), e.detail()));
  }
}

/// The span built from what was given and the line's shared tables; the model's
/// InvalidParameter at the key (or column) it names, or at the shared table's line.
line::LineSpan build_given(const GivenSpan& given, const SpanReading& shared, const toml::table& document,
                           const TomlSource& source, const std::filesystem::path& base,
                           std::vector<std::filesystem::path>& inputs, std::vector<std::string>& warnings) {
  span::Conductor conductor = span_conductor(given, shared.conductor, base, inputs);
  span::WindModel wind = shared.wind;
  if (given.speed_min) wind.speed_min = *given.speed_min;
  if (given.speed_max) wind.speed_max = *given.speed_max;
  try {
    wind = within_field("span", [&] {
      return span::terrain_wind(std::move(wind), given.terrain, shared.wind_law_by_terrain, shared.turbulence_given);
    });
    double tension = given.tension_value;
    if (given.tension_form == "tension_fraction") tension = span::tension_from_fraction(conductor, tension, "span.tension_fraction");
    if (given.tension_form == "catenary_parameter") {
      tension = span::tension_from_catenary_parameter(conductor, tension, "span.catenary_parameter");
    }
    if (given.tension_form == "tension") span::check_tension(conductor, tension, "span.tension");
    require_plausible("span.length", *given.length, "m");
    span_reading::judge_span_tension(
        conductor, *given.length, tension,
        fmt::format("{}span \"{}\": ", given.located(given.tension_form), printable(given.id)),
        given.named(given.tension_form), given.tension_value, shared.policy, warnings);
    span::Span s(std::move(conductor), *given.length, tension, std::move(wind), shared.self_damping, {}, shared.fatigue,
                 given.terrain, given.masses);
    return line::LineSpan{given.id, std::move(s), shared.balance, given.tension_form, given.tension_value,
                          given.conductor, given.where};
  } catch (const InvalidParameter& e) {
    const std::string& field = e.field();
    if (field.starts_with("mass[") && given.from_csv) {
      throw InputError(fmt::format("{}span \"{}\": column 'masses' = '{}': {}{}", given.where, printable(given.id),
                                   printable(given.masses_cell), field.ends_with(".mass") ? "a mass" : "a position",
                                   e.detail()));
    }
    if (field.starts_with("mass[")) {
      throw InputError(fmt::format("{}span \"{}\": {}{}", given.located(field), printable(given.id), field, e.detail()));
    }
    if (field.starts_with("span.")) {
      throw InputError(fmt::format("{}span \"{}\": {}{}", given.located(field.substr(5)), printable(given.id),
                                   given.named(field.substr(5)), e.detail()));
    }
    if (field.starts_with("wind.speed_m") && (given.speed_min || given.speed_max)) {
      throw InputError(fmt::format("{}span \"{}\": {}", given.where, printable(given.id), e.what()));
    }
    if (field.starts_with("conductor.") && !given.conductor.empty()) {
      throw InputError(fmt::format("{}span \"{}\": {}", given.located("conductor"), printable(given.id), e.what()));
    }
    throw InputError(field_location(document, source, field) + e.what());
  }
}

/// The span's values outside their typical ranges, at its table or row: one a unit
/// slip explains refused under `policy` (typical_ranges.hpp).
void check_given(const GivenSpan& given, SlipPolicy policy, std::vector<std::string>& warnings) {
  std::vector<UnusualValue> unusual;
  check_typical(unusual, "length", *given.length, typical::span_length);
  const TypicalRange& range = given.tension_form == "tension"            ? typical::span_tension
                              : given.tension_form == "tension_fraction" ? typical::tension_fraction
                                                                         : typical::catenary_parameter;
  check_typical(unusual, given.tension_form, given.tension_value, range);
  for (std::size_t m = 0; m < given.masses.size(); ++m) {
    check_typical(unusual, fmt::format("mass[{}].mass", m), given.masses[m].mass, typical::attachment_mass);
  }
  for (UnusualValue& u : unusual) {
    const std::string location = fmt::format("{}span \"{}\": ", given.located(u.field), printable(given.id));
    u.field = given.named(u.field);
    judge_unusual(u, location, policy, warnings);
  }
}

/// The location of a [[span.mass]] table's key that a model's field names
/// ("mass[1].positions[0]": the second table's positions), or of the span's table.
std::string mass_location(const TomlTable& span_table, const std::vector<TomlTable>& masses, std::string_view field) {
  const std::size_t open = field.find('['), close = field.find(']');
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(field.data() + open + 1, field.data() + close, index);
  if (error != std::errc() || index >= masses.size() || close + 1 >= field.size()) return span_table.location("mass");
  std::string_view key = field.substr(close + 2);
  key = key.substr(0, key.find('['));
  return masses[index].location(key);
}

/// A [[span]] table.
GivenSpan given_from_table(const TomlTable& t) {
  t.accept_only({"id", "length", "tension", "tension_fraction", "catenary_parameter", "terrain", "conductor", "wind",
                 "mass"});
  GivenSpan g;
  g.id = t.required_string("id", "a string naming the span (e.g. \"T12-T13\")");
  g.length = t.number("length");
  std::vector<std::string_view> forms;
  for (const std::string_view form : kTensionForms) {
    if (const auto v = t.optional_number(form)) {
      if (forms.empty()) g.tension_form = std::string(form), g.tension_value = *v;
      forms.push_back(form);
    }
  }
  if (forms.empty()) {
    throw InputError(fmt::format("{}missing key 'tension' in [{}]: expected one of tension (N), tension_fraction (of "
                                 "the rated tensile strength) and catenary_parameter (H/w, m)",
                                 t.location("tension"), t.key_path()));
  }
  if (forms.size() > 1) t.fail(forms[1], fmt::format("given beside {}: expected one form of the tension", forms[0]));
  if (const auto n = t.optional_integer("terrain", 1, 4)) g.terrain = static_cast<int>(*n);
  g.conductor = t.optional_string("conductor").value_or("");
  if (const std::optional<TomlTable> w = t.optional_table("wind")) {
    w->accept_only({"speed_min", "speed_max"});
    g.speed_min = w->optional_number("speed_min");
    g.speed_max = w->optional_number("speed_max");
  }
  const std::vector<TomlTable> masses = t.table_array("mass", false);
  for (const TomlTable& m : masses) g.masses.push_back(span_reading::read_span_mass(m, g.masses.size()));
  g.where = t.location("id");
  g.located = [t, masses](std::string_view key) {
    if (key.starts_with("mass[")) return mass_location(t, masses, key);
    return key == "speed_min" || key == "speed_max" ? t.location("wind") : t.location(key);
  };
  return g;
}

std::optional<double> csv_number(const std::string& cell, const std::string& where, std::string_view column) {
  if (cell.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value)) {
    throw InputError(fmt::format("{}column '{}' = '{}': expected a number ('.' as decimal separator)", where, column,
                                 printable(cell)));
  }
  return value;
}

constexpr std::array<std::string_view, 10> kCsvColumns{"id", "length_m", "tension_n", "tension_fraction",
                                                       "catenary_parameter_m", "terrain", "conductor",
                                                       "wind_speed_min_m_s", "wind_speed_max_m_s", "masses"};

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// A number of a masses cell's entry, or none where the text is not one.
std::optional<double> mass_entry_number(std::string_view text) {
  text = trimmed(text);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// A spans CSV's masses cell: "12.5@30;12.5@90" (kg @ m from end 1, ';'-separated;
/// empty: none). Masses of one value are one SpanMass at all their positions, named
/// "mass 1", "mass 2", ... in the order first given (a span file's [[mass]] names);
/// the model checks the values.
std::vector<span::SpanMass> csv_masses(const std::string& cell, const std::string& where) {
  std::vector<span::SpanMass> masses;
  if (trimmed(cell).empty()) return masses;
  std::string_view rest(cell);
  while (true) {
    const std::size_t split = rest.find(';');
    const std::string_view entry = rest.substr(0, split);
    const std::size_t at = entry.find('@');
    const std::optional<double> mass = at == std::string_view::npos ? std::nullopt : mass_entry_number(entry.substr(0, at));
    const std::optional<double> position =
        at == std::string_view::npos ? std::nullopt : mass_entry_number(entry.substr(at + 1));
    if (!mass || !position) {
      throw InputError(fmt::format("{}column 'masses' = '{}': '{}' is not a mass at a position: expected "
                                   "<kg>@<m from end 1> entries, ';'-separated (e.g. 12.5@30;12.5@90), or an empty "
                                   "cell for none",
                                   where, printable(cell), printable(trimmed(entry))));
    }
    auto same = std::find_if(masses.begin(), masses.end(), [&](const span::SpanMass& m) { return m.mass == *mass; });
    if (same == masses.end()) {
      masses.push_back(span::SpanMass{fmt::format("mass {}", masses.size() + 1), *mass, {}, 1.0});
      same = masses.end() - 1;
    }
    same->positions.push_back(*position);
    if (split == std::string_view::npos) break;
    rest.remove_prefix(split + 1);
  }
  return masses;
}

/// The spans of a spans CSV.
std::vector<GivenSpan> given_from_csv(const std::filesystem::path& path) {
  const CsvCells csv = read_csv_cells(path);
  const std::string file = path.string();
  std::vector<std::ptrdiff_t> column(kCsvColumns.size(), -1);
  for (std::size_t c = 0; c < csv.header.size(); ++c) {
    const auto known = std::find(kCsvColumns.begin(), kCsvColumns.end(), csv.header[c]);
    if (known == kCsvColumns.end()) {
      throw InputError(fmt::format("{}: column '{}' is not a spans column: expected {}", file, printable(csv.header[c]),
                                   fmt::join(kCsvColumns, ", ")));
    }
    auto& slot = column[static_cast<std::size_t>(known - kCsvColumns.begin())];
    if (slot >= 0) throw InputError(fmt::format("{}: column '{}' appears twice", file, csv.header[c]));
    slot = static_cast<std::ptrdiff_t>(c);
  }
  for (const std::size_t required : {std::size_t{0}, std::size_t{1}}) {
    if (column[required] < 0) {
      throw InputError(fmt::format("{}: missing column '{}': expected id, length_m and one of tension_n, "
                                   "tension_fraction and catenary_parameter_m",
                                   file, kCsvColumns[required]));
    }
  }
  if (csv.rows.empty()) throw InputError(fmt::format("{}: no spans: expected a row per span below the header", file));
  std::vector<GivenSpan> spans;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const std::vector<std::string>& row = csv.rows[r];
    const std::string where = fmt::format("{}:{}: ", file, csv.lines[r]);
    const auto cell = [&](std::size_t k) -> std::string { return column[k] < 0 ? "" : row[static_cast<std::size_t>(column[k])]; };
    GivenSpan g;
    g.where = where;
    g.located = [where](std::string_view) { return where; };
    g.from_csv = true;
    g.id = cell(0);
    if (g.id.empty()) throw InputError(where + "column 'id' is empty: expected the span's name (e.g. T12-T13)");
    g.length = csv_number(cell(1), where, "length_m");
    if (!g.length) throw InputError(where + "column 'length_m' is empty: expected the span's length (m)");
    const std::array<std::pair<std::size_t, std::string_view>, 3> forms{
        {{2, "tension"}, {3, "tension_fraction"}, {4, "catenary_parameter"}}};
    int given = 0;
    for (const auto& [k, form] : forms) {
      if (const auto v = csv_number(cell(k), where, kCsvColumns[k])) {
        if (++given > 1) {
          throw InputError(fmt::format("{}span \"{}\": {} given beside {}: expected one form of the tension in a row",
                                       where, printable(g.id), kCsvColumns[k], g.tension_form));
        }
        g.tension_form = std::string(form);
        g.tension_value = *v;
      }
    }
    if (given == 0) {
      throw InputError(fmt::format("{}span \"{}\": no tension: expected a value in one of tension_n, tension_fraction "
                                   "and catenary_parameter_m",
                                   where, printable(g.id)));
    }
    if (const auto t = csv_number(cell(5), where, "terrain")) {
      if (*t != std::floor(*t) || *t < 1 || *t > 4) {
        throw InputError(fmt::format("{}column 'terrain' = {}: expected a TB 273 terrain category, 1 to 4", where, cell(5)));
      }
      g.terrain = static_cast<int>(*t);
    }
    g.conductor = cell(6);
    g.speed_min = csv_number(cell(7), where, "wind_speed_min_m_s");
    g.speed_max = csv_number(cell(8), where, "wind_speed_max_m_s");
    g.masses_cell = cell(9);
    g.masses = csv_masses(g.masses_cell, where);
    spans.push_back(std::move(g));
  }
  return spans;
}

/// A damper type of [dampers] types: a damper file or a measured sheet, its mass.
line::DamperType read_damper_type(const TomlTable& t, const std::filesystem::path& base, SpanReading& reading) {
  t.accept_only({"name", "file", "impedance", "fit_from", "free", "mass", "price"});
  span_reading::DamperSource source = span_reading::read_damper_source(
      t, base, reading,
      fmt::format("missing key 'file' in {}: expected a damper file, or impedance = a measured impedance CSV file "
                  "(relative to the line file)",
                  t.key_path()));
  line::DamperType type;
  type.mass = t.optional_number("mass");
  type.price = t.optional_number("price");
  if (source.damper && !type.mass) type.mass = source.damper->total_mass();
  type.file = std::filesystem::absolute(source.path).lexically_normal().string();
  type.name = t.optional_string("name").value_or(source.name);
  type.damper.damper = std::move(source.damper);
  type.damper.sheet = std::move(source.sheet);
  type.damper.fit = std::move(source.fit);
  if (type.damper.fit) type.fit_from = std::filesystem::absolute(source.fit_from).lexically_normal().string();
  type.damper.name = type.name;
  return type;
}

line::ScheduleRules read_rules(const TomlTable& d, const std::optional<TomlTable>& l) {
  line::ScheduleRules r;
  if (const auto n = d.optional_integer("min_per_end", 0, 10)) r.min_per_end = static_cast<int>(*n);
  if (const auto n = d.optional_integer("max_per_end", 1, 10)) r.max_per_end = static_cast<int>(*n);
  r.positions.position_min = d.optional_number("position_min").value_or(r.positions.position_min);
  r.positions.position_max = d.optional_number("position_max").value_or(r.positions.position_max);
  r.positions.spacing_min = d.optional_number("spacing_min").value_or(r.positions.spacing_min);
  if (const auto objective = d.optional_string("objective")) {
    try {
      r.positions.objective = io::parse_position_objective(*objective);
    } catch (const InvalidParameter& e) {
      throw InputError(d.location("objective") + e.within("dampers").what());
    }
  }
  r.life_target = d.optional_number("life_target");
  const auto parsed = [&d](std::string_view key, auto parse) {
    try {
      return parse(*d.optional_string(key));
    } catch (const InvalidParameter& e) {
      throw InputError(d.location(key) + e.within("dampers").what());
    }
  };
  if (d.contains("choose")) r.choose = parsed("choose", line::parse_type_choice);
  if (d.contains("undamped_rule")) r.undamped_rule = parsed("undamped_rule", line::parse_undamped_rule);
  r.accept_uncertain = d.optional_boolean("accept_uncertain").value_or(false);
  r.position_step = d.optional_number("position_step").value_or(r.position_step);
  if (d.contains("sphere_dampers")) r.sphere_dampers = parsed("sphere_dampers", line::parse_sphere_dampers);
  r.sphere_distance_min = d.optional_number("sphere_distance_min").value_or(r.sphere_distance_min);
  r.sphere_distance_max = d.optional_number("sphere_distance_max").value_or(r.sphere_distance_max);
  if (l) {
    if (const auto n = l->optional_integer("points", 2, 100000)) r.points = static_cast<int>(*n);
    if (const auto n = l->optional_integer("search_points", 2, 100000)) r.search_points = static_cast<int>(*n);
  }
  return r;
}

LineFile build_line(toml::table document, const TomlSource& source, const std::filesystem::path& base,
                    SlipPolicy policy) {
  const TomlTable top(document, source, "");
  top.accept_only({"conductor", "wind", "self_damping", "fatigue", "balance", "line", "dampers", "span", "spans"});
  SpanReading shared;
  shared.policy = policy;
  shared.conductor = span_reading::read_conductor(top.table("conductor"), base, shared);
  span_reading::read_wind(top.table("wind"), base, shared);
  shared.self_damping = span_reading::read_self_damping(top.table("self_damping"));
  shared.fatigue = span_reading::read_fatigue(top.table("fatigue"), base, shared);
  shared.balance = span_reading::read_balance(top.optional_table("balance"));
  build_from_file(document, source, [&] {
    within_field("balance", [&] { shared.balance.validate(); });
    within_field("conductor", [&] { shared.conductor.validate(); });
  });
  const std::optional<TomlTable> line_table = top.optional_table("line");
  std::string name = source.lines ? std::filesystem::path(source.name).stem().string() : std::string("line");
  if (line_table) {
    line_table->accept_only({"name", "points", "search_points", "wind_law_by_terrain"});
    shared.wind_law_by_terrain = line_table->optional_boolean("wind_law_by_terrain").value_or(false);
    name = line_table->optional_string("name").value_or(name);
  }
  const TomlTable dampers = top.table("dampers");
  dampers.accept_only({"types", "min_per_end", "max_per_end", "position_min", "position_max", "spacing_min",
                       "objective", "life_target", "position_step", "choose", "accept_uncertain", "undamped_rule",
                       "sphere_dampers", "sphere_distance_min", "sphere_distance_max"});
  std::vector<line::DamperType> types;
  for (const TomlTable& t : dampers.table_array("types", true)) types.push_back(read_damper_type(t, base, shared));
  const line::ScheduleRules rules = read_rules(dampers, line_table);

  std::vector<GivenSpan> given;
  if (const toml::node* node = top.node("spans"); node && !node->is_string()) {
    top.fail("spans", fmt::format("{}: expected the path of a spans CSV file (a string); spans written in the line "
                                  "file are [[span]] tables",
                                  describe_type(*node)));
  }
  const std::optional<std::string> spans_csv = top.optional_string("spans");
  const std::vector<TomlTable> span_tables = top.table_array("span", false);
  if (spans_csv && !span_tables.empty()) {
    top.fail("spans", "given beside [[span]] tables: expected the spans as [[span]] tables or in a CSV file, one of the two");
  }
  if (spans_csv) {
    const std::filesystem::path path = span_reading::span_input_file(top, "spans", *spans_csv, base, "spans CSV file");
    shared.inputs.push_back(path);
    given = given_from_csv(path);
  } else {
    for (const TomlTable& t : span_tables) given.push_back(given_from_table(t));
  }
  std::vector<std::string> warnings;
  span_reading::add_span_warnings(shared, document, source, warnings, false);
  for (const auto& [key, value] : {std::pair{"position_min", rules.positions.position_min},
                                   std::pair{"position_max", rules.positions.position_max},
                                   std::pair{"sphere_distance_min", rules.sphere_distance_min},
                                   std::pair{"sphere_distance_max", rules.sphere_distance_max}}) {
    if (const auto u = unusual(fmt::format("dampers.{}", key), value, typical::damper_position)) {
      judge_unusual(*u, dampers.location(key), policy, warnings);
    }
  }
  std::vector<line::LineSpan> spans;
  spans.reserve(given.size());
  for (const GivenSpan& g : given) {
    check_given(g, policy, warnings);
    spans.push_back(build_given(g, shared, document, source, base, shared.inputs, warnings));
  }
  std::optional<line::Line> built;
  try {
    built.emplace(std::move(spans), std::move(types), rules);
  } catch (const InvalidParameter& e) {
    const std::string& field = e.field();
    if (field.starts_with("span[")) {  // an id: at the span's line (its table's, or its CSV row's)
      const std::size_t i = std::stoul(field.substr(5));
      throw InputError(fmt::format("{}{}", given.at(i).where, e.what()));
    }
    throw InputError(field_location(document, source, field) + e.what());
  }
  warnings.insert(warnings.begin(), shared.warnings.begin(), shared.warnings.end());
  std::sort(shared.inputs.begin(), shared.inputs.end());
  shared.inputs.erase(std::unique(shared.inputs.begin(), shared.inputs.end()), shared.inputs.end());
  return LineFile{std::move(*built), std::move(name), std::move(shared.inputs), std::move(warnings),
                  std::make_shared<const LineDocument>(LineDocument{std::move(document)}), base};
}

}  // namespace line_reading

LineFile load_line_file(const std::filesystem::path& path, SlipPolicy policy) {
  return line_reading::build_line(parse_toml_file(path), TomlSource{path.string(), true}, path.parent_path(), policy);
}

LineFile load_line_text(std::string_view text, std::string_view source, const std::filesystem::path& base_directory,
                        SlipPolicy policy) {
  return line_reading::build_line(parse_toml_text(text, source), TomlSource{std::string(source), false}, base_directory,
                                  policy);
}

}  // namespace stockbridge::io
