#pragma once
// The cubic Hermite beam element of the span in time (degrees of freedom w1, theta1,
// w2, theta2; length h): its matrices, shape functions and the gathering of one
// element's values, shared by the beam model (beam_in_time.cpp) and the loads the
// span's run builds on it (conductor_in_time.cpp).

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stockbridge/span/conductor_in_time.hpp"

namespace stockbridge::span::hermite {

using Matrix4 = Eigen::Matrix4d;

/// The Hermite element's matrices (degrees of freedom w1, theta1, w2, theta2), length h.
inline Matrix4 unit_mass(double h) {  // ∫ N^T N dx
  Matrix4 m;
  m << 156, 22 * h, 54, -13 * h,  //
      22 * h, 4 * h * h, 13 * h, -3 * h * h,  //
      54, 13 * h, 156, -22 * h,  //
      -13 * h, -3 * h * h, -22 * h, 4 * h * h;
  return m * (h / 420.0);
}
inline Matrix4 bending(double h) {  // ∫ N''^T N'' dx
  Matrix4 k;
  k << 12, 6 * h, -12, 6 * h,  //
      6 * h, 4 * h * h, -6 * h, 2 * h * h,  //
      -12, -6 * h, 12, -6 * h,  //
      6 * h, 2 * h * h, -6 * h, 4 * h * h;
  return k / (h * h * h);
}
inline Matrix4 geometric(double h) {  // ∫ N'^T N' dx
  Matrix4 g;
  g << 36, 3 * h, -36, 3 * h,  //
      3 * h, 4 * h * h, -3 * h, -h * h,  //
      -36, -3 * h, 36, -3 * h,  //
      3 * h, -h * h, -3 * h, 4 * h * h;
  return g / (30.0 * h);
}

/// The free indices of element e's four degrees of freedom (-1 where held).
inline std::array<Eigen::Index, 4> element_dofs(const BeamModel& model, int e) {
  return {model.index(e, 0), model.index(e, 1), model.index(e + 1, 0), model.index(e + 1, 1)};
}

inline void add_element(std::vector<Eigen::Triplet<double>>& triplets, const std::array<Eigen::Index, 4>& dofs,
                        const Matrix4& matrix) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (dofs[r] >= 0 && dofs[c] >= 0) triplets.emplace_back(dofs[r], dofs[c], matrix(r, c));
    }
  }
}

/// The element's shape functions N(s) and their slopes N'(s) at s = (x - x_e) / h in [0, 1].
inline Eigen::Vector4d shape(double s, double h) {
  return {1 - 3 * s * s + 2 * s * s * s, h * (s - 2 * s * s + s * s * s), 3 * s * s - 2 * s * s * s, h * (s * s * s - s * s)};
}
inline Eigen::Vector4d shape_slope(double s, double h) {
  return {(-6 * s + 6 * s * s) / h, 1 - 4 * s + 3 * s * s, (6 * s - 6 * s * s) / h, 3 * s * s - 2 * s};
}

/// Element e's four values of the free vector u (0 where held).
template <class Scalar>
inline Eigen::Matrix<Scalar, 4, 1> gather(const BeamModel& model, int e,
                                          const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& u) {
  const std::array<Eigen::Index, 4> dofs = element_dofs(model, e);
  Eigen::Matrix<Scalar, 4, 1> q;
  for (int i = 0; i < 4; ++i) q(i) = dofs[i] >= 0 ? u(dofs[i]) : Scalar(0);
  return q;
}

}  // namespace stockbridge::span::hermite
