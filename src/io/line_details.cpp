// The span file of a span of a line with its scheduled dampers (stockbridge line
// --details, docs/line.md): the line's shared tables, the span's own values, its
// masses, the dampers at its ends and those beside its masses, every path absolute,
// so that `stockbridge span` balances it as the schedule did.

#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "line_document.hpp"
#include "stockbridge/core/error.hpp"
#include "stockbridge/io/line_file.hpp"

namespace stockbridge::io {

namespace {

/// `node`'s path values made absolute (the span file lies elsewhere).
void absolute_path_value(toml::table& table, std::string_view key, const std::filesystem::path& base) {
  if (const auto* value = table.get_as<std::string>(key)) {
    const std::filesystem::path p(value->get());
    if (!p.is_absolute()) table.insert_or_assign(key, std::filesystem::absolute(base / p).lexically_normal().string());
  }
}

/// A [[damper]] table's source keys for a damper type: its file, or its sheet (and
/// the drawing it was fitted from), absolute.
toml::table damper_source_table(const line::DamperType& type) {
  toml::table d;
  d.insert(type.damper.measured() || type.damper.fit ? "impedance" : "file", type.file);
  if (type.damper.fit) {
    d.insert("fit_from", type.fit_from);
    toml::array free;
    for (const std::string& number : type.damper.fit->free) free.push_back(number);
    d.insert("free", std::move(free));
  }
  return d;
}

/// The span's masses as a span file's [[mass]] tables.
toml::array mass_tables(const span::Span& span) {
  toml::array out;
  for (const span::SpanMass& m : span.masses()) {
    toml::table t;
    t.insert("name", m.name);
    t.insert("mass", m.mass);
    toml::array positions;
    for (const double x : m.positions) positions.push_back(x);
    t.insert("positions", std::move(positions));
    t.insert("stress_factor", m.stress_factor);
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace

std::string span_file_text(const LineFile& file, const line::ScheduleRow& row) {
  const line::LineSpan& s = file.line.spans().at(row.index);
  toml::table doc;
  for (const char* key : {"conductor", "wind", "self_damping", "fatigue", "balance"}) {
    if (const toml::table* t = file.document->table.get_as<toml::table>(key)) doc.insert(key, *t);
  }
  const std::filesystem::path& base = file.base_directory;
  if (!s.conductor.empty()) {
    toml::table c;
    c.insert(s.conductor.ends_with(".toml") ? "file" : "type", s.conductor);
    doc.insert_or_assign("conductor", std::move(c));
  }
  absolute_path_value(*doc.get_as<toml::table>("conductor"), "file", base);  // the span's or the line's
  toml::table& wind = *doc.get_as<toml::table>("wind");
  absolute_path_value(wind, "table", base);
  wind.insert_or_assign("speed_min", s.span.wind().speed_min);  // the span's own where it has one
  wind.insert_or_assign("speed_max", s.span.wind().speed_max);
  toml::table span_table;
  span_table.insert("length", s.span.length());
  span_table.insert(s.tension_form, s.tension_given);
  if (s.span.terrain()) span_table.insert("terrain", static_cast<int64_t>(*s.span.terrain()));
  doc.insert("span", std::move(span_table));
  if (!s.span.masses().empty()) doc.insert("mass", mass_tables(s.span));
  if (!row.positions.empty()) {
    const line::DamperType* type = nullptr;
    for (const line::DamperType& t : file.line.types()) {
      if (t.name == row.damper_type) type = &t;
    }
    if (!type) throw InvalidParameter("damper_type", fmt::format(" = \"{}\": not a type of the line", printable(row.damper_type)));
    if (type->file.empty()) throw InvalidParameter("damper_type", ": a type made in code has no file to name");
    toml::array dampers;
    for (const double x : row.positions) {
      toml::table d = damper_source_table(*type);
      d.insert("position", x);
      d.insert("ends", "both");
      dampers.push_back(std::move(d));
    }
    if (row.sphere_dampers > 0) {  // after the ends' (with_arrangement's order: the same columns)
      toml::table d = damper_source_table(*type);
      toml::array along;
      for (const double x : line::sphere_damper_positions(s.span, row.sphere_distance)) along.push_back(x);
      d.insert("positions", std::move(along));
      dampers.push_back(std::move(d));
    }
    doc.insert("damper", std::move(dampers));
  }
  std::ostringstream out;
  out << "# span " << s.id << " of line " << file.name << ", as its damper schedule balanced it\n"
      << toml::toml_formatter(doc, toml::toml_formatter::default_flags & ~toml::format_flags::allow_literal_strings)
      << "\n";
  return out.str();
}

}  // namespace stockbridge::io
