// The span's conductor: taut-string quantities on hand-computed numbers, the
// tensioned beam's wavenumbers against their dispersion relation, Lilien's k, and
// validation messages naming the span file's field.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "support/error_message.hpp"
#include "unit/span/aster570.hpp"

#include "stockbridge/core/error.hpp"
#include "stockbridge/span/conductor.hpp"

namespace stockbridge::span {
namespace {

using stockbridge::testing::invalid_parameter_message;
using testing::aster570;
using testing::aster570_tension;
using testing::expect_relative;

TEST(Conductor, TautStringQuantitiesOfAster570) {
  const Conductor c = aster570();
  const double t = aster570_tension;  // 27795 N
  // c = sqrt(27795 / 1.571) = sqrt(17692.55) = 133.0134 m/s
  expect_relative(wave_speed(c, t), 133.01335, 1e-6);
  // at 20 Hz: k = 2 pi 20 / 133.0134 = 0.944745 rad/m, lambda = 133.0134 / 20 = 6.650668 m
  expect_relative(wavenumber(c, t, 20.0), 0.944745, 1e-6);
  expect_relative(wavelength(c, t, 20.0), 6.650668, 1e-6);
  // Z0 = sqrt(27795 * 1.571) = sqrt(43665.9) = 208.964 N s/m
  expect_relative(wave_impedance(c, t), 208.96398, 1e-6);
  // p = sqrt(27795 / 28.28) = sqrt(982.85) = 31.3504 1/m
  expect_relative(bending_decay(c, t), 31.35044, 1e-6);
}

// Tension as utilities give it: 27795 N of ASTER570 is H/w = 27795 / (1.571 * 9.80665)
// = 27795 / 15.40625 = 1804.14 m; back again exactly.
TEST(Conductor, TheCatenaryParameterOfAster570) {
  const Conductor c = aster570();
  expect_relative(catenary_parameter(c, aster570_tension), 1804.138, 1e-6);
  expect_relative(tension_from_catenary_parameter(c, 1804.138), aster570_tension, 1e-6);
  EXPECT_EQ(invalid_parameter_message([&] { tension_from_catenary_parameter(c, -1.0); }),
            "catenary_parameter = -1: expected a finite value > 0 (m)");
  // RTS / (m g) = 185300 / 15.40625 = 12027.59 m
  EXPECT_EQ(invalid_parameter_message([&] { tension_from_catenary_parameter(c, 13000.0); }),
            "catenary_parameter = 13000: expected less than the rated tensile strength per weight, 12027.6 m (T = "
            "(H/w) m g = 200281 N)");
  EXPECT_EQ(invalid_parameter_message([&] { tension_from_fraction(c, 15.0); }),
            "tension_fraction = 15: expected a fraction of the rated tensile strength > 0 and < 1 (a percentage? 15 % "
            "is 0.15)");
}

TEST(Conductor, LiliensKOfAster570) {
  // 31.05 mm / sqrt(1.571 kg/m * 185.3 kN) = 31.05 / sqrt(291.1063) = 31.05 / 17.06184 = 1.81985
  expect_relative(lilien_k(aster570()), 1.819851, 1e-6);
}

TEST(Conductor, BeamWavenumbersSolveTheTensionedBeam) {
  const Conductor c = aster570();
  const double t = aster570_tension;
  for (double f : {5.0, 40.0, 150.0}) {
    const BeamWavenumbers b = beam_wavenumbers(c, t, f);
    const double mw2 = c.mass_per_length * std::pow(2.0 * std::numbers::pi * f, 2);
    // sin(k1 x): EI k1^4 + T k1^2 = m w^2;  exp(-p1 x): EI p1^4 - T p1^2 = m w^2
    expect_relative(c.ei_min * std::pow(b.travelling, 4) + t * b.travelling * b.travelling, mw2, 1e-12);
    expect_relative(c.ei_min * std::pow(b.decaying, 4) - t * b.decaying * b.decaying, mw2, 1e-9);
    EXPECT_LT(b.travelling, wavenumber(c, t, f));  // bending stiffens: a longer wave
  }
  Conductor string_like = c;
  string_like.ei_min = 1e-9;  // k1 -> k: no cancellation in the formula
  expect_relative(beam_wavenumbers(string_like, t, 20.0).travelling, wavenumber(c, t, 20.0), 1e-12);
}

TEST(Conductor, ValidationNamesTheField) {
  EXPECT_NO_THROW(aster570().validate());
  Conductor c = aster570();
  c.mass_per_length = -1.0;
  EXPECT_EQ(invalid_parameter_message([&] { c.validate(); }),
            "mass_per_length = -1: expected a finite value > 0 (kg/m)");
  c = aster570();
  c.ei_max = 20.0;
  EXPECT_EQ(invalid_parameter_message([&] { c.validate(); }),
            "ei_max = 20: expected 0 (not given) or at least ei_min = 28.28 N m^2");
  c.ei_max = 0.0;  // not given: fine
  EXPECT_NO_THROW(c.validate());
  c = aster570();
  c.outer_wire_diameter = 0.04;
  EXPECT_EQ(invalid_parameter_message([&] { c.validate(); }),
            "outer_wire_diameter = 0.04: expected less than the conductor's diameter = 0.03105 m");
  c = aster570();
  c.aluminium_layers = 0;
  EXPECT_EQ(invalid_parameter_message([&] { c.validate(); }),
            "aluminium_layers = 0: expected an integer from 1 to 10");
  c = aster570();
  c.outer_wire_modulus = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(invalid_parameter_message([&] { c.validate(); }).rfind("outer_wire_modulus = ", 0), 0u);
}

TEST(Conductor, TensionLiesBetweenZeroAndTheRatedStrength) {
  const Conductor c = aster570();
  EXPECT_NO_THROW(check_tension(c, aster570_tension));
  EXPECT_EQ(invalid_parameter_message([&] { check_tension(c, 185300.0); }),
            "tension = 185300: expected less than the rated tensile strength = 185300 N");
  EXPECT_EQ(invalid_parameter_message([&] { check_tension(c, 0.0); }), "tension = 0: expected a finite value > 0 (N)");
  EXPECT_DOUBLE_EQ(tension_from_fraction(c, 0.15), aster570_tension);
  EXPECT_EQ(invalid_parameter_message([&] { tension_from_fraction(c, 1.2); }),
            "tension_fraction = 1.2: expected a fraction of the rated tensile strength > 0 and < 1");
}

}  // namespace
}  // namespace stockbridge::span
