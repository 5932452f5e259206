#pragma once
// The power the wind feeds into a vibrating span (MODEL.md section 9; docs/span.md).
//
// Wind of speed U sheds vortices off the conductor at f = St U / D (Strouhal
// number St); locked onto a standing wave of antinode amplitude Y at that
// frequency, it feeds the span of length L with
//     P_w = L f^3 D^4 fnc(Y / D)                              (W)
// where the reduced power fnc (W / (m Hz^3 m^4)) is measured in wind tunnels and
// on test spans. The laws here:
//   * cigre: fnc(y) = 0.2256 + 0.1627 y + 101.62 y^2 - 99.73 y^3, a formula for every
//     y >= 0; it falls through zero at y = 1.022 and is negative beyond, which bounds
//     the amplitude.
//   * foti: Foti & Martinelli (2018): CIGRE's times 1 / sqrt(1 + (I_v / 0.09)^2), I_v
//     the turbulence intensity.
//   * diana-falco (1971), rawlins-1983, brika-laneville (1995): the measured curves by
//     their published points (published_points), joined by straight lines.
//   * table: the user's points (y_over_d strictly increasing from >= 0), the same way.
// A law given by points (a measured one or a table) is extended outside its points
// by two rules: below the first point a straight line to fnc(0) = 0 (the wind does
// no work on a conductor at rest; a first point at y = 0 keeps its own value);
// beyond the last point its last value is held. The balance still has a finite
// amplitude, since the self-damping grows like Y^l (l >= 2) while P_w stays bounded;
// measured_range() tells a caller where the law rests on data.

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace stockbridge::span {

enum class WindLaw { cigre, foti, diana_falco_1971, rawlins_1983, brika_laneville_1995, table };

/// "cigre", "foti", "diana-falco", "rawlins-1983", "brika-laneville" or "table";
/// throws InvalidParameter naming "law" otherwise.
WindLaw parse_wind_law(std::string_view name);
std::string_view wind_law_name(WindLaw law);

/// One point of a reduced-power curve: fnc (W / (m Hz^3 m^4)) at y = Y / D.
struct WindPoint {
  double y_over_d = 0.0;
  double fnc = 0.0;
};

/// The published points of a measured law (diana-falco, rawlins-1983, brika-laneville);
/// empty for the others. Sources in docs/span.md.
std::span<const WindPoint> published_points(WindLaw law);

/// A closed interval [lo, hi].
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// What a span file's [wind] table says; validate() checks it once.
struct WindModel {
  WindLaw law = WindLaw::cigre;
  double strouhal = 0.185;            ///< St, in (0, 1)
  double speed_min = 1.0;             ///< lowest wind speed of the aeolian band, m/s
  double speed_max = 7.0;             ///< highest, m/s (> speed_min)
  double turbulence_intensity = 0.0;  ///< I_v, in [0, 1]; law foti only
  /// Where turbulence_intensity is the span's terrain's assumed one (span/tension_figures.hpp,
  /// terrain_wind): the TB 273 category; none where given.
  std::optional<int> turbulence_terrain;
  std::vector<WindPoint> table;       ///< law table only: at least 2 points
  /// A factor on the wind's power input, any law (> 0; 1: the law as published): a
  /// line's own record calibrates it (stockbridge recorder --calibrate wind.power_scale).
  double power_scale = 1.0;

  /// Throws InvalidParameter naming the field ("strouhal", "speed_max",
  /// "turbulence_intensity", "table", "table[2].y_over_d", ...). A setting the law
  /// does not use (a turbulence intensity other than 0 without foti, a table without
  /// table) is an error rather than silently ignored.
  void validate() const;

  /// The reduced power at y = Y / D >= 0, W / (m Hz^3 m^4).
  double fnc(double y_over_d) const;
  /// P_w = power_scale L f^3 D^4 fnc(Y / D), W: amplitude Y (m, antinode, zero-to-peak), frequency f
  /// (Hz), diameter D (m), span length L (m).
  double power(double amplitude, double frequency, double diameter, double span_length) const;
  /// The frequencies the wind band excites: St speed_min / D to St speed_max / D, Hz.
  Interval frequency_band(double diameter) const;
  /// The wind speed that sheds vortices at `frequency`: U = f D / St, m/s.
  double wind_speed(double frequency, double diameter) const;
  /// The y = Y / D from the first to the last point of a law given by points; none for
  /// cigre and foti (formulas for every y).
  std::optional<Interval> measured_range() const;

 private:
  std::span<const WindPoint> points() const;
};

/// CIGRE's reduced power 0.2256 + 0.1627 y + 101.62 y^2 - 99.73 y^3.
double cigre_fnc(double y_over_d);
/// Foti & Martinelli's turbulence factor 1 / sqrt(1 + (I_v / 0.09)^2).
double foti_turbulence_factor(double turbulence_intensity);
/// The curve through `points` with the two extension rules above (points validated).
double interpolate_fnc(std::span<const WindPoint> points, double y_over_d);

}  // namespace stockbridge::span
