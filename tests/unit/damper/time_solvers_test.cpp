// Time integration and shooting for one arm: the closed-form linear steady state,
// second-order convergence in the time step, agreement of the two methods,
// the energy balance, and non-convergence reported rather than thrown.

#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/damper/shooting.hpp"
#include "stockbridge/damper/time_integration.hpp"
#include "support/damper_fixtures.hpp"

namespace stockbridge::damper {
namespace {

/// The verification damper's arm (MODEL.md section 4).
ArmDescription damper_arm() {
  ArmDescription a;
  a.name = "arm";
  a.mass = 0.856;
  a.inertia = 0.001814;
  a.offset = 0.0325;
  a.cable = cable::CableDescription::uniform(0.1875, 40, 2.8, {{20.0, 0.7}});
  return a;
}

/// The same arm with an elastic cable at the all-stick stiffness (no Jenkin elements).
ArmDescription elastic_arm() {
  ArmDescription a = damper_arm();
  a.cable = cable::CableDescription::uniform(0.1875, 40, 22.8, {});
  return a;
}

std::complex<double> impedance(const ArmSolution& solution, const Excitation& excitation) {
  return arm_force_first_harmonic(solution.period) / excitation.velocity_amplitude();
}

/// First harmonic of -F(t) for the linear arm of bending stiffness `ei`, from
/// (K - W^2 M) U = -W^2 X L with the classical beam tip stiffness K and M, L from the
/// arm's m, Theta, b (MODEL.md section 4; nothing from damper::Arm):
/// u = U sin(W t), F = (K U)_0 sin(W t), whose first harmonic (2/T) int F e^{-i W t} is -i (K U)_0.
/// With `steps_per_period` = N > 0, the trapezoidal rule's own steady state instead:
/// W^2 M replaced by W_h^2 M, W_h = (2/h) tan(W h / 2), h = T / N.
std::complex<double> linear_arm_force(const ArmDescription& a, double ei, const Excitation& excitation,
                                      int steps_per_period = 0) {
  const double w = excitation.angular_frequency();
  const double h = excitation.period() / steps_per_period;
  const double w_inertia = steps_per_period > 0 ? 2.0 / h * std::tan(0.5 * w * h) : w;
  const Eigen::Matrix2d k = testing::beam_tip_stiffness(ei, a.cable.length);
  const Eigen::Vector2d u = (k - w_inertia * w_inertia * testing::arm_mass_matrix(a))
                                .partialPivLu()
                                .solve(-w * w * excitation.displacement_amplitude * testing::arm_load_vector(a));
  const double f = (k * u)(0);
  return std::complex<double>(0.0, f);  // -(-i f)
}

/// The energy error from its definition (SolverSummary::energy_error), computed here
/// in the time domain rather than by the library's energy_error(): the mean input
/// power (1/T) int -F(t) v(t) dt over the samples, v = V cos(W t), against the
/// sliders' dissipation per period D / T, relative to the apparent power V |F1| / 2.
double direct_energy_error(const ArmPeriod& period, const Excitation& excitation) {
  const double v = excitation.velocity_amplitude();
  const Eigen::Index n = period.loads.cols();
  double power = 0.0, cosine = 0.0, sine = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n);
    const double force = -period.loads(0, j);  // the arm's share of the shaker force
    power += force * v * std::cos(angle) / static_cast<double>(n);
    cosine += force * std::cos(angle);
    sine += force * std::sin(angle);
  }
  const double apparent = 0.5 * v * 2.0 * std::hypot(cosine, sine) / static_cast<double>(n);
  return std::abs(power - period.dissipated / excitation.period()) / apparent;
}

// (a) Elastic arm away from resonance: the first harmonic of -F(t) is the
// closed-form linear steady state, for both solvers (the scheme's error is
// O((W h)^2) times the dynamic amplification: 2e-5 at 30 Hz with N = 1024), and
// to round-off the steady state of the discrete scheme.
TEST(TimeIntegration, ElasticArmMatchesClosedFormSteadyState) {
  const Arm arm(elastic_arm());
  const Eigen::Vector2d natural = arm.natural_frequencies(22.8);
  ASSERT_NEAR(natural(0), 21.2, 0.2);
  ASSERT_NEAR(natural(1), 68.2, 0.3);
  const int steps = 1024;
  TimeIntegrationOptions ti_options;
  ti_options.steps_per_period = steps;
  TimeIntegration time_integration(arm, ti_options);
  ShootingOptions sh_options;
  sh_options.steps_per_period = steps;
  Shooting shooting(arm, sh_options);
  for (const double frequency : {8.0, 30.0, 100.0}) {
    SCOPED_TRACE(frequency);
    const Excitation excitation = Excitation::from_velocity(frequency, 0.2);
    const std::complex<double> expected = linear_arm_force(elastic_arm(), 22.8, excitation);
    const std::complex<double> discrete = linear_arm_force(elastic_arm(), 22.8, excitation, steps);
    const ArmSolution ti = time_integration.solve(excitation);
    ASSERT_TRUE(ti.summary.converged()) << brief_report(ti.summary);
    // The start is the discrete scheme's own linear steady state: periodic at once.
    EXPECT_EQ(ti.summary.periods, 2);
    EXPECT_LT(std::abs(arm_force_first_harmonic(ti.period) - expected), 1e-4 * std::abs(expected));
    EXPECT_LT(std::abs(arm_force_first_harmonic(ti.period) - discrete), 1e-9 * std::abs(expected));
    EXPECT_LT(std::abs(ti.period.dissipated), 1e-12);
    const ArmSolution sh = shooting.solve(excitation);
    ASSERT_TRUE(sh.summary.converged()) << brief_report(sh.summary);
    EXPECT_LT(std::abs(arm_force_first_harmonic(sh.period) - expected), 1e-4 * std::abs(expected));
    EXPECT_LT(std::abs(arm_force_first_harmonic(sh.period) - discrete), 1e-8 * std::abs(expected));
  }
}

// Shooting from a start that is not periodic converges to the same linear state.
TEST(Shooting, ElasticArmFromRestConverges) {
  const Arm arm(elastic_arm());
  ShootingOptions options;
  options.steps_per_period = 1024;
  Shooting shooting(arm, options);
  const Excitation excitation = Excitation::from_velocity(30.0, 0.2);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(4);
  const ArmSolution solution = shooting.solve(excitation, &rest);
  ASSERT_TRUE(solution.summary.converged()) << brief_report(solution.summary);
  EXPECT_GE(solution.summary.newton_iterations, 1);
  const std::complex<double> expected = linear_arm_force(elastic_arm(), 22.8, excitation);
  EXPECT_LT(std::abs(arm_force_first_harmonic(solution.period) - expected), 1e-4 * std::abs(expected));
}

// The recorded period is aligned with the excitation phase and starts at `unknowns`.
TEST(TimeIntegration, PeriodStartsAtTheReturnedState) {
  const Arm arm(damper_arm());
  TimeIntegration solver(arm, {});
  const ArmSolution solution = solver.solve(Excitation::from_velocity(15.0, 0.2));
  ASSERT_TRUE(solution.summary.converged()) << brief_report(solution.summary);
  ASSERT_EQ(solution.unknowns.size(), 4);
  ASSERT_EQ(solution.period.kinematics.cols(), 256);
  ASSERT_EQ(solution.period.clamp_moment.size(), 256u);
  EXPECT_EQ(solution.period.kinematics(0, 0), solution.unknowns(0));
  EXPECT_EQ(solution.period.kinematics(1, 0), solution.unknowns(1));
  EXPECT_GT(solution.period.dissipated, 0.0);
  EXPECT_LE(solution.summary.residual, 1e-8);
}

// (b) Second order in the time step on a slipping case: the observed order,
// fitted over N = 128 .. 2048 against N = 8192, is about 2 (a ratio of about 4 per
// doubling). Slip and reversal points fall anywhere within a step, so single
// ratios scatter (1.7 to 7.5 here); the fit over five values does not.
TEST(TimeIntegration, SecondOrderInTheTimeStep) {
  const Arm arm(damper_arm());
  const Excitation excitation = Excitation::from_velocity(15.0, 0.2);
  auto solve = [&](int steps) {
    TimeIntegrationOptions options;
    options.steps_per_period = steps;
    TimeIntegration solver(arm, options);
    const ArmSolution solution = solver.solve(excitation);
    EXPECT_TRUE(solution.summary.converged()) << steps << ": " << brief_report(solution.summary);
    return impedance(solution, excitation);
  };
  const std::complex<double> reference = solve(8192);
  ASSERT_GT(reference.real(), 10.0);  // slipping: clearly dissipative
  std::vector<double> log_n, log_error;
  for (int steps = 128; steps <= 2048; steps *= 2) {
    const double error = std::abs(solve(steps) - reference) / std::abs(reference);
    log_n.push_back(std::log2(steps));
    log_error.push_back(std::log2(error));
  }
  double mean_n = 0.0, mean_e = 0.0;
  for (std::size_t i = 0; i < log_n.size(); ++i) {
    mean_n += log_n[i] / log_n.size();
    mean_e += log_error[i] / log_n.size();
  }
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < log_n.size(); ++i) {
    sxy += (log_n[i] - mean_n) * (log_error[i] - mean_e);
    sxx += (log_n[i] - mean_n) * (log_n[i] - mean_n);
  }
  const double order = -sxy / sxx;
  EXPECT_GT(order, 1.6);
  EXPECT_LT(order, 2.6);
  EXPECT_LT(std::exp2(log_error.back()), 1e-4);           // N = 2048
  EXPECT_LT(log_error.back(), log_error.front() - 6.0);    // 4 doublings: at least 2^6 smaller
}

// (c) Shooting and time integration solve the same discrete equations, so they
// agree on the impedance far better than the required 1e-3.
TEST(Shooting, AgreesWithTimeIntegrationWhenSlipping) {
  const Arm arm(damper_arm());
  TimeIntegration time_integration(arm, {});
  Shooting shooting(arm, {});
  for (const double frequency : {15.0, 25.0}) {
    SCOPED_TRACE(frequency);
    const Excitation excitation = Excitation::from_velocity(frequency, 0.2);
    const ArmSolution ti = time_integration.solve(excitation);
    const ArmSolution sh = shooting.solve(excitation);
    ASSERT_TRUE(ti.summary.converged()) << brief_report(ti.summary);
    ASSERT_TRUE(sh.summary.converged()) << brief_report(sh.summary);
    EXPECT_LE(sh.summary.residual, 1e-9);
    EXPECT_LE(sh.summary.periodicity_defect, 1e-7);
    const std::complex<double> z_ti = impedance(ti, excitation), z_sh = impedance(sh, excitation);
    EXPECT_GT(z_ti.real(), 10.0);  // slipping
    EXPECT_NEAR(z_sh.real(), z_ti.real(), 1e-3 * std::abs(z_ti.real()));
    EXPECT_NEAR(z_sh.imag(), z_ti.imag(), 1e-3 * std::abs(z_ti.imag()));
    EXPECT_LT(std::abs(z_sh - z_ti), 1e-6 * std::abs(z_ti));
    EXPECT_NEAR(sh.period.dissipated, ti.period.dissipated, 1e-6 * ti.period.dissipated);
  }
}

// Model apart from state: a solve depends on its arguments only. The same point
// solved on a stepper that ran other points before, and on a fresh one, agrees to
// the last bit, for both methods; a stepper failure is reported by its summary.
TEST(TimeSolvers, ASolveOnAReusedStepperEqualsOneOnAFreshStepper) {
  const Arm arm(damper_arm());
  const TimeIntegration time_integration(arm, {});
  ShootingOptions shooting_options;
  shooting_options.steps_per_period = 64;
  const Shooting shooting(arm, shooting_options);
  const Excitation target = Excitation::from_velocity(15.0, 0.2);
  NewmarkStepper reused_ti = time_integration.stepper();
  NewmarkStepper reused_sh = shooting.stepper();
  for (const double frequency : {25.0, 8.0}) {  // other points first: their cable and mechanical state left behind
    (void)time_integration.solve(Excitation::from_velocity(frequency, 0.2), nullptr, reused_ti);
    (void)shooting.solve(Excitation::from_velocity(frequency, 0.2), nullptr, reused_sh);
  }
  const ArmSolution ti_reused = time_integration.solve(target, nullptr, reused_ti);
  const ArmSolution ti_fresh = time_integration.solve(target);
  const ArmSolution sh_reused = shooting.solve(target, nullptr, reused_sh);
  const ArmSolution sh_fresh = shooting.solve(target);
  ASSERT_TRUE(ti_fresh.summary.converged()) << brief_report(ti_fresh.summary);
  ASSERT_TRUE(sh_fresh.summary.converged()) << brief_report(sh_fresh.summary);
  EXPECT_EQ(ti_reused.period.loads, ti_fresh.period.loads);
  EXPECT_EQ(ti_reused.summary.periods, ti_fresh.summary.periods);
  EXPECT_EQ(sh_reused.period.loads, sh_fresh.period.loads);
  EXPECT_EQ(sh_reused.unknowns, sh_fresh.unknowns);
  EXPECT_EQ(sh_reused.summary.newton_iterations, sh_fresh.summary.newton_iterations);
}

TEST(TimeSolvers, AStepperReportsAFailedStepByItsSummary) {
  const Arm arm(damper_arm());
  TimeIntegrationOptions options;
  options.max_newton = 1;  // too few for a slipping step
  const TimeIntegration time_integration(arm, options);
  NewmarkStepper stepper = time_integration.stepper();
  const Excitation excitation = Excitation::from_velocity(15.0, 0.2);
  stepper.set_excitation(excitation);
  const SolverSummary placed = stepper.place(linear_discrete_start(arm, excitation, options.steps_per_period));
  ASSERT_TRUE(placed.converged()) << brief_report(placed);
  SolverSummary period;
  for (int k = 0; k < 20 && period.termination != Termination::max_iterations; ++k) period = stepper.advance_period();
  EXPECT_EQ(period.termination, Termination::max_iterations) << brief_report(period);
  EXPECT_EQ(period.newton_iterations, 1);
  EXPECT_NE(period.where.find("in the time step to t ="), std::string::npos) << period.where;
}

// (d) Energy: the input power from the first harmonic equals the sliders'
// dissipation per period up to the time-discretisation error, which falls with N.
TEST(TimeIntegration, EnergyBalanceImprovesWithSteps) {
  const Arm arm(damper_arm());
  const Excitation excitation = Excitation::from_velocity(15.0, 0.2);
  double previous = 1.0;
  for (const int steps : {256, 512, 1024}) {
    SCOPED_TRACE(steps);
    TimeIntegrationOptions options;
    options.steps_per_period = steps;
    TimeIntegration solver(arm, options);
    const ArmSolution solution = solver.solve(excitation);
    ASSERT_TRUE(solution.summary.converged()) << brief_report(solution.summary);
    EXPECT_LT(solution.summary.energy_error, 1e-3);
    EXPECT_LT(solution.summary.energy_error, previous);
    EXPECT_NEAR(solution.summary.energy_error, direct_energy_error(solution.period, excitation), 1e-12);
    previous = solution.summary.energy_error;
  }
}

TEST(Shooting, EnergyBalance) {
  const Arm arm(damper_arm());
  const Excitation excitation = Excitation::from_velocity(15.0, 0.2);
  Shooting solver(arm, {});
  const ArmSolution solution = solver.solve(excitation);
  ASSERT_TRUE(solution.summary.converged()) << brief_report(solution.summary);
  EXPECT_LT(solution.summary.energy_error, 1e-3);
}

// (e) Non-convergence is a result, not an exception.
TEST(TimeIntegration, TooFewPeriodsIsReported) {
  const Arm arm(damper_arm());
  TimeIntegrationOptions options;
  options.max_periods = 2;
  TimeIntegration solver(arm, options);
  ArmSolution solution;
  ASSERT_NO_THROW(solution = solver.solve(Excitation::from_velocity(15.0, 0.2)));
  EXPECT_FALSE(solution.summary.converged());
  EXPECT_EQ(solution.summary.newton_iterations, 0);  // time integration takes no Newton steps at this level
  EXPECT_GT(solution.summary.residual, 1e-3);  // the slipping start is far from periodic
  EXPECT_EQ(solution.summary.termination, Termination::not_periodic) << brief_report(solution.summary);
  EXPECT_EQ(solution.summary.periods, 2);
    EXPECT_EQ(solution.period.kinematics.cols(), 256);  // the last period is still there to inspect
}

TEST(Shooting, TooFewIterationsIsReported) {
  const Arm arm(damper_arm());
  ShootingOptions options;
  options.max_iterations = 1;
  Shooting solver(arm, options);
  ArmSolution solution;
  ASSERT_NO_THROW(solution = solver.solve(Excitation::from_velocity(15.0, 0.2)));
  EXPECT_FALSE(solution.summary.converged());
  EXPECT_EQ(solution.summary.termination, Termination::max_iterations) << brief_report(solution.summary);
}

TEST(Shooting, UnsettledMemoryIsReported) {
  const Arm arm(damper_arm());
  ShootingOptions options;
  options.max_pre_periods = 2;  // the memory needs about 30 periods at 15 Hz
  Shooting solver(arm, options);
  const ArmSolution solution = solver.solve(Excitation::from_velocity(15.0, 0.2));
  EXPECT_FALSE(solution.summary.converged());
  EXPECT_EQ(solution.summary.termination, Termination::not_periodic) << brief_report(solution.summary);
}

// At a resonance of the time-discrete system (the elastic arm's first natural
// frequency seen through the trapezoidal rule, W_h = W_n) no periodic response
// exists: shooting reports a singular Jacobian and time integration, whose
// amplitude grows every period, never finds periodicity. Neither returns a number.
TEST(TimeSolvers, DiscreteResonanceHasNoPeriodicResponse) {
  const Arm arm(elastic_arm());
  const int n = 256;
  const double f = arm.natural_frequencies(22.8)(0) * std::numbers::pi / (n * std::tan(std::numbers::pi / n));
  const Excitation excitation = Excitation::from_velocity(f, 0.2);
  ShootingOptions shooting;
  shooting.steps_per_period = n;
  const ArmSolution shot = Shooting(arm, shooting).solve(excitation);
  EXPECT_FALSE(shot.summary.converged());
  EXPECT_EQ(shot.summary.termination, Termination::singular_jacobian) << brief_report(shot.summary);
  TimeIntegrationOptions marching;
  marching.steps_per_period = n;
  marching.max_periods = 200;
  const ArmSolution marched = TimeIntegration(arm, marching).solve(excitation);
  EXPECT_FALSE(marched.summary.converged());
  EXPECT_EQ(marched.summary.termination, Termination::not_periodic) << brief_report(marched.summary);
  EXPECT_EQ(marched.summary.periods, 200);
}

template <class Options, class Solver>
void expect_invalid(Options options, const std::string& field) {
  const Arm arm(damper_arm());
  try {
    Solver solver(arm, options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const InvalidParameter& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(TimeIntegration, BadOptionsThrowNamingTheField) {
  TimeIntegrationOptions o;
  EXPECT_NO_THROW(o.validate());
  o.steps_per_period = 4;
  expect_invalid<TimeIntegrationOptions, TimeIntegration>(o, "steps_per_period");
  o = {};
  o.max_periods = 1;
  expect_invalid<TimeIntegrationOptions, TimeIntegration>(o, "max_periods");
  o = {};
  o.periodicity_tolerance = -1e-8;
  expect_invalid<TimeIntegrationOptions, TimeIntegration>(o, "periodicity_tolerance");
  o = {};
  o.max_newton = 0;
  expect_invalid<TimeIntegrationOptions, TimeIntegration>(o, "max_newton");
  o = {};
  o.newton_tolerance = std::nan("");
  expect_invalid<TimeIntegrationOptions, TimeIntegration>(o, "newton_tolerance");
  o = {};
  o.cantilever.tolerance = 0.0;
  expect_invalid<TimeIntegrationOptions, TimeIntegration>(o, "cantilever.tolerance");

  const Arm arm(damper_arm());
  TimeIntegration solver(arm, {});
  const Eigen::VectorXd three = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(solver.solve(Excitation::from_velocity(15.0, 0.2), &three), InvalidParameter);
  EXPECT_THROW(solver.solve(Excitation{15.0, -1.0}), InvalidParameter);
}

TEST(Shooting, BadOptionsThrowNamingTheField) {
  ShootingOptions o;
  EXPECT_NO_THROW(o.validate());
  o.steps_per_period = 2;
  expect_invalid<ShootingOptions, Shooting>(o, "steps_per_period");
  o = {};
  o.pre_periods = 0;
  expect_invalid<ShootingOptions, Shooting>(o, "pre_periods");
  o = {};
  o.max_pre_periods = 1;  // below pre_periods = 2
  expect_invalid<ShootingOptions, Shooting>(o, "max_pre_periods");
  o = {};
  o.max_iterations = 0;
  expect_invalid<ShootingOptions, Shooting>(o, "max_iterations");
  o = {};
  o.tolerance = 0.0;
  expect_invalid<ShootingOptions, Shooting>(o, "tolerance");
  o = {};
  o.finite_difference_step = -1e-6;
  expect_invalid<ShootingOptions, Shooting>(o, "finite_difference_step");
  o = {};
  o.cantilever.max_iterations = 0;
  expect_invalid<ShootingOptions, Shooting>(o, "cantilever.max_iterations");

  const Arm arm(damper_arm());
  Shooting solver(arm, {});
  const Eigen::VectorXd five = Eigen::VectorXd::Zero(5);
  EXPECT_THROW(solver.solve(Excitation::from_velocity(15.0, 0.2), &five), InvalidParameter);
}

}  // namespace
}  // namespace stockbridge::damper
