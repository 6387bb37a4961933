// Small 3D helpers shared by the FEM kernels (TetraFEM, HexaFEM, the
// tensor-mass force fields): dot and cross products, M·v, 3×3 determinant and inverse, written term by term as
// SOFA writes them: results are compared with SOFA's to
// round-off, so the order of the operations matters and must stay as it is.
// (math/finite_element.h has the same formulas for its own array-based Mat3d.)
#pragma once

#include <cmath>
#include <limits>

#include "math/types.h"

namespace sinew::fem {

// Point i of a flat array of coordinates (3 per point).
inline Vec3 at3(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }

// a·b summed in index order (Eigen's dot may pair the terms differently).
inline double dot3(const Vec3& a, const Vec3& b) {
  double r = a[0] * b[0];
  r += a[1] * b[1];
  r += a[2] * b[2];
  return r;
}

inline Vec3 cross3(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

// M·v, rows summed left to right.
inline Vec3 mul(const Mat3& M, const Vec3& v) {
  return Vec3(M(0, 0) * v[0] + M(0, 1) * v[1] + M(0, 2) * v[2], M(1, 0) * v[0] + M(1, 1) * v[1] + M(1, 2) * v[2],
              M(2, 0) * v[0] + M(2, 1) * v[1] + M(2, 2) * v[2]);
}

// Sum of the six triple products, in SOFA's order.
inline double det3(const Mat3& m) {
  return m(0, 0) * m(1, 1) * m(2, 2) + m(1, 0) * m(2, 1) * m(0, 2) + m(2, 0) * m(0, 1) * m(1, 2) -
         m(0, 0) * m(2, 1) * m(1, 2) - m(1, 0) * m(0, 1) * m(2, 2) - m(2, 0) * m(1, 1) * m(0, 2);
}

// Inverse by cofactors divided by `det` (the caller's det3(a), which it often
// needs too). Like SOFA, refuses (and leaves `inv` untouched) when
// |det| ≤ DBL_EPSILON — an absolute threshold.
inline bool invert3(const Mat3& a, double det, Mat3& inv) {
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

}  // namespace sinew::fem
