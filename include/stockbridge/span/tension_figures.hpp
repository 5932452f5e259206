#pragma once
// A span's tension as line engineers give it, and CIGRE's safe design tension for
// an undamped span (MODEL.md section 11; docs/span.md, "Tension").
//
// Tension is given three ways: in N; as a fraction of the rated tensile strength
// (RTS); as the catenary parameter H/w (m), H = (H/w) m g (conductor.hpp). The span
// parameter L D / m (m^3/kg) is the other axis of CIGRE TB 273's ("Overhead
// conductor safe design tension with respect to aeolian vibrations", Task Force
// B2.11.04, 2005) charts. For single conductors without dampers TB 273 recommends
// an H/w no higher than a limit that depends on the terrain's turbulence: the
// rougher the terrain, the more turbulent the wind and the less it feeds aeolian
// vibration. The four categories and limits are those docs/span.md cites.

#include <optional>
#include <string>
#include <string_view>

#include "stockbridge/span/span.hpp"

namespace stockbridge::span {

/// One of TB 273's terrain categories.
struct TerrainCategory {
  int category = 0;                     ///< 1 (open, smooth: the most severe) to 4 (built-up)
  std::string_view description;         ///< the category's terrain, as docs/span.md words it
  double catenary_parameter_limit = 0;  ///< the safe design H/w of an undamped single conductor, m
  /// The wind's turbulence intensity this program assumes for the category (not
  /// TB 273's: docs/span.md, "Terrain in the wind"): I = 1 / ln(z / z0) at the
  /// reference height z = 10 m (the logarithmic law of EN 1991-1-4, (4.7), with
  /// k_I = c_0 = 1), with the roughness length z0 below.
  double roughness_length = 0;          ///< z0, m
  double turbulence_intensity() const;
};

/// The reference height of the assumed turbulence intensities, m.
inline constexpr double turbulence_reference_height = 10.0;

/// Category 1..4; InvalidParameter naming `field` otherwise.
const TerrainCategory& terrain_category(int category, std::string_view field = "terrain");

/// The span's tension in each form, whatever the span file gave.
struct TensionFigures {
  double tension = 0.0;             ///< T, N
  double fraction_of_rts = 0.0;     ///< T / RTS
  double catenary_parameter = 0.0;  ///< H/w = T / (m g), m
  double span_parameter = 0.0;      ///< L D / m, m^3/kg
};
TensionFigures tension_figures(const Span& span);

/// The wind of a span in its terrain (docs/span.md, "Terrain in the wind"): with
/// `by_terrain` (a span file's wind_law_by_terrain) the cigre law becomes foti; a
/// foti law without its own turbulence intensity (`intensity_given` false) takes
/// the terrain's (TerrainCategory::turbulence_intensity), and records the category
/// it came from (WindModel::turbulence_terrain); without a terrain it keeps 0 (the
/// laminar wind, CIGRE's). InvalidParameter naming "wind_law_by_terrain" for a span
/// without a terrain, or a law other than cigre or foti.
WindModel terrain_wind(WindModel wind, std::optional<int> terrain, bool by_terrain, bool intensity_given);

/// The bounds of a tension a span hangs at: H/w from 100 to 5000 m, and a sag
/// (the parabola's w L^2 / (8 H)) within a tenth of the span.
inline constexpr double min_catenary_parameter = 100.0;
inline constexpr double max_catenary_parameter = 5000.0;
inline constexpr double max_sag_ratio = 0.1;

/// The sag of the span as a fraction of its length, L / (8 H/w).
double sag_ratio(const Conductor& conductor, double length, double tension);

/// Why a tension (N) is not one the span hangs at (the bounds above), as a message's
/// tail ("H/w = 2 m: expected 100 to 5000 m ..."); none where it is. Most often a
/// tension in kN, a fraction in percent or a length in km.
std::optional<std::string> implausible_tension(const Conductor& conductor, double length, double tension);

/// TB 273's judgement of the span without dampers: H/w against its terrain's limit.
struct SafeDesignTension {
  TerrainCategory terrain;
  double catenary_parameter = 0.0;  ///< the span's H/w, m
  bool within = false;              ///< H/w <= the limit
};
/// None unless the span gives its terrain.
std::optional<SafeDesignTension> safe_design_tension(const Span& span);

}  // namespace stockbridge::span
