// The request layer: each method's own defaults, settings applied where the method
// uses them and rejected (by name) where it does not; non-converged points masked.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/requests/solver_settings.hpp"
#include "stockbridge/requests/sweep_request.hpp"
#include "support/error_message.hpp"

namespace stockbridge::requests {
namespace {

using damper::Method;

/// A damper of D. Sauter's arms with these names.
damper::Damper damper_named(const std::vector<std::string>& names) {
  damper::DamperDescription d;
  d.clamp_mass = 0.7;
  for (const std::string& name : names) {
    damper::ArmDescription arm;
    arm.name = name;
    arm.mass = 0.856;
    arm.inertia = 0.001814;
    arm.offset = 0.0325;
    arm.cable = cable::CableDescription::uniform(0.1875, 8, 2.8, {{20.0, 0.7}});
    d.arms.push_back(arm);
  }
  return damper::Damper(d);
}

TEST(SolverSettings, UnsetSettingsTakeTheMethodsOwnDefaults) {
  const damper::SolverOptions hb = solver_options({});
  EXPECT_EQ(hb.method, Method::harmonic_balance);
  EXPECT_EQ(hb.harmonic_balance.harmonics, 17);
  EXPECT_TRUE(hb.harmonic_balance.half_wave);
  SolverSettings collocation;
  collocation.method = "collocation";
  const damper::SolverOptions co = solver_options(collocation);
  EXPECT_EQ(co.method, Method::collocation);
  EXPECT_EQ(co.collocation.harmonics, 40);  // its 2H + 1 points are its sampling
  EXPECT_TRUE(co.collocation.collocation);
}

TEST(SolverSettings, EachSettingReachesTheChosenMethod) {
  SolverSettings s;
  s.method = "collocation";
  s.harmonics = 25;
  s.max_iterations = 70;
  s.energy_tolerance = 0.05;
  const damper::SolverOptions co = solver_options(s);
  EXPECT_EQ(co.collocation.harmonics, 25);
  EXPECT_EQ(co.collocation.max_iterations, 70);
  EXPECT_EQ(co.energy_tolerance, 0.05);
  EXPECT_EQ(co.harmonic_balance.harmonics, 17);  // the other method's options are untouched
  SolverSettings t;
  t.method = "time";
  t.steps = 64;
  t.max_periods = 50;
  const damper::SolverOptions time = solver_options(t);
  EXPECT_EQ(time.time_integration.steps_per_period, 64);
  EXPECT_EQ(time.time_integration.max_periods, 50);
}

TEST(SolverSettings, ASettingTheMethodDoesNotUseOrABadValueIsNamed) {
  SolverSettings s;
  s.steps = 64;
  EXPECT_EQ(testing::invalid_parameter_message([&] { solver_options(s); }),
            "steps = 64: not used by this method (only by time and shooting)");
  SolverSettings h;
  h.harmonics = 0;
  EXPECT_EQ(testing::invalid_parameter_message([&] { solver_options(h); }),
            "harmonics = 0: expected an integer from 1 to 100");
  SolverSettings m;
  m.method = "newton";
  EXPECT_THROW(solver_options(m), InvalidParameter);
  SolverSettings w;
  w.method = "collocation";
  w.half_wave = false;
  EXPECT_EQ(testing::invalid_parameter_message([&] { solver_options(w); }),
            "half_wave = false: not used by this method (only by hb)");
  w.method = "hb";
  EXPECT_FALSE(solver_options(w).harmonic_balance.half_wave);
}

TEST(SweepRequest, GridEndsAndAmplitudeChoice) {
  SweepRequest r;
  r.velocities = {0.2};
  r.grid = {5.0, 100.0, 7};
  const damper::SweepSpec spec = sweep_spec(r);
  ASSERT_EQ(spec.frequencies.size(), 7u);
  EXPECT_FALSE(spec.constant_displacement);
  r.displacements = {0.001};
  EXPECT_THROW(sweep_spec(r), InvalidParameter);
  r.velocities.clear();
  EXPECT_TRUE(sweep_spec(r).constant_displacement);
}

TEST(ImpedanceRow, ANonConvergedPointShowsOnlyWhereItWas) {
  damper::ImpedancePoint p;
  p.frequency_hz = 20.0;
  p.velocity_amplitude = 0.2;
  p.displacement_amplitude = 0.0016;
  p.termination = Termination::line_search_failed;
  p.impedance = {1.0, 2.0};
  p.power = 3.0;
  p.messenger_curvature_max = 0.1;  // as if computed: the mask, not the NaN, must hide them
  p.arms = {damper::ArmFigures{{1.0, 2.0}, 0.04, 0.002, 0.1}, damper::ArmFigures{{1.0, 2.0}, 0.04, 0.002, 0.1}};
  const TableValues row = impedance_table(damper_named({"long", "short"})).values(p);
  for (const TableValues::Column& c : row.columns) {
    const std::string& name = c.name;
    if (name == "frequency_hz" || name == "velocity_m_s" || name == "displacement_m" || name == "converged" ||
        name == "iterations" || name == "periods" || name == "non_unique") {
      EXPECT_TRUE(std::isfinite(c.numbers[0])) << name;
    } else {
      EXPECT_TRUE(std::isnan(c.numbers[0])) << name;
    }
  }
  EXPECT_EQ(row.column("converged").numbers[0], 0.0);
  std::vector<damper::SweepRun> runs(1);
  runs[0].points = {p};
  const SweepTally t = tally(runs);
  EXPECT_EQ(t.converged, 0);
  EXPECT_FALSE(t.max_energy_error.has_value());  // none, not 0
}

// The design figures close the row, per arm by the arms' column names; an arm's
// power that is round-off of zero against its own |Z_k| is 0, as the damper's.
TEST(ImpedanceRow, DesignFiguresFollowPerArm) {
  const Table<damper::ImpedancePoint> table = impedance_table(damper_named({"long", "short"}));
  const std::vector<std::string> columns = table.names();
  const std::vector<std::string> last(columns.end() - 5, columns.end());
  EXPECT_EQ(last, (std::vector<std::string>{"messenger_curvature_max_per_m", "long_power_w", "long_mass_amplitude_m",
                                            "short_power_w", "short_mass_amplitude_m"}));
  const std::vector<std::string> summary = point_summary_table(damper_named({"long", "short"})).names();
  EXPECT_EQ(std::vector<std::string>(summary.end() - 5, summary.end()), last);
  damper::ImpedancePoint p;
  p.frequency_hz = 20.0;
  p.velocity_amplitude = 0.2;
  p.termination = Termination::converged;
  p.impedance = {0.5, 40.0};
  p.power = 0.01;
  p.messenger_curvature_max = 0.25;
  p.arms = {damper::ArmFigures{{1e-15, 20.0}, 1e-17, 0.003, 0.25},  // sticks: 1e-17 W is round-off of 0.4 W apparent
            damper::ArmFigures{{0.5, 20.0}, 0.01, 0.002, 0.125}};
  const TableValues row = table.values(p), summary_row = point_summary_table(damper_named({"long", "short"})).values(p);
  for (std::size_t i = 0; i < 5; ++i) {
    const double expected[] = {0.25, 0.0, 0.003, 0.01, 0.002};
    EXPECT_EQ(row.columns[row.columns.size() - 5 + i].numbers[0], expected[i]) << last[i];
    EXPECT_EQ(summary_row.columns[summary_row.columns.size() - 5 + i].numbers[0], expected[i]) << last[i];
  }
}

TEST(ArmColumns, NamedByTheArmsNamesWhereTheyMakeColumnNames) {
  EXPECT_EQ(arm_column_prefixes(damper_named({"long", "short_2"})), (std::vector<std::string>{"long", "short_2"}));
  // No name, a repeated name or one with a space or a comma: numbered, all of them.
  EXPECT_EQ(arm_column_prefixes(damper_named({"long", ""})), (std::vector<std::string>{"arm1", "arm2"}));
  EXPECT_EQ(arm_column_prefixes(damper_named({"a", "a"})), (std::vector<std::string>{"arm1", "arm2"}));
  EXPECT_EQ(arm_column_prefixes(damper_named({"long arm", "b,c"})), (std::vector<std::string>{"arm1", "arm2"}));
  // A name that makes a table's own column (dissipated_power_w, shaker_force_n): numbered.
  EXPECT_EQ(arm_column_prefixes(damper_named({"dissipated", "b"})), (std::vector<std::string>{"arm1", "arm2"}));
  EXPECT_EQ(arm_column_prefixes(damper_named({"a", "shaker"})), (std::vector<std::string>{"arm1", "arm2"}));
  for (const auto& names : {std::vector<std::string>{"dissipated", "power"}, std::vector<std::string>{"messenger", "x"}}) {
    std::vector<std::string> columns = impedance_table(damper_named(names)).names();
    std::sort(columns.begin(), columns.end());
    EXPECT_EQ(std::adjacent_find(columns.begin(), columns.end()), columns.end()) << names[0];
  }
}

}  // namespace
}  // namespace stockbridge::requests
