// Quaternion arithmetic with SOFA's formulas and evaluation order
// (sofa::type::Quat): Euler angles → quaternion (default ZYX order, i.e.
// R = Rz·Ry·Rx), rotation matrix, rotate, product, inverse, slerp2. Used by
// the mesh loaders' transforms, TransformEngine and LinearMovementProjective-
// Constraint, where results must match SOFA to round-off. Storage (x, y, z, w), scalar last.
#pragma once

#include <array>
#include <cmath>

#include "math/types.h"

namespace sinew::io {

// a × b with SOFA's component formula.
inline Vec3 cross3(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

struct SQuat {
  std::array<double, 4> q{0, 0, 0, 1};

  static SQuat from_euler(const Vec3& v) {  // radians, SOFA's default EulerOrder::ZYX
    const double c1 = std::cos(v[0] / 2), c2 = std::cos(v[1] / 2), c3 = std::cos(v[2] / 2);
    const double s1 = std::sin(v[0] / 2), s2 = std::sin(v[1] / 2), s3 = std::sin(v[2] / 2);
    SQuat r;
    r.q[0] = s1 * c2 * c3 - c1 * s2 * s3;
    r.q[1] = c1 * s2 * c3 + s1 * c2 * s3;
    r.q[2] = c1 * c2 * s3 - s1 * s2 * c3;
    r.q[3] = c1 * c2 * c3 + s1 * s2 * s3;
    return r;
  }

  // Row-major 3×3 rotation matrix.
  std::array<double, 9> matrix() const {
    return {1 - 2 * (q[1] * q[1] + q[2] * q[2]), 2 * (q[0] * q[1] - q[2] * q[3]), 2 * (q[2] * q[0] + q[1] * q[3]),
            2 * (q[0] * q[1] + q[2] * q[3]),     1 - 2 * (q[2] * q[2] + q[0] * q[0]), 2 * (q[1] * q[2] - q[0] * q[3]),
            2 * (q[2] * q[0] - q[1] * q[3]),     2 * (q[1] * q[2] + q[0] * q[3]),  1 - 2 * (q[1] * q[1] + q[0] * q[0])};
  }

  // v + w·t + q×t with t = 2·(q×v)
  Vec3 rotate(const Vec3& v) const {
    const Vec3 u(q[0], q[1], q[2]);
    const Vec3 t = cross3(u, v) * 2;
    return v + q[3] * t + cross3(u, t);
  }

  SQuat operator*(const SQuat& b) const {
    SQuat r;
    r.q[3] = q[3] * b.q[3] - (q[0] * b.q[0] + q[1] * b.q[1] + q[2] * b.q[2]);
    r.q[0] = q[3] * b.q[0] + q[0] * b.q[3] + q[1] * b.q[2] - q[2] * b.q[1];
    r.q[1] = q[3] * b.q[1] + q[1] * b.q[3] + q[2] * b.q[0] - q[0] * b.q[2];
    r.q[2] = q[3] * b.q[2] + q[2] * b.q[3] + q[0] * b.q[1] - q[1] * b.q[0];
    return r;
  }

  SQuat inverse() const {
    SQuat r;
    double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (norm != 0.0) {
      norm = 1.0 / norm;
      r.q[3] = q[3] * norm;
      for (int i = 0; i < 3; ++i) r.q[i] = -q[i] * norm;
    } else {
      r.q = {0, 0, 0, 0};
    }
    return r;
  }

  // SOFA's Quat equality: every component within 1e-6.
  bool near(const SQuat& b) const {
    for (int i = 0; i < 4; ++i)
      if (std::abs(q[i] - b.q[i]) > 1e-6) return false;
    return true;
  }
};

// SOFA's Quat::operator+ (a + b): the product with b applied first — xyz = a.xyz·b.w +
// b.xyz·a.w + b.xyz × a.xyz, w = a.w·b.w − a.xyz·b.xyz — then SOFA's normalize (only when the
// squared norm is more than 1e-10 away from 1; a zero quaternion becomes w = 1).
inline SQuat sofa_add(const SQuat& a, const SQuat& b) {
  const auto& p = a.q;
  const auto& q = b.q;
  SQuat r;
  r.q[0] = p[0] * q[3] + q[0] * p[3] + ((q[1] * p[2]) - (q[2] * p[1]));
  r.q[1] = p[1] * q[3] + q[1] * p[3] + ((q[2] * p[0]) - (q[0] * p[2]));
  r.q[2] = p[2] * q[3] + q[2] * p[3] + ((q[0] * p[1]) - (q[1] * p[0]));
  r.q[3] = p[3] * q[3] - (p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  const double mag = r.q[0] * r.q[0] + r.q[1] * r.q[1] + r.q[2] * r.q[2] + r.q[3] * r.q[3];
  if (std::abs(mag - 1.0) > 1.0e-10) {
    if (mag != 0) {
      const double s = 1.0 / std::sqrt(mag);
      for (double& c : r.q) c *= s;
    } else {
      r.q[3] = 1;
    }
  }
  return r;
}

// SOFA's Quat::slerp2: a.slerp2(b, t). Equal (or opposite) quaternions give
// a; a half-angle whose sine is below 1e-3 gives the mean of a and b; no
// shortest-path flip and no renormalisation.
inline SQuat slerp2(const SQuat& a, const SQuat& b, double t) {
  const double cos_half = a.q[3] * b.q[3] + a.q[0] * b.q[0] + a.q[1] * b.q[1] + a.q[2] * b.q[2];
  if (std::abs(cos_half) >= 1.0) return a;
  const double half = std::acos(cos_half);
  const double sin_half = std::sqrt(1.0 - cos_half * cos_half);
  SQuat r;
  if (std::abs(sin_half) < 0.001) {
    for (int i = 0; i < 4; ++i) r.q[i] = a.q[i] * 0.5 + b.q[i] * 0.5;
    return r;
  }
  const double ra = std::sin((1 - t) * half) / sin_half, rb = std::sin(t * half) / sin_half;
  for (int i = 0; i < 4; ++i) r.q[i] = a.q[i] * ra + b.q[i] * rb;
  return r;
}

// SOFA's Vec equality (every component within 1e-6).
inline bool sofa_vec_eq(const Vec3& a, const Vec3& b) {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(a[i] - b[i]) < 1e-6)) return false;
  return true;
}

}  // namespace sinew::io
