// SOFA's Vec3 products written out, for code whose results must round as
// SOFA's do: sums from left to right, no fused multiply-add (the project
// builds with -ffp-contract=off). Eigen's dot may reassociate.
#pragma once

#include <cmath>

#include "math/types.h"

namespace sinew {

inline double sofa_dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 sofa_cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double sofa_norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

}  // namespace sinew
