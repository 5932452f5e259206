#pragma once
// The request layer for the span's natural frequencies with its attachments
// (`stockbridge span --modes`, Python's span_modes; span/span_modes.hpp): what a
// user asks for by the names they type (fmax, dampers, shapes), with its defaults
// (fmax: the top of the span's wind band), validated once; the run; the modes
// CSV's rows, the shapes CSV's samples and the JSON summary both front ends show.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "stockbridge/io/json_writer.hpp"
#include "stockbridge/requests/output_table.hpp"
#include "stockbridge/span/span_modes.hpp"

namespace stockbridge::requests {

struct SpanModesRequest {
  std::optional<double> fmax;       ///< Hz: the modes below it; none: the top of the span's wind band
  std::string dampers = "linear";   ///< removed | linear (span::parse_mode_dampers)
  bool shapes = true;               ///< sample the shapes (the shapes CSV, Python's arrays)
  double samples_per_wavelength = span::SpanModesOptions{}.samples_per_wavelength;
};

/// Checks what can be checked without the span: InvalidParameter naming the setting
/// ("fmax", "dampers", "samples_per_wavelength").
void validate(const SpanModesRequest& request);

/// The library's options for `span`: fmax, or the top of its wind band St U_max / D.
span::SpanModesOptions span_modes_options(const span::Span& span, const SpanModesRequest& request);

struct SpanModesResult {
  span::SpanModes modes;
  bool fmax_from_wind_band = false;  ///< fmax was not given: the wind band's top
  /// How the per-attachment columns name each attachment: its name where it is
  /// unique, name_1, name_2, ... for one at several positions (column_prefixes:
  /// attachment1, attachment2, ... for all where those are not usable).
  std::vector<std::string> attachment_columns;
};

/// Validates the request and computes the modes of `span` (span::span_modes).
/// Throws InvalidParameter naming "dampers" where a damper known only by its sheet
/// is asked for at its linear impedance.
SpanModesResult run_span_modes(const span::Span& span, const SpanModesRequest& request);

/// The modes CSV's quantities, a row per mode: mode, frequency_hz, wavelength_m,
/// bare_frequency_ratio (f over the bare string's n c / (2 L)), end_residual, then
/// for each attachment <attachment>_deflection (Y there over the largest |Y|).
Table<span::SpanMode> span_modes_table(const SpanModesResult& result);

/// A sample of the shapes CSV: its index into SpanModes::x.
struct ShapeSample {
  std::size_t index = 0;
};
/// The shapes CSV's quantities, a row per sample along the span: attachment (the
/// attachments' names at that x, ';'-separated; empty between them), x_m, then a
/// column per mode, mode_1, mode_2, ... (<mode>: Y / max |Y|).
Table<ShapeSample> span_mode_shapes_table(const SpanModesResult& result);
/// Every sample's row of the shapes CSV.
std::vector<ShapeSample> shape_samples(const SpanModesResult& result);

/// The --json summary: length_m, wave_speed_m_s, bare_fundamental_hz, fmax_hz,
/// fmax_from_wind_band, dampers, modes, frequencies_hz, clamp_still_modes,
/// max_end_residual, attachments [{name, column, kind, position_m, mass_kg}].
io::JsonObject span_modes_summary(const SpanModesResult& result);

}  // namespace stockbridge::requests
