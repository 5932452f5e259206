#pragma once
// Reading span description files (TOML, format in docs/file-formats.md and
// docs/span.md): the conductor, the span, the wind, the self-damping, the dampers
// and the fatigue criterion of `stockbridge span`.
//
//   [conductor]
//   name = "ASTER570"
//   mass_per_length = 1.571          # kg/m
//   diameter = 0.03105               # m
//   rated_tensile_strength = 185300  # N
//   ei_min = 28.28                   # N m^2
//   ei_max = 2155                    # N m^2 (optional: Foti's self-damping)
//   outer_wire_diameter = 0.00345    # m
//   outer_wire_modulus = 68e9        # Pa
//   aluminium_layers = 4             # 0 allowed where outer_wire_material is not aluminium
//   outer_wire_material = "aluminium-alloy"  # optional: aluminium (default), aluminium-alloy, steel,
//                                    # aluminium-clad-steel (the last two: no Safe Border Line)
//   [span]
//   length = 400                     # m
//   tension_fraction = 0.15          # or tension = N: exactly one
//   ends = "clamped"                 # optional: clamped (default) | pinned, in time only
//   [wind]
//   law = "cigre"                    # strouhal, speed_min, speed_max optional;
//                                    # turbulence_intensity (foti); table = "fnc.csv" (table)
//   [self_damping]
//   law = "noiseux-1991"             # k, l, m, n, limit_curvature as the law needs
//   [[damper]]                       # zero or more
//   file = "sauter2003.toml"         # a damper file, relative to the span file
//   position = 1.0                   # m from the span end's clamp
//   ends = "both"                    # both (default) | one
//   [fatigue]
//   cycles = 5e8                     # or endurance_limit_mpa = MPa (required for steel or
//                                    # aluminium-clad steel outer wires), endurance_limit = Pa
//   wind_weibull = { shape = 2.0, scale = 4.0 }  # optional, with aeolian_fraction
//   aeolian_fraction = 0.3
//   [balance]                        # optional, every key optional (span::BalanceOptions' defaults)
//   damper_model = "travelling"      # travelling | weak
//   polish = true                    # the dampers solved directly at their clamp velocities
//   polish_tolerance = 1e-6          # in log v
//   max_polish_evaluations = 60
//   amplitude_min_over_diameter = 1e-6
//   amplitude_max_over_diameter = 10
//   [balance.table]                  # the dampers' impedance tables
//   velocities = 9
//   velocity_min = 1e-3              # m/s
//   velocity_max = 3.0               # m/s
//   column_ratio = 1.5
//   [time]                           # optional: a run in time (simulate, span --check-time)
//   elements_per_wavelength = 30
//   steps_per_period = 160
//   duration = 60                    # s simulated at most
//   [wake]                           # optional: simulate --wind wake (Facchinetti's values)
//   epsilon = 0.3
//   coupling = 12
//   lift_coefficient = 0.3
//   air_density = 1.225              # kg/m^3
//
// The reader checks types and keys (a misspelt or unknown key is an error); the
// span model validates the values (span::Span), and its InvalidParameter, named
// by the field's path ("conductor.diameter", "damper[1].position"), is reported at
// that key's line.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stockbridge/core/typical_ranges.hpp"
#include "stockbridge/span/balance.hpp"
#include "stockbridge/span/span.hpp"
#include "stockbridge/span/time_settings.hpp"

namespace stockbridge::io {

/// A span file as read: the (validated) span, how to balance it (validated), the
/// files it references (damper files, the cable files those reference, a wind
/// table: inputs a command must not overwrite; the span file itself is not listed),
/// and a located warning line for each value outside the typical ranges (those of
/// the damper files).
struct SpanFile {
  span::Span span;
  span::BalanceOptions balance;
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> warnings;
  /// How a run in time steps the span ([span] ends, [time]): `simulate` and
  /// `span --check-time`; the balance does not use it.
  span::TimeSettings time;
};

/// Reads a span file and builds the span; InputError naming the file, line, key,
/// value and expectation. Damper files and the wind table are relative to the span
/// file's folder. A value a unit slip explains (typical_ranges.hpp), and a tension
/// at which no span hangs (span::implausible_tension: H/w outside 100 to 5000 m, a
/// sag over a tenth of the span), are refused (UnusualValueError) under
/// SlipPolicy::refuse, warnings under warn.
SpanFile load_span_file(const std::filesystem::path& path, SlipPolicy policy = SlipPolicy::refuse);
/// The same from TOML text a front end holds (Python's span(text=...)): messages
/// name `source` and no lines; referenced files are relative to `base_directory`
/// (empty: the working directory), and a missing one's message says which.
SpanFile load_span_text(std::string_view text, std::string_view source,
                        const std::filesystem::path& base_directory = {}, SlipPolicy policy = SlipPolicy::refuse);

}  // namespace stockbridge::io
