#pragma once
// A dense matrix under rank-one changes (Broyden's updates of a Newton matrix):
// its LU factors once, the changes kept beside them.

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

namespace stockbridge::numerics {

/// Sign of det(A) from A's LU factors with partial pivoting.
inline int determinant_sign(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
  double sign = lu.permutationP().determinant();
  for (Eigen::Index i = 0; i < lu.matrixLU().rows(); ++i) sign *= lu.matrixLU()(i, i) < 0.0 ? -1.0 : 1.0;
  return sign < 0.0 ? -1 : 1;
}

/// A = A0 + u1 v1^T + ... + uk vk^T as A0's LU factors and the rank-one changes
/// (Sherman-Morrison in product form). After a change a solve costs one solve with
/// the factors and two dot products a change, where factoring A again costs
/// (2/3) n^3; det(A)'s sign follows from the changes' denominators.
class UpdatedFactors {
 public:
  /// Whether a matrix is factored (none yet, after clear(), or after a singular change: no).
  bool ready() const { return ready_; }
  void clear() {
    ready_ = false;
    changes_.clear();
  }
  /// A = A0 = `matrix`, factored, no changes.
  void factor(const Eigen::MatrixXd& matrix) {
    lu_.compute(matrix);
    changes_.clear();
    sign_ = numerics::determinant_sign(lu_);
    ready_ = true;
  }
  /// A0's estimated reciprocal condition number (1-norm; about half a factorisation's cost).
  double reciprocal_condition() const { return lu_.rcond(); }
  /// A^-1 b (not finite where A0 is singular). Only where ready().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x = lu_.solve(b);
    for (const Change& c : changes_) x -= c.w * (c.v.dot(x) / c.sigma);
    return x;
  }
  /// A += u v^T. With w = A^-1 u and sigma = 1 + v^T w: (A + u v^T)^-1 b = y - w (v^T y) /
  /// sigma for y = A^-1 b, and det(A + u v^T) = det(A) sigma. A change that leaves A
  /// singular (sigma 0 or not finite) leaves nothing ready. Only where ready().
  void update(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
    Eigen::VectorXd w = solve(u);
    const double sigma = 1.0 + v.dot(w);
    if (!(std::isfinite(sigma) && sigma != 0.0)) {
      clear();
      return;
    }
    if (sigma < 0.0) sign_ = -sign_;
    changes_.push_back({std::move(w), v, sigma});
  }
  /// Sign of det(A). Only where ready().
  int determinant_sign() const { return sign_; }
  /// Rank-one changes since the factorisation.
  std::size_t changes() const { return changes_.size(); }

 private:
  struct Change {
    Eigen::VectorXd w, v;
    double sigma;
  };
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  std::vector<Change> changes_;
  int sign_ = 1;
  bool ready_ = false;
};

}  // namespace stockbridge::numerics
