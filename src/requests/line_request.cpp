#include "stockbridge/requests/line_request.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "record_text.hpp"

namespace stockbridge::requests {

namespace {

using Row = line::ScheduleRow;

/// A stress or life of a balance that converged throughout, NaN otherwise.
double trusted(const Row& r, double value, bool undamped) {
  if (undamped) return value;  // the undamped balance has no iteration that can fail
  return r.converged == r.points ? value : kNoValue;
}

std::string positions_text(const std::vector<double>& positions) {
  std::string out;
  for (const double x : positions) out += fmt::format("{}{}", out.empty() ? "" : ";", x);
  return out;
}

std::string joined_warnings(const std::vector<std::string>& warnings) {
  std::string out;
  for (const std::string& w : warnings) out += fmt::format("{}{}", out.empty() ? "" : " | ", w);
  return out;
}

}  // namespace

Table<line::ScheduleRow> schedule_table() {
  using K = ColumnKind;
  const auto number = [](double (*f)(const Row&)) { return [f](const Row& r, std::size_t) { return f(r); }; };
  return Table<Row>({
      {"id", "", "the span's name", K::label, {}, [](const Row& r, std::size_t) { return r.id; }},
      {"conductor", "", "the conductor's name", K::label, {}, [](const Row& r, std::size_t) { return r.conductor; }},
      {"undamped_verdict", "", "safe, unsafe or unknown without dampers, by the span's energy balance", K::label, {},
       [](const Row& r, std::size_t) { return std::string(span::verdict_name(r.undamped_verdict)); }},
      {"damper_type", "", "the recommended damper type (empty: none needed)", K::label, {},
       [](const Row& r, std::size_t) { return r.damper_type; }},
      {"positions_m", "m", "each damper's distance from the clamp at one end, ';'-separated, increasing (both ends alike)",
       K::label, {}, [](const Row& r, std::size_t) { return positions_text(r.positions); }},
      {"verdict", "", "safe, unsafe, unknown or uncertain (a measured sheet's band reaches above the limit) with the "
                      "recommended dampers",
       K::label, {}, [](const Row& r, std::size_t) { return std::string(span::verdict_name(r.verdict)); }},
      {"no_damper_basis", "", "where the span gets no damper, what judged it safe: balance (its own) or tb273 (its H/w "
                              "within its terrain's limit, dampers.undamped_rule)",
       K::label, {}, [](const Row& r, std::size_t) { return r.no_damper_basis; }},
      {"warnings", "", "what the engineer should know, ' | '-separated", K::label, {},
       [](const Row& r, std::size_t) { return joined_warnings(r.warnings); }},
      {"governing_place", "",
       "where the largest stress with the recommended dampers lies: span clamp 1, span clamp 2 or a mass's clamp (sphere "
       "at 120 m)",
       K::label, {}, [](const Row& r, std::size_t) { return r.converged == r.points ? r.governing_place : std::string(); }},
      {"length_m", "m", "the span's length", K::number, number([](const Row& r) { return r.length; }), {}},
      {"tension_n", "N", "the tension T", K::number, number([](const Row& r) { return r.tension; }), {}},
      {"tension_percent_rts", "%", "T over the rated tensile strength", K::number,
       number([](const Row& r) { return 100.0 * r.tension_fraction; }), {}},
      {"catenary_parameter_m", "m", "H/w = T / (m g)", K::number,
       number([](const Row& r) { return r.catenary_parameter; }), {}},
      {"span_parameter_m3_kg", "m^3/kg", "L D / m", K::number, number([](const Row& r) { return r.span_parameter; }), {}},
      {"terrain", "", "CIGRE TB 273's terrain category (empty: not given)", K::number,
       number([](const Row& r) { return r.terrain > 0 ? static_cast<double>(r.terrain) : kNoValue; }), {}},
      {"terrain_hw_within", "", "1 if H/w is within the terrain's limit for an undamped span, 0 if above", K::flag,
       number([](const Row& r) { return r.terrain_within < 0 ? kNoValue : static_cast<double>(r.terrain_within); }), {}},
      {"endurance_limit_mpa", "MPa", "the stress the verdict allows (the criterion's limit as a zero-to-peak stress)",
       K::number,
       number([](const Row& r) { return megapascal_of(r.endurance_limit); }), {}},
      {"undamped_max_stress_mpa", "MPa",
       "the largest stress the criterion judges without dampers, at the span clamps and the masses' clamps (fymax; "
       "Poffenberger-Swart under the microstrain criterion)",
       K::number,
       number([](const Row& r) { return megapascal_of(r.undamped_max_stress); }), {}},
      {"undamped_life_years", "years", "Miner's life without dampers (with the line's climate; inf: no damage)",
       K::number, number([](const Row& r) { return r.undamped_life_years; }), {}},
      {"dampers_per_end", "", "the recommended number of dampers at each end", K::count,
       number([](const Row& r) { return static_cast<double>(r.per_end); }), {}},
      {"sphere_dampers", "", "dampers of the type beside the span's masses, one on either side of each (dampers.sphere_dampers)",
       K::count, number([](const Row& r) { return static_cast<double>(r.sphere_dampers); }), {}},
      {"sphere_damper_distance_m", "m", "their distance from each mass's clamp (empty: none)", K::number,
       number([](const Row& r) { return r.sphere_dampers > 0 ? r.sphere_distance : kNoValue; }), {}},
      {"max_stress_mpa", "MPa",
       "the largest stress the criterion judges with those dampers, at the span clamps and the masses' clamps", K::number,
       number([](const Row& r) { return trusted(r, megapascal_of(r.max_stress), false); }), {}},
      {"max_stress_high_mpa", "MPa",
       "the top of its measured sheets' band (empty without a measured damper): the verdict is uncertain where it "
       "exceeds the limit and max_stress_mpa does not",
       K::number, number([](const Row& r) { return trusted(r, megapascal_of(r.max_stress_high), false); }), {}},
      {"max_stress_frequency_hz", "Hz", "where it occurs", K::number,
       number([](const Row& r) { return trusted(r, r.max_stress_frequency, false); }), {}},
      {"life_years", "years", "Miner's life with those dampers", K::number,
       number([](const Row& r) { return trusted(r, r.life_years, false); }), {}},
      {"stress_ratio", "", "max_stress_mpa over endurance_limit_mpa", K::number,
       number([](const Row& r) { return trusted(r, r.stress_ratio(), false); }), {}},
      {"margin_percent", "%", "100 (1 - stress_ratio): the share of the endurance limit left", K::number,
       number([](const Row& r) { return trusted(r, 100.0 * (1.0 - r.stress_ratio()), false); }), {}},
      {"converged", "", "1 if every frequency of the recommended arrangement's balance converged", K::flag,
       number([](const Row& r) { return r.converged == r.points ? 1.0 : 0.0; }), {}},
      {"converged_points", "", "its frequencies that converged", K::count,
       number([](const Row& r) { return static_cast<double>(r.converged); }), {}},
      {"points", "", "its frequencies", K::count, number([](const Row& r) { return static_cast<double>(r.points); }), {}},
      {"search_balances", "", "balances the position search made (its cost)", K::count,
       number([](const Row& r) { return static_cast<double>(r.balances); }), {}},
  });
}

Table<line::BillLine> bill_table() {
  using B = line::BillLine;
  using K = ColumnKind;
  return Table<B>({
      {"damper_type", "", "the damper type", K::label, {}, [](const B& b, std::size_t) { return b.damper_type; }},
      {"dampers", "", "dampers of the type over the line (both ends of every span, and beside its masses)", K::count,
       [](const B& b, std::size_t) { return static_cast<double>(b.dampers); }, {}},
      {"spans", "", "spans that get the type", K::count, [](const B& b, std::size_t) { return static_cast<double>(b.spans); }, {}},
      {"mass_kg", "kg", "their mass (empty where the type's mass is not known)", K::number,
       [](const B& b, std::size_t) { return b.mass.value_or(kNoValue); }, {}},
      {"price", "", "their price, in the line file's currency (empty where the type's price is not given)", K::number,
       [](const B& b, std::size_t) { return b.price.value_or(kNoValue); }, {}},
  });
}

LineSchedule line_schedule(const io::LineFile& file, std::map<std::size_t, line::ScheduleRow> rows) {
  LineSchedule s;
  const std::size_t spans = file.line.spans().size();
  s.rows.reserve(spans);
  for (std::size_t i = 0; i < spans; ++i) {
    const auto found = rows.find(i);
    if (found == rows.end()) {
      throw InvalidParameter("rows", fmt::format(": span {} ({}) has no row", i, file.line.spans()[i].id));
    }
    s.rows.push_back(std::move(found->second));
  }
  s.bill = line::bill_of_materials(file.line, s.rows);
  return s;
}

io::JsonObject line_summary(const io::LineFile& file, const LineSchedule& schedule) {
  const std::vector<line::ScheduleRow>& rows = schedule.rows;
  const line::ScheduleCounts c = line::schedule_counts(rows);
  const Row* governing = c.governing;
  std::vector<io::JsonObject> counts;
  for (const auto& [n, spans] : c.per_end) counts.push_back(io::JsonObject().add("dampers_per_end", n).add("spans", spans));
  std::vector<io::JsonObject> bill;
  const TableValues values = bill_table().values(schedule.bill);
  for (std::size_t r = 0; r < values.rows; ++r) bill.push_back(values.json_row(r));
  io::JsonObject json;
  json.add("line", file.name)
      .add("spans", static_cast<int>(rows.size()))
      .add("spans_safe", c.safe)
      .add("spans_unsafe", c.unsafe)
      .add("spans_unknown", c.unknown)
      .add("spans_uncertain", c.uncertain)
      .add("criterion", file.line.spans().empty()
                            ? std::string("safe-border-line")
                            : std::string(span::fatigue_criterion_name(file.line.spans().front().span.fatigue().criterion)))
      .add("choose", std::string(line::type_choice_name(file.line.rules().choose)))
      .add("undamped_rule", std::string(line::undamped_rule_name(file.line.rules().undamped_rule)))
      .add("accept_uncertain", file.line.rules().accept_uncertain)
      .add("sphere_dampers", std::string(line::sphere_dampers_name(file.line.rules().sphere_dampers)))
      .add("spans_not_converged", c.not_converged)
      .add("spans_worse_than_undamped", c.worse_than_undamped)
      .add("dampers_per_end", counts)
      .add("bill", bill);
  if (governing) {
    json.add("governing_span", governing->id)
        .add("governing_stress_ratio", governing->stress_ratio())
        .add("governing_place", governing->governing_place);
  } else {
    json.add_null("governing_span").add_null("governing_stress_ratio").add_null("governing_place");
  }
  return json;
}

namespace {

using record_text::bad_record;
using record_text::escaped;
using record_text::RecordFields;

/// span-v3: the dampers beside the masses and the governing place added. A record of
/// an earlier tag is not a schedule record (its span is computed again).
constexpr std::string_view kRecordTag = "span-v3";

span::Verdict verdict_from(long long v) {
  if (v < 0 || v > 3) bad_record("a verdict out of range");
  return static_cast<span::Verdict>(v);
}

}  // namespace

std::string schedule_record(const line::ScheduleRow& r) {
  std::string out = fmt::format("{}\t{}\t{}\t{}", kRecordTag, r.index, escaped(r.id), escaped(r.conductor));
  for (const double v : {r.length, r.tension, r.tension_fraction, r.catenary_parameter, r.span_parameter,
                         r.endurance_limit, r.undamped_max_stress, r.undamped_life_years, r.max_stress,
                         r.max_stress_high, r.max_stress_frequency, r.life_years}) {
    out += fmt::format("\t{}", v);
  }
  out += '\t';
  out += escaped(r.no_damper_basis);
  out += fmt::format("\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}", r.terrain, r.terrain_within,
                     static_cast<int>(r.undamped_verdict), static_cast<int>(r.verdict), r.per_end, r.converged,
                     r.points, r.balances, escaped(r.damper_type), r.positions.size());
  for (const double x : r.positions) out += fmt::format("\t{}", x);
  out += fmt::format("\t{}\t{}\t", r.sphere_dampers, r.sphere_distance);
  out += escaped(r.governing_place);
  out += fmt::format("\t{}", r.warnings.size());
  for (const std::string& w : r.warnings) {
    out += '\t';
    out += escaped(w);
  }
  out += "\tend";
  return out;
}

line::ScheduleRow parse_schedule_record(std::string_view record) {
  RecordFields f(record);
  if (f.text() != kRecordTag) bad_record("not a schedule record");
  Row r;
  r.index = static_cast<std::size_t>(f.integer());
  r.id = f.text();
  r.conductor = f.text();
  for (double* v : {&r.length, &r.tension, &r.tension_fraction, &r.catenary_parameter, &r.span_parameter,
                    &r.endurance_limit, &r.undamped_max_stress, &r.undamped_life_years, &r.max_stress,
                    &r.max_stress_high, &r.max_stress_frequency, &r.life_years}) {
    *v = f.number();
  }
  r.no_damper_basis = f.text();
  r.terrain = static_cast<int>(f.integer());
  r.terrain_within = static_cast<int>(f.integer());
  r.undamped_verdict = verdict_from(f.integer());
  r.verdict = verdict_from(f.integer());
  r.per_end = static_cast<int>(f.integer());
  r.converged = static_cast<int>(f.integer());
  r.points = static_cast<int>(f.integer());
  r.balances = static_cast<int>(f.integer());
  r.damper_type = f.text();
  const long long positions = f.integer();
  if (positions < 0 || positions > 100) bad_record("a count of positions out of range");
  for (long long k = 0; k < positions; ++k) r.positions.push_back(f.number());
  const long long sphere_dampers = f.integer();
  if (sphere_dampers < 0 || sphere_dampers > 100000) bad_record("a count of dampers beside the masses out of range");
  r.sphere_dampers = static_cast<int>(sphere_dampers);
  r.sphere_distance = f.number();
  r.governing_place = f.text();
  const long long warnings = f.integer();
  if (warnings < 0 || warnings > 1000) bad_record("a count of warnings out of range");
  for (long long k = 0; k < warnings; ++k) r.warnings.push_back(f.text());
  if (f.text() != "end" || !f.done()) bad_record("no end mark");
  return r;
}

std::string line_fingerprint(const io::LineFile& file, std::string_view line_text) {
  return record_text::input_fingerprint(line_text, file.inputs);
}

line::ScheduleRow failed_row(const io::LineFile& file, std::size_t index, std::string_view message) {
  const line::LineSpan& s = file.line.spans().at(index);
  Row r;
  r.index = index;
  r.id = s.id;
  r.conductor = s.span.conductor().name;
  r.length = s.span.length();
  r.tension = s.span.tension();
  r.tension_fraction = s.span.tension() / s.span.conductor().rated_tensile_strength;
  r.catenary_parameter = r.span_parameter = r.endurance_limit = kNoValue;
  r.undamped_max_stress = r.undamped_life_years = r.max_stress = r.max_stress_frequency = r.life_years = kNoValue;
  r.max_stress_high = kNoValue;
  r.points = 1;
  r.warnings.push_back(fmt::format("not scheduled: {}", message));
  return r;
}

}  // namespace stockbridge::requests
