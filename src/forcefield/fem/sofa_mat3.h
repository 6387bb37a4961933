// Small 3D helpers shared by the FEM kernels (TetraFEM, HexaFEM, the
// tensor-mass force fields): dot and cross products, M·v, 3×3 determinant and
// inverse, as math/sofa_vec.h writes them term by term in SOFA's order.
// (math/finite_element.h has the same formulas for its own array-based Mat3d.)
#pragma once

#include "math/sofa_vec.h"

namespace sinew::fem {

// Point i of a flat array of coordinates (3 per point).
inline Vec3 at3(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }

// The FEM kernels' names for math/sofa_vec.h's SOFA-order products.
inline double dot3(const Vec3& a, const Vec3& b) { return sofa_dot(a, b); }
inline Vec3 cross3(const Vec3& a, const Vec3& b) { return sofa_cross(a, b); }
inline Vec3 mul(const Mat3& M, const Vec3& v) { return sofa_mul(M, v); }
inline double det3(const Mat3& m) { return sofa_det(m); }
inline bool invert3(const Mat3& a, double det, Mat3& inv) { return sofa_invert(a, det, inv); }

}  // namespace sinew::fem
