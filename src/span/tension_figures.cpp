#include "stockbridge/span/tension_figures.hpp"

#include <array>
#include <string>

#include "stockbridge/core/error.hpp"

namespace stockbridge::span {

namespace {

// CIGRE TB 273 (2005), single unprotected conductors: the safe design tension H/w
// by terrain category (docs/span.md, "Tension", gives the source and its caveat).
constexpr std::array<TerrainCategory, 4> kTerrainCategories{{
    {1, "open, flat, no trees, no obstruction, with snow cover, or near or across large bodies of water; flat desert",
     1000.0},
    {2, "open, flat, no obstruction, no snow; e.g. farmland without any obstruction, summer time", 1125.0},
    {3, "open, flat or undulating with very few obstacles; e.g. open grass or farmland with few trees, hedgerows and "
        "other barriers; prairie, tundra",
     1225.0},
    {4, "built-up with some trees and buildings; e.g. residential suburbs, small towns, woodlands and shrubs; small "
        "fields with bushes, trees and hedges",
     1425.0},
}};

}  // namespace

const TerrainCategory& terrain_category(int category, std::string_view field) {
  require_in_range(std::string(field), category, 1, static_cast<int>(kTerrainCategories.size()));
  return kTerrainCategories[static_cast<std::size_t>(category - 1)];
}

TensionFigures tension_figures(const Span& span) {
  const Conductor& c = span.conductor();
  return {span.tension(), span.tension() / c.rated_tensile_strength, catenary_parameter(c, span.tension()),
          span.length() * c.diameter / c.mass_per_length};
}

std::optional<SafeDesignTension> safe_design_tension(const Span& span) {
  if (!span.terrain()) return std::nullopt;
  const TerrainCategory& terrain = terrain_category(*span.terrain());
  const double h_over_w = catenary_parameter(span.conductor(), span.tension());
  return SafeDesignTension{terrain, h_over_w, h_over_w <= terrain.catenary_parameter_limit};
}

}  // namespace stockbridge::span
