#include "stockbridge/requests/span_modes_request.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/conductor.hpp"

namespace stockbridge::requests {

namespace {

// Names in this unnamed namespace are unique across the library (unity batches).

/// An attachment's name as a column's prefix: letters, digits and '_' ("mass 1" -> "mass_1").
std::string attachment_word(const std::string& name) {
  std::string word = name;
  for (char& ch : word) {
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_')) ch = '_';
  }
  return word;
}

/// Each attachment's column prefix: its name, numbered by position where it is at several.
std::vector<std::string> attachment_column_names(const std::vector<span::ModeAttachment>& attachments) {
  std::vector<std::string> words;
  for (const span::ModeAttachment& a : attachments) words.push_back(attachment_word(a.name));
  std::vector<std::string> names;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const auto alike = std::count(words.begin(), words.end(), words[i]);
    const auto before = std::count(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(i), words[i]);
    names.push_back(alike > 1 ? fmt::format("{}_{}", words[i], before + 1) : words[i]);
  }
  return column_prefixes(names, "attachment");
}

/// The bare string's frequency of mode n: n c / (2 L), Hz.
double bare_string_frequency(const span::SpanModes& modes, int n) { return n * modes.wave_speed / (2.0 * modes.length); }

/// The attachments at sample i of the shapes, by name ("sphere", "sphere;sauter2003").
std::string attachments_at(const span::SpanModes& modes, std::size_t i) {
  std::string names;
  for (const span::ModeAttachment& a : modes.attachments) {
    if (a.position == modes.x[i]) names += (names.empty() ? "" : ";") + a.name;
  }
  return names;
}

std::vector<io::JsonObject> attachments_json(const SpanModesResult& result) {
  std::vector<io::JsonObject> out;
  for (std::size_t i = 0; i < result.modes.attachments.size(); ++i) {
    const span::ModeAttachment& a = result.modes.attachments[i];
    out.push_back(io::JsonObject()
                      .add("name", a.name)
                      .add("column", result.attachment_columns[i])
                      .add("kind", span::attachment_kind_name(a.kind))
                      .add("position_m", a.position)
                      .add("mass_kg", a.mass));
  }
  return out;
}

}  // namespace

void validate(const SpanModesRequest& request) {
  if (request.fmax) require_plausible("fmax", *request.fmax, "Hz");
  span::parse_mode_dampers(request.dampers);
  if (!(std::isfinite(request.samples_per_wavelength) && request.samples_per_wavelength >= 4.0 &&
        request.samples_per_wavelength <= 1000.0)) {
    throw_invalid("samples_per_wavelength", request.samples_per_wavelength, "from 4 to 1000 samples a wavelength");
  }
}

span::SpanModesOptions span_modes_options(const span::Span& span, const SpanModesRequest& request) {
  validate(request);
  span::SpanModesOptions options;
  options.max_frequency_hz = request.fmax.value_or(span.wind().frequency_band(span.conductor().diameter).hi);
  options.dampers = span::parse_mode_dampers(request.dampers);
  options.shapes = request.shapes;
  options.samples_per_wavelength = request.samples_per_wavelength;
  options.validate();
  return options;
}

SpanModesResult run_span_modes(const span::Span& span, const SpanModesRequest& request) {
  SpanModesResult result;
  try {
    result.modes = span::span_modes(span, span_modes_options(span, request));
  } catch (const InvalidParameter& e) {
    if (e.field() != "max_frequency_hz") throw;
    throw InvalidParameter("fmax", e.detail());  // the option as the user named it
  }
  result.fmax_from_wind_band = !request.fmax.has_value();
  result.attachment_columns = attachment_column_names(result.modes.attachments);
  return result;
}

Table<span::SpanMode> span_modes_table(const SpanModesResult& result) {
  const span::SpanModes* modes = &result.modes;
  return Table<span::SpanMode>(
      {
          {"mode", "", "the mode's number, from 1 by increasing frequency", ColumnKind::count,
           [](const span::SpanMode& m, std::size_t) { return static_cast<double>(m.number); }, {}},
          {"frequency_hz", "Hz", "its natural frequency", ColumnKind::number,
           [](const span::SpanMode& m, std::size_t) { return m.frequency_hz; }, {}},
          {"wavelength_m", "m", "the conductor's wavelength at it, c / f", ColumnKind::number,
           [](const span::SpanMode& m, std::size_t) { return m.wavelength_m; }, {}},
          {"bare_frequency_ratio", "",
           "the frequency over the bare span's mode of the same number, n c / (2 L): what the attachments move it by",
           ColumnKind::number,
           [modes](const span::SpanMode& m, std::size_t) { return m.frequency_hz / bare_string_frequency(*modes, m.number); },
           {}},
          {"end_residual", "", "|Y(L)| of the chain at the frequency found over the largest |Y|: round-off",
           ColumnKind::number, [](const span::SpanMode& m, std::size_t) { return m.end_residual; }, {}},
          {"<attachment>_deflection", "",
           "Y at the attachment over the largest |Y| along the span (0: the mode leaves it still)", ColumnKind::number,
           [](const span::SpanMode& m, std::size_t a) { return m.attachment_deflection[a]; }, {}},
      },
      {{"<attachment>", result.attachment_columns}});
}

Table<ShapeSample> span_mode_shapes_table(const SpanModesResult& result) {
  const span::SpanModes* modes = &result.modes;
  std::vector<std::string> mode_columns;
  for (const span::SpanMode& m : modes->modes) mode_columns.push_back(fmt::format("mode_{}", m.number));
  return Table<ShapeSample>(
      {
          {"attachment", "", "the attachments at x_m by name (';' between several), empty between them",
           ColumnKind::label, {}, [modes](const ShapeSample& s, std::size_t) { return attachments_at(*modes, s.index); }},
          {"x_m", "m", "the distance from end 1", ColumnKind::number,
           [modes](const ShapeSample& s, std::size_t) { return modes->x[s.index]; }, {}},
          {"<mode>", "",
           "a column per mode (mode_1, mode_2, ...): its shape Y over the largest |Y| along the span, Y'(0) > 0",
           ColumnKind::number, [modes](const ShapeSample& s, std::size_t m) { return modes->modes[m].shape[s.index]; },
           {}},
      },
      {{"<mode>", mode_columns}});
}

std::vector<ShapeSample> shape_samples(const SpanModesResult& result) {
  std::vector<ShapeSample> samples;
  for (std::size_t i = 0; i < result.modes.x.size(); ++i) samples.push_back({i});
  return samples;
}

io::JsonObject span_modes_summary(const SpanModesResult& result) {
  const span::SpanModes& m = result.modes;
  std::vector<double> frequencies;
  for (const span::SpanMode& mode : m.modes) frequencies.push_back(mode.frequency_hz);
  return io::JsonObject()
      .add("length_m", m.length)
      .add("wave_speed_m_s", m.wave_speed)
      .add("bare_fundamental_hz", bare_string_frequency(m, 1))
      .add("fmax_hz", m.max_frequency_hz)
      .add("fmax_from_wind_band", result.fmax_from_wind_band)
      .add("dampers", span::mode_dampers_name(m.dampers))
      .add("modes", static_cast<int>(m.modes.size()))
      .add("frequencies_hz", frequencies)
      .add("clamp_still_modes", m.clamp_still_modes)
      .add("max_end_residual", m.max_end_residual)
      .add("attachments", attachments_json(result));
}

}  // namespace stockbridge::requests
