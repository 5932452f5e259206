// slenderpy's damper (examples/slenderpy_damper.toml, the Bouc-Wen law) against
// slenderpy's equations converged in space and time (tests/support/reference_bouc_wen.hpp:
// the rate form of the law by the trapezoid rule, equal midpoint sections, an explicit
// time march; nothing shared with the library).

#include <complex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stockbridge/damper/steady_state.hpp"
#include "stockbridge/io/damper_file.hpp"
#include "support/reference_bouc_wen.hpp"
#include "support/test_scale.hpp"

namespace stockbridge::damper {
namespace {

namespace reference = testing::reference;

/// slenderpy's arm (MODEL.md section 13) on n equal sections.
reference::BoucWenArmNumbers slenderpy_arm(int sections) {
  const double l = 0.1875;
  return {.mass = 0.856,
          .inertia = 0.001814,
          .offset = 0.0325,
          .length = l,
          .sections = sections,
          .zones = {{0.2 * l, 5.0, 40.0, 0.15}, {0.92 * l, 2.5, 25.0, 0.03}, {l, 5.0, 40.0, 0.15}}};
}

reference::BoucWenDamperNumbers slenderpy_damper(int sections) {
  return {.clamp_mass = 0.7, .arms = {slenderpy_arm(sections), slenderpy_arm(sections)}};
}

std::complex<double> library_impedance(double frequency_hz, double velocity) {
  static const Damper damper =
      io::read_damper_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/slenderpy_damper.toml");
  const DamperSteadyState s = solve_steady_state(damper, Excitation::from_velocity(frequency_hz, velocity), {});
  EXPECT_TRUE(s.point.converged()) << s.point.failure;
  return s.point.impedance;
}

reference::MarchOptions bouc_wen_march(int steps) {
  reference::MarchOptions options;
  options.steps_per_period = steps;
  options.periodicity_tolerance = 1e-6;
  options.max_periods = 3000;
  return options;
}

// The library at its defaults (40 Gauss points over slenderpy's three zones, the
// harmonic-balance defaults) against the reference on 100 sections and 2000 steps a
// period, at 0.2 m/s from 10 to 100 Hz. Measured (Release): within 2.3e-4 of |Z| at
// 10, 25 and 60 Hz (10 Hz: 221.444 + 171.669i against 221.426 + 171.658i). The
// reference's own error (ReferenceConverges) is about that size, so the tolerance
// is 1e-3 of |Z|, well inside what issue 32 asks (1.5 %, 2.5 % at 10 Hz, where
// the arm sits between its stick and slip modes). (Checked: with chi0 5 % larger
// in the middle zone, given to the library only, every frequency fails, by 1.5 to
// 16 % of |Z|.)
TEST(BoucWenReference, LibraryMatchesSlenderpysEquationsConverged) {
  for (const double f : {10.0, 15.0, 25.0, 40.0, 60.0, 100.0}) {
    const std::complex<double> z = library_impedance(f, 0.2);
    const reference::ReferenceResult r = reference::reference_bouc_wen_impedance(slenderpy_damper(100), f, 0.2, bouc_wen_march(2000));
    EXPECT_LT(std::abs(z - r.impedance), 1e-3 * std::abs(r.impedance))
        << f << " Hz: library " << z << ", reference " << r.impedance;
    // The reference's energy balance: the shaker's work is what the sections dissipate.
    EXPECT_LT(std::abs(r.input_power - r.dissipated_power), 1e-5 * r.input_power) << f << " Hz";
  }
}

// The reference converges: at second order in the sections (50 -> 100 -> 200: each
// step about 4x closer) and its time step is fine (2000 -> 4000 steps a period
// moves Z by about 1e-6 of |Z|).
TEST(BoucWenReference, ReferenceConverges) {
  const double f = 25.0;
  const auto z = [&](int sections, int steps) {
    return reference::reference_bouc_wen_impedance(slenderpy_damper(sections), f, 0.2, bouc_wen_march(steps)).impedance;
  };
  const std::complex<double> z50 = z(50, 2000), z100 = z(100, 2000), z200 = z(200, 2000);
  EXPECT_GT(std::abs(z50 - z200), 3.0 * std::abs(z100 - z200)) << z50 << " " << z100 << " " << z200;
  EXPECT_LT(std::abs(z(100, 4000) - z100), 1e-5 * std::abs(z100));
}

}  // namespace
}  // namespace stockbridge::damper
