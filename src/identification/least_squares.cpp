#include "least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SVD>
#include <boost/math/distributions/chi_squared.hpp>
#include <unsupported/Eigen/LevenbergMarquardt>

namespace stockbridge::identification::least_squares {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A singular value below this fraction of the largest spans the null space.
constexpr double kNullSingularValue = 1e-9;
/// A variable whose share of a null-space direction exceeds this lies in it.
constexpr double kNullComponent = 1e-6;

/// Eigen's functor interface over a Problem.
struct Functor : Eigen::DenseFunctor<double> {
  explicit Functor(Problem& p) : Eigen::DenseFunctor<double>(p.variables(), p.residual_count()), problem(p) {}
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    r = problem.residuals(x);
    return 0;
  }
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jacobian) const {
    jacobian = problem.jacobian(x);
    return 0;
  }
  Problem& problem;
};

Termination termination_of(Eigen::LevenbergMarquardtSpace::Status status) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (status) {
    case RelativeReductionTooSmall:
    case RelativeErrorTooSmall:
    case RelativeErrorAndReductionTooSmall:
    case CosinusTooSmall: return Termination::converged;
    case TooManyFunctionEvaluation: return Termination::max_iterations;
    case FtolTooSmall:
    case XtolTooSmall:
    case GtolTooSmall: return Termination::no_progress;
    default: return Termination::inner_failure;  // improper input, user asked
  }
}

}  // namespace

Run levenberg_marquardt(Problem& problem, Eigen::VectorXd x, int max_jacobians, double first_step) {
  Functor functor(problem);
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  lm.setXtol(1e-10);
  lm.setFtol(1e-10);
  lm.setFactor(first_step);
  lm.setMaxfev(100 * (max_jacobians + 1));  // the iteration count below is what limits
  // The variables are of order one (logarithms): a trust region of unit scaling.
  // MINPACK's default, the Jacobian's column norms, lets a variable the residuals
  // hardly see (a slip moment where nothing slips) take arbitrarily long steps.
  lm.setExternalScaling(true);
  lm.diag() = Eigen::VectorXd::Ones(x.size());
  Eigen::LevenbergMarquardtSpace::Status status = lm.minimizeInit(x);
  bool exhausted = false;
  while (status == Eigen::LevenbergMarquardtSpace::NotStarted || status == Eigen::LevenbergMarquardtSpace::Running) {
    if ((exhausted = lm.njev() >= max_jacobians)) break;
    status = lm.minimizeOneStep(x);
  }
  // MINPACK keeps x at the best accepted point; fnorm() is |r| there.
  Run run{x, lm.fnorm() * lm.fnorm(), static_cast<int>(lm.njev()), {}};
  run.summary.termination = exhausted ? Termination::max_iterations : termination_of(status);
  run.summary.residual = lm.fnorm();
  run.summary.jacobians = run.jacobians;
  run.summary.evaluations = static_cast<int>(lm.nfev());
  return run;
}

double Statistics::resolution_of(const Eigen::VectorXd& g) const {
  if (null_space.cols() > 0 && (null_space.transpose() * g).cwiseAbs().maxCoeff() > kNullComponent * g.norm()) {
    return kInfinity;
  }
  return scatter * std::sqrt(g.dot(covariance * g));
}

double Statistics::standard_error_of(const Eigen::VectorXd& g) const {
  const double resolution = resolution_of(g);
  return std::isinf(resolution) ? kInfinity : resolution / scatter * error_scatter;
}

Statistics statistics(const Eigen::MatrixXd& jacobian, double sum_of_squares, double scatter, double error_floor) {
  const Eigen::Index m = jacobian.rows(), n = jacobian.cols();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::MatrixXd& v = svd.matrixV();
  Statistics out;
  out.scatter = scatter;
  out.covariance = Eigen::MatrixXd::Zero(n, n);
  std::vector<Eigen::Index> null_columns;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (s(k) > kNullSingularValue * s(0)) {
      out.covariance += v.col(k) * v.col(k).transpose() / (s(k) * s(k));
    } else {
      null_columns.push_back(k);
    }
  }
  out.null_space.resize(n, static_cast<Eigen::Index>(null_columns.size()));
  for (std::size_t k = 0; k < null_columns.size(); ++k) out.null_space.col(static_cast<Eigen::Index>(k)) = v.col(null_columns[k]);
  out.rank = static_cast<int>(n - out.null_space.cols());
  const double variance = m > out.rank ? sum_of_squares / static_cast<double>(m - out.rank) : kInfinity;
  out.residual_scatter = std::sqrt(variance);
  out.error_scatter = std::max(out.residual_scatter, error_floor);
  out.standard_error.resize(n);
  out.resolution.resize(n);
  out.sensitivity.resize(n);
  out.in_null_space.assign(static_cast<std::size_t>(n), false);
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool null = out.null_space.cols() > 0 && out.null_space.row(i).cwiseAbs().maxCoeff() > kNullComponent;
    out.in_null_space[static_cast<std::size_t>(i)] = null;
    const double c = out.covariance(i, i);
    out.standard_error(i) = null ? kInfinity : out.error_scatter * std::sqrt(c);
    out.resolution(i) = null ? kInfinity : scatter * std::sqrt(c);
    out.sensitivity(i) = jacobian.col(i).norm() / std::sqrt(static_cast<double>(m));
  }
  out.correlation.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const bool null = out.in_null_space[static_cast<std::size_t>(i)] || out.in_null_space[static_cast<std::size_t>(j)];
      out.correlation(i, j) = null ? std::numeric_limits<double>::quiet_NaN()
                                   : out.covariance(i, j) / std::sqrt(out.covariance(i, i) * out.covariance(j, j));
    }
  }
  return out;
}

ChiSquareTest chi_square_test(double statistic, int degrees_of_freedom, double level) {
  ChiSquareTest out;
  out.statistic = statistic;
  out.degrees_of_freedom = degrees_of_freedom;
  out.level = level;
  if (degrees_of_freedom <= 0 || !std::isfinite(statistic)) {
    out.p_value = degrees_of_freedom > 0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    out.critical = std::numeric_limits<double>::quiet_NaN();
    out.significant = degrees_of_freedom > 0;  // an infinite statistic
    return out;
  }
  const boost::math::chi_squared distribution(static_cast<double>(degrees_of_freedom));
  out.p_value = boost::math::cdf(boost::math::complement(distribution, std::max(statistic, 0.0)));
  out.critical = boost::math::quantile(boost::math::complement(distribution, level));
  out.significant = out.p_value < level;
  return out;
}

ExtraVariable extra_variable(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals,
                             const Eigen::VectorXd& column) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < s.size() && s(rank) > kNullSingularValue * s(0)) ++rank;
  const Eigen::MatrixXd u = svd.matrixU().leftCols(rank);
  const Eigen::VectorXd along = u.transpose() * column;  // the column in J's range, in U's basis
  const Eigen::VectorXd outside = column - u * along;
  ExtraVariable out;
  out.shift = Eigen::VectorXd::Zero(jacobian.cols());
  const double norm2 = outside.squaredNorm();
  if (!(std::sqrt(norm2) > kNullSingularValue * column.norm())) return out;  // J's columns move Z so already
  const double projection = outside.dot(residuals);
  out.reduction = projection * projection / norm2;
  out.step = -projection / norm2;
  // J^+ column = V S^-1 U^T column over the range.
  out.shift = -(svd.matrixV().leftCols(rank) * (along.array() / s.head(rank).array()).matrix()) * out.step;
  return out;
}

}  // namespace stockbridge::identification::least_squares
