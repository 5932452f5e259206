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
#include <string_view>

#include "stockbridge/span/span.hpp"

namespace stockbridge::span {

/// One of TB 273's terrain categories.
struct TerrainCategory {
  int category = 0;                     ///< 1 (open, smooth: the most severe) to 4 (built-up)
  std::string_view description;         ///< the category's terrain, as docs/span.md words it
  double catenary_parameter_limit = 0;  ///< the safe design H/w of an undamped single conductor, m
};

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

/// TB 273's judgement of the span without dampers: H/w against its terrain's limit.
struct SafeDesignTension {
  TerrainCategory terrain;
  double catenary_parameter = 0.0;  ///< the span's H/w, m
  bool within = false;              ///< H/w <= the limit
};
/// None unless the span gives its terrain.
std::optional<SafeDesignTension> safe_design_tension(const Span& span);

}  // namespace stockbridge::span
