// SOFA's Vec3 and Mat3 products written out, for code whose results must
// round as SOFA's do: sums from left to right, no fused multiply-add (the
// project builds with -ffp-contract=off). Eigen's products may reassociate.
#pragma once

#include <cmath>

#include "math/types.h"

namespace sinew {

inline double sofa_dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 sofa_cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double sofa_norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

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

// SOFA's 3×3 inverse: cofactors over the determinant (its term order). False, `out`
// unchanged, when |det| ≤ DBL_EPSILON or det is not finite.
inline bool sofa_invert(const Mat3& f, Mat3& out) {
  const double det = f(0, 0) * f(1, 1) * f(2, 2) + f(1, 0) * f(2, 1) * f(0, 2) + f(2, 0) * f(0, 1) * f(1, 2) -
                     f(0, 0) * f(2, 1) * f(1, 2) - f(1, 0) * f(0, 1) * f(2, 2) - f(2, 0) * f(1, 1) * f(0, 2);
  if (!(std::abs(det) > 2.220446049250313e-16) || !std::isfinite(det)) return false;
  out(0, 0) = (f(1, 1) * f(2, 2) - f(2, 1) * f(1, 2)) / det;
  out(1, 0) = (f(1, 2) * f(2, 0) - f(2, 2) * f(1, 0)) / det;
  out(2, 0) = (f(1, 0) * f(2, 1) - f(2, 0) * f(1, 1)) / det;
  out(0, 1) = (f(2, 1) * f(0, 2) - f(0, 1) * f(2, 2)) / det;
  out(1, 1) = (f(2, 2) * f(0, 0) - f(0, 2) * f(2, 0)) / det;
  out(2, 1) = (f(2, 0) * f(0, 1) - f(0, 0) * f(2, 1)) / det;
  out(0, 2) = (f(0, 1) * f(1, 2) - f(1, 1) * f(0, 2)) / det;
  out(1, 2) = (f(0, 2) * f(1, 0) - f(1, 2) * f(0, 0)) / det;
  out(2, 2) = (f(0, 0) * f(1, 1) - f(1, 0) * f(0, 1)) / det;
  return true;
}

}  // namespace sinew
