// SOFA's Vec3 and Mat3 products written out, for code whose results must
// round as SOFA's do: sums from left to right, no fused multiply-add (the
// project builds with -ffp-contract=off). Eigen's products may reassociate.
#pragma once

#include <cmath>
#include <limits>

#include "math/types.h"

namespace sinew {

inline double sofa_dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 sofa_cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// The same on raw arrays (out must not alias a or b).
inline void sofa_cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
inline double sofa_norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
// SOFA's Vec::normalize: divided by its norm unless that is ≤ DBL_EPSILON (then unchanged).
inline void sofa_normalize(Vec3& v) {
  const double n = sofa_norm(v);
  if (n > std::numeric_limits<double>::epsilon())
    for (int i = 0; i < 3; ++i) v[i] /= n;
}

// M·v, each row summed left to right (SOFA's Mat * Vec).
inline Vec3 sofa_mul(const Mat3& m, const Vec3& v) {
  return {m(0, 0) * v[0] + m(0, 1) * v[1] + m(0, 2) * v[2], m(1, 0) * v[0] + m(1, 1) * v[1] + m(1, 2) * v[2],
          m(2, 0) * v[0] + m(2, 1) * v[1] + m(2, 2) * v[2]};
}

// A·B, each entry summed left to right (SOFA's Mat * Mat).
inline Mat3 sofa_mul(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
  return r;
}

// Sum of the six triple products, in SOFA's order.
inline double sofa_det(const Mat3& m) {
  return m(0, 0) * m(1, 1) * m(2, 2) + m(1, 0) * m(2, 1) * m(0, 2) + m(2, 0) * m(0, 1) * m(1, 2) -
         m(0, 0) * m(2, 1) * m(1, 2) - m(1, 0) * m(0, 1) * m(2, 2) - m(2, 0) * m(1, 1) * m(0, 2);
}

// Inverse by cofactors divided by `det` (the caller's sofa_det(a), which it often needs too).
// Like SOFA, refuses (and leaves `inv` untouched) when |det| ≤ DBL_EPSILON, an absolute
// threshold.
inline bool sofa_invert(const Mat3& a, double det, Mat3& inv) {
  if (std::fabs(det) <= std::numeric_limits<double>::epsilon()) return false;
  inv(0, 0) = (a(1, 1) * a(2, 2) - a(2, 1) * a(1, 2)) / det;
  inv(1, 0) = (a(1, 2) * a(2, 0) - a(2, 2) * a(1, 0)) / det;
  inv(2, 0) = (a(1, 0) * a(2, 1) - a(2, 0) * a(1, 1)) / det;
  inv(0, 1) = (a(2, 1) * a(0, 2) - a(0, 1) * a(2, 2)) / det;
  inv(1, 1) = (a(2, 2) * a(0, 0) - a(0, 2) * a(2, 0)) / det;
  inv(2, 1) = (a(2, 0) * a(0, 1) - a(0, 0) * a(2, 1)) / det;
  inv(0, 2) = (a(0, 1) * a(1, 2) - a(1, 1) * a(0, 2)) / det;
  inv(1, 2) = (a(0, 2) * a(1, 0) - a(1, 2) * a(0, 0)) / det;
  inv(2, 2) = (a(0, 0) * a(1, 1) - a(1, 0) * a(0, 1)) / det;
  return true;
}

}  // namespace sinew
