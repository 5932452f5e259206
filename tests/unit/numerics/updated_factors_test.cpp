// A matrix under rank-one changes (src/numerics/updated_factors.hpp): its solves and
// determinant's sign against those of the changed matrix factored afresh.

#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "numerics/updated_factors.hpp"

namespace stockbridge::numerics {
namespace {

Eigen::MatrixXd random_matrix(int n, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) a(i, j) = normal(rng);
  }
  return a;
}

Eigen::VectorXd random_vector(int n, std::mt19937& rng) { return random_matrix(n, rng).col(0); }

int sign_of_determinant(const Eigen::MatrixXd& a) { return a.determinant() < 0.0 ? -1 : 1; }

// Eight Broyden-like changes of a 36 x 36 matrix (harmonic balance's size at H = 17):
// after each, the solve agrees with the changed matrix's LU solve and the sign with
// its determinant's.
TEST(UpdatedFactors, SolvesAndSignsAsTheChangedMatrixFactoredAfresh) {
  std::mt19937 rng(7);
  const int n = 36;
  Eigen::MatrixXd a = random_matrix(n, rng) + 8.0 * Eigen::MatrixXd::Identity(n, n);
  UpdatedFactors factors;
  EXPECT_FALSE(factors.ready());
  factors.factor(a);
  ASSERT_TRUE(factors.ready());
  EXPECT_EQ(factors.determinant_sign(), sign_of_determinant(a));
  for (int k = 0; k < 8; ++k) {
    const Eigen::VectorXd u = 0.5 * random_vector(n, rng), v = random_vector(n, rng);
    factors.update(u, v);
    a += u * v.transpose();
    ASSERT_TRUE(factors.ready()) << k;
    EXPECT_EQ(factors.changes(), static_cast<std::size_t>(k + 1));
    const Eigen::VectorXd b = random_vector(n, rng);
    const Eigen::VectorXd expected = Eigen::PartialPivLU<Eigen::MatrixXd>(a).solve(b);
    EXPECT_LT((factors.solve(b) - expected).norm(), 1e-11 * expected.norm()) << k;
    EXPECT_EQ(factors.determinant_sign(), sign_of_determinant(a)) << k;
  }
}

// A change whose denominator 1 + v^T A^-1 u is negative flips det's sign (here
// A = I, u = -3 e0, v = e0: det goes from 1 to -2), and one that makes A singular
// leaves nothing ready, so that the caller factors again.
TEST(UpdatedFactors, AChangeFlipsTheSignOrLeavesNothingReady) {
  const int n = 4;
  UpdatedFactors factors;
  factors.factor(Eigen::MatrixXd::Identity(n, n));
  EXPECT_EQ(factors.determinant_sign(), 1);
  const Eigen::VectorXd e0 = Eigen::VectorXd::Unit(n, 0);
  factors.update(-3.0 * e0, e0);
  ASSERT_TRUE(factors.ready());
  EXPECT_EQ(factors.determinant_sign(), -1);
  EXPECT_NEAR(factors.solve(e0)(0), -0.5, 1e-15);
  // Now A = diag(-2, 1, 1, 1): adding 2 e0 e0^T makes it singular.
  factors.update(2.0 * e0, e0);
  EXPECT_FALSE(factors.ready());
  EXPECT_EQ(factors.changes(), 0u);
}

}  // namespace
}  // namespace stockbridge::numerics
