#pragma once
// The conductor of MODEL.md section 9's check numbers and of issue 14's example:
// ASTER570 (all-aluminium-alloy, 61 wires of 3.45 mm) at 15 % of its rated strength.

#include <cmath>

#include <gtest/gtest.h>

#include "stockbridge/span/conductor.hpp"

namespace stockbridge::span::testing {

inline Conductor aster570() {
  Conductor c;
  c.name = "ASTER570";
  c.mass_per_length = 1.571;
  c.diameter = 0.03105;
  c.rated_tensile_strength = 185300.0;
  c.ei_min = 28.28;
  c.ei_max = 2155.0;
  c.outer_wire_diameter = 0.00345;
  c.outer_wire_modulus = 68e9;
  c.aluminium_layers = 4;
  return c;
}

/// T = 0.15 RTS = 27795 N.
inline constexpr double aster570_tension = 0.15 * 185300.0;

inline void expect_relative(double actual, double expected, double tolerance) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected))
      << "actual " << actual << ", expected " << expected << " (relative tolerance " << tolerance << ")";
}

}  // namespace stockbridge::span::testing
