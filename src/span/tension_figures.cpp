#include "stockbridge/span/tension_figures.hpp"

#include <array>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

// CIGRE TB 273 (2005), single unprotected conductors: the safe design tension H/w
// by terrain category (docs/span.md, "Tension", gives the source and its caveat).
// The roughness lengths are this program's assumption (docs/span.md): EN 1991-1-4's
// terrain categories I (0.01 m), II (0.05 m) and III (0.3 m) for TB 273's 1, 2 and 4,
// and 0.1 m, between II and III, for 3.
constexpr std::array<TerrainCategory, 4> kTerrainCategories{{
    {1, "open, flat, no trees, no obstruction, with snow cover, or near or across large bodies of water; flat desert",
     1000.0, 0.01},
    {2, "open, flat, no obstruction, no snow; e.g. farmland without any obstruction, summer time", 1125.0, 0.05},
    {3, "open, flat or undulating with very few obstacles; e.g. open grass or farmland with few trees, hedgerows and "
        "other barriers; prairie, tundra",
     1225.0, 0.1},
    {4, "built-up with some trees and buildings; e.g. residential suburbs, small towns, woodlands and shrubs; small "
        "fields with bushes, trees and hedges",
     1425.0, 0.3},
}};

}  // namespace

double TerrainCategory::turbulence_intensity() const {
  return 1.0 / std::log(turbulence_reference_height / roughness_length);
}

WindModel terrain_wind(WindModel wind, std::optional<int> terrain, bool by_terrain, bool intensity_given) {
  if (by_terrain) {
    if (!terrain) throw InvalidParameter("wind_law_by_terrain", ": the span gives no terrain (1 to 4) to take the wind's turbulence from");
    if (wind.law != WindLaw::cigre && wind.law != WindLaw::foti) {
      throw InvalidParameter("wind_law_by_terrain",
                             fmt::format(": turns law cigre into foti (CIGRE's times the turbulence's reduction); the "
                                         "wind's law is {}",
                                         wind_law_name(wind.law)));
    }
    wind.law = WindLaw::foti;
  }
  if (wind.law != WindLaw::foti || intensity_given || !terrain) return wind;
  wind.turbulence_intensity = terrain_category(*terrain).turbulence_intensity();
  wind.turbulence_terrain = *terrain;
  return wind;
}

const TerrainCategory& terrain_category(int category, std::string_view field) {
  require_in_range(std::string(field), category, 1, static_cast<int>(kTerrainCategories.size()));
  return kTerrainCategories[static_cast<std::size_t>(category - 1)];
}

TensionFigures tension_figures(const Span& span) {
  const Conductor& c = span.conductor();
  return {span.tension(), span.tension() / c.rated_tensile_strength, catenary_parameter(c, span.tension()),
          span.length() * c.diameter / c.mass_per_length};
}

double sag_ratio(const Conductor& conductor, double length, double tension) {
  return length / (8.0 * catenary_parameter(conductor, tension));
}

std::optional<std::string> implausible_tension(const Conductor& conductor, double length, double tension) {
  const double h_over_w = catenary_parameter(conductor, tension);
  const double sag = sag_ratio(conductor, length, tension);
  if (h_over_w >= min_catenary_parameter && h_over_w <= max_catenary_parameter && sag <= max_sag_ratio) {
    return std::nullopt;
  }
  return fmt::format("H/w = {:.4g} m and a sag of {:.3g} m ({:.3g} % of the {} m span): expected H/w from {:g} to {:g} "
                     "m and a sag within {:g} % of the span, as spans hang",
                     h_over_w, sag * length, 100.0 * sag, format_value(length), min_catenary_parameter,
                     max_catenary_parameter, 100.0 * max_sag_ratio);
}

std::optional<SafeDesignTension> safe_design_tension(const Span& span) {
  if (!span.terrain()) return std::nullopt;
  const TerrainCategory& terrain = terrain_category(*span.terrain());
  const double h_over_w = catenary_parameter(span.conductor(), span.tension());
  return SafeDesignTension{terrain, h_over_w, h_over_w <= terrain.catenary_parameter_limit};
}

}  // namespace stockbridge::span
