// Small nonlinear systems (src/numerics/nonlinear_system.hpp): Powell's hybrid
// method on a smooth system, and the fixed point of a bounded map past a minimum
// of |h| off the root (the span polish's hard case), and where h jumps (no root).

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "numerics/nonlinear_system.hpp"

namespace stockbridge::numerics {
namespace {

TEST(NonlinearSystem, ASmoothSystemConvergesInAFewEvaluations) {
  // x^2 + y^2 = 4, x y = 1: a root near (1.932, 0.518).
  const Residual r = [](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.resize(2);
    f << x[0] * x[0] + x[1] * x[1] - 4.0, x[0] * x[1] - 1.0;
    return true;
  };
  const ResidualJacobian j = [](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    jac.resize(2, 2);
    jac << 2.0 * x[0], 2.0 * x[1], x[1], x[0];
    return true;
  };
  NonlinearSystemOptions options;
  options.tolerance = 1e-12;
  const NonlinearSystemResult s = solve_nonlinear_system(r, j, Eigen::Vector2d(2.0, 0.3), options);
  ASSERT_EQ(s.summary.termination, Termination::converged) << brief_report(s.summary);
  EXPECT_NEAR(s.x[0] * s.x[1], 1.0, 1e-12);
  EXPECT_NEAR(s.x.squaredNorm(), 4.0, 1e-12);
  EXPECT_LE(s.summary.evaluations, 10);
  EXPECT_LE(s.summary.residual, 1e-12);
}

TEST(NonlinearSystem, AFixedPointIsFoundPastAMinimumOfTheResidualOffTheRoot) {
  // h > 0 for u < u*, < 0 beyond, but nearly flat around a local minimum of |h|
  // far from the root, where a Newton step points the wrong way.
  const auto h = [](double u) { return 0.4 * std::tanh(-3.0 * (u + 0.64)) * (u > -1.0 ? 1.0 : 0.0) +
                                       (u <= -1.0 ? 0.035 + 0.3 * (u + 2.0) * (u + 2.0) : 0.0); };
  ASSERT_GT(h(-1.0 - 1e-9), 0.0);
  const Residual r = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f = Eigen::VectorXd::Constant(1, h(x[0]));
    return true;
  };
  const ResidualJacobian j = [&](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    const double d = 1e-7;
    jac = Eigen::MatrixXd::Constant(1, 1, (h(x[0] + d) - h(x[0] - d)) / (2.0 * d));
    return true;
  };
  NonlinearSystemOptions options;
  options.tolerance = 1e-10;
  options.max_evaluations = 60;
  const NonlinearSystemResult plain = solve_nonlinear_system(r, j, Eigen::VectorXd::Constant(1, -2.3), options);
  EXPECT_NE(plain.summary.termination, Termination::converged);  // stuck at the minimum of |h| near -2
  const NonlinearSystemResult s = solve_fixed_point(r, j, Eigen::VectorXd::Constant(1, -2.3), options);
  ASSERT_EQ(s.summary.termination, Termination::converged) << brief_report(s.summary);
  EXPECT_NEAR(s.x[0], -0.64, 1e-9);
}

// Newton's steps first (newton_steps): on an exact Jacobian, from near the root, the
// residual falls quadratically, so the fixed point takes fewer residuals than the
// hybrid method's Broyden updates; where a step does not halve the residual (a
// Jacobian pointing away), the hybrid method takes over from the best point and
// still finds the root.
TEST(NonlinearSystem, NewtonStepsFirstTakeFewerResidualsAndHandOverWhereTheyStall) {
  // h(u) = F(u) - u with F(u) = (cos u_1 + u_2 / 3, sin u_1 / 2): a contraction.
  int evaluations = 0;
  const Residual r = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    ++evaluations;
    f.resize(2);
    f << std::cos(x[0]) + x[1] / 3.0 - x[0], 0.5 * std::sin(x[0]) - x[1];
    return true;
  };
  const ResidualJacobian exact = [](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    jac.resize(2, 2);
    jac << -std::sin(x[0]) - 1.0, 1.0 / 3.0, 0.5 * std::cos(x[0]), -1.0;
    return true;
  };
  NonlinearSystemOptions options;
  options.tolerance = 1e-12;
  const Eigen::Vector2d start(0.9, 0.4);
  const NonlinearSystemResult hybrid = solve_fixed_point(r, exact, start, options);
  const int hybrid_evaluations = evaluations;
  options.newton_steps = 6;
  evaluations = 0;
  const NonlinearSystemResult newton = solve_fixed_point(r, exact, start, options);
  ASSERT_EQ(hybrid.summary.termination, Termination::converged) << brief_report(hybrid.summary);
  ASSERT_EQ(newton.summary.termination, Termination::converged) << brief_report(newton.summary);
  EXPECT_LE(newton.summary.residual, 1e-12);
  EXPECT_NEAR(newton.x[0], hybrid.x[0], 1e-11);
  EXPECT_NEAR(newton.x[1], hybrid.x[1], 1e-11);
  EXPECT_EQ(newton.summary.evaluations, evaluations);
  EXPECT_LE(evaluations, 5);
  EXPECT_LT(evaluations, hybrid_evaluations);
  EXPECT_GE(newton.summary.jacobians, 1);

  // The Jacobian's sign flipped: the first Newton step moves away and the residual
  // grows, so the hybrid method (which gets the same wrong Jacobian but keeps its
  // trust region and updates it) finishes the solve, from the Newton phase's best
  // point, whose residual it is handed rather than evaluating it again (the polish's
  // residual solves every damper).
  std::vector<Eigen::VectorXd> evaluated;
  const Residual recorded = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    evaluated.push_back(x);
    return r(x, f);
  };
  const ResidualJacobian flipped = [&](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    exact(x, jac);
    jac = -jac;
    return true;
  };
  evaluations = 0;
  const NonlinearSystemResult recovered = solve_fixed_point(recorded, flipped, start, options);
  ASSERT_EQ(recovered.summary.termination, Termination::converged) << brief_report(recovered.summary);
  EXPECT_NEAR(recovered.x[0], hybrid.x[0], 1e-9);
  EXPECT_GT(recovered.summary.evaluations, 2);  // the Newton phase's two, then the hybrid method's
  EXPECT_EQ(recovered.summary.evaluations, static_cast<int>(evaluated.size()));
  for (std::size_t a = 0; a < evaluated.size(); ++a) {
    for (std::size_t b = 0; b < a; ++b) EXPECT_NE(evaluated[a], evaluated[b]) << "evaluations " << b << " and " << a;
  }
}

// Where the residual is nearly flat at the start, the Newton step is enormous (here
// 740 from u = 5 toward the root at 1 of h = tanh(1 - u)): it is not taken, as the
// span's polish once took one out to an infinite clamp velocity; the hybrid method
// starts from there with its trust radius, and nothing is evaluated far away.
TEST(NonlinearSystem, ANewtonStepBeyondTheFirstTrustRadiusIsLeftToTheHybridMethod) {
  double farthest = 0.0;
  const Residual r = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    farthest = std::max(farthest, std::abs(x[0]));
    f = Eigen::VectorXd::Constant(1, std::tanh(1.0 - x[0]));
    return true;
  };
  const ResidualJacobian j = [](const Eigen::VectorXd& x, Eigen::MatrixXd& jac) {
    const double c = std::cosh(1.0 - x[0]);
    jac = Eigen::MatrixXd::Constant(1, 1, -1.0 / (c * c));
    return true;
  };
  NonlinearSystemOptions options;
  options.tolerance = 1e-10;
  options.newton_steps = 6;
  const NonlinearSystemResult s = solve_fixed_point(r, j, Eigen::VectorXd::Constant(1, 5.0), options);
  ASSERT_EQ(s.summary.termination, Termination::converged) << brief_report(s.summary);
  EXPECT_NEAR(s.x[0], 1.0, 1e-9);
  EXPECT_LT(farthest, 10.0);
}

TEST(NonlinearSystem, AJumpOfTheResidualIsNoRootAndSaysWhere) {
  // h = 0.5 for u < 0.3, -0.5 beyond: a bracket closes on the jump, no fixed point.
  const Residual r = [](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f = Eigen::VectorXd::Constant(1, x[0] < 0.3 ? 0.5 : -0.5);
    return true;
  };
  const ResidualJacobian j = [](const Eigen::VectorXd&, Eigen::MatrixXd& jac) {
    jac = Eigen::MatrixXd::Constant(1, 1, -1.0);
    return true;
  };
  NonlinearSystemOptions options;
  options.tolerance = 1e-8;
  const NonlinearSystemResult s = solve_fixed_point(r, j, Eigen::VectorXd::Constant(1, -1.0), options);
  EXPECT_EQ(s.summary.termination, Termination::no_progress) << brief_report(s.summary);
  ASSERT_EQ(s.jump_at.size(), 1);
  EXPECT_NEAR(s.jump_at[0], 0.3, 1e-7);
  EXPECT_NE(brief_report(s.summary).find("jumps by 0.5"), std::string::npos) << brief_report(s.summary);
}

TEST(NonlinearSystem, AResidualThatCannotBeEvaluatedIsAnInnerFailure) {
  const Residual r = [](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f = Eigen::VectorXd::Constant(1, 1.0 - x[0]);
    return x[0] < 0.5;  // not defined beyond 0.5
  };
  const ResidualJacobian j = [](const Eigen::VectorXd&, Eigen::MatrixXd& jac) {
    jac = Eigen::MatrixXd::Constant(1, 1, -1.0);
    return true;
  };
  const NonlinearSystemResult s = solve_fixed_point(r, j, Eigen::VectorXd::Constant(1, 0.0), NonlinearSystemOptions{});
  EXPECT_EQ(s.summary.termination, Termination::inner_failure);
}

// A point that is not a number (a step off a singular Jacobian) is never handed to
// the residual, which may not survive it (the polish's clamp velocity exp(u)): the
// solve ends unconverged.
TEST(NonlinearSystem, APointThatIsNotANumberIsNeverEvaluated) {
  int evaluated = 0;
  const Residual r = [&evaluated](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    ++evaluated;
    f = Eigen::VectorXd::Constant(1, 1.0 - x[0]);
    return true;
  };
  const ResidualJacobian j = [](const Eigen::VectorXd&, Eigen::MatrixXd& jac) {
    jac = Eigen::MatrixXd::Constant(1, 1, -1.0);
    return true;
  };
  const Eigen::VectorXd nan = Eigen::VectorXd::Constant(1, std::nan(""));
  EXPECT_FALSE(solve_fixed_point(r, j, nan, NonlinearSystemOptions{}).summary.converged());
  EXPECT_EQ(solve_nonlinear_system(r, j, nan, NonlinearSystemOptions{}).summary.termination, Termination::inner_failure);
  EXPECT_EQ(evaluated, 0);
}

}  // namespace
}  // namespace stockbridge::numerics
