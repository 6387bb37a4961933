// Quaternions as SOFA's type::Quat computes them, on (x, y, z, w) storage
// (the layout of a Rigid3d coordinate's last four numbers). The operation
// order follows SOFA's so results agree to the last bits; these are the
// operations the Lagrangian constraints and rigid mappings need.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "math/types.h"

namespace sinew {

struct Quat {
  double x = 0, y = 0, z = 0, w = 1;

  static Quat from(const double* q) { return {q[0], q[1], q[2], q[3]}; }
  void store(double* q) const { q[0] = x, q[1] = y, q[2] = z, q[3] = w; }
};

// Hamilton product a·b (rotation b then a).
inline Quat quat_mul(const Quat& a, const Quat& b) {
  Quat r;
  r.w = a.w * b.w - (a.x * b.x + a.y * b.y + a.z * b.z);
  r.x = a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y;
  r.y = a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z;
  r.z = a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x;
  return r;
}

// Rescaled to unit length unless already within 1e-10 of it (SOFA's rule;
// a zero quaternion becomes the identity's w).
inline Quat quat_normalized(Quat q) {
  const double mag = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (std::abs(mag - 1.0) > 1.0e-10) {
    if (mag != 0) {
      const double s = 1.0 / std::sqrt(mag);
      q.x *= s, q.y *= s, q.z *= s, q.w *= s;
    } else {
      q.w = 1;
    }
  }
  return q;
}

// SOFA's `a + b` (Quat::operator+ and +=): rotation a, then b, i.e. the product
// b·a with SOFA's grouping of the sums, then normalised.
inline Quat quat_then(const Quat& a, const Quat& b) {
  Quat r;
  r.x = a.x * b.w + b.x * a.w + (b.y * a.z - b.z * a.y);
  r.y = a.y * b.w + b.y * a.w + (b.z * a.x - b.x * a.z);
  r.z = a.z * b.w + b.z * a.w + (b.x * a.y - b.y * a.x);
  r.w = a.w * b.w - (a.x * b.x + a.y * b.y + a.z * b.z);
  return quat_normalized(r);
}

// Rotation of `phi` radians about `axis` (SOFA's Quat::axisToQuat): the
// identity for an axis shorter than machine epsilon.
inline Quat quat_from_axis_angle(Vec3 axis, double phi) {
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (n < std::numeric_limits<double>::epsilon()) return {};
  axis /= n;
  const double sp = std::sin(phi / 2.0), cp = std::cos(phi / 2.0);
  return {axis[0] * sp, axis[1] * sp, axis[2] * sp, cp};
}

// Conjugate divided by the norm (zero for a zero quaternion).
inline Quat quat_inverse(const Quat& q) {
  double n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (n == 0.0) return {0, 0, 0, 0};
  n = 1.0 / n;
  return {-q.x * n, -q.y * n, -q.z * n, q.w * n};
}

// R(q)·v as t = 2 q⃗×v, v + w t + q⃗×t.
inline Vec3 quat_rotate(const Quat& q, const Vec3& v) {
  const Vec3 u(q.x, q.y, q.z);
  const Vec3 t = u.cross(v) * 2;
  return v + q.w * t + u.cross(t);
}
// R(q)ᵀ·v.
inline Vec3 quat_inverse_rotate(const Quat& q, const Vec3& v) {
  const Vec3 u(-q.x, -q.y, -q.z);
  const Vec3 t = u.cross(v) * 2;
  return v + q.w * t + u.cross(t);
}

// b⁻¹·a, a first flipped onto b's hemisphere (SOFA's Quat::quatDiff).
inline Quat quat_diff(Quat a, const Quat& b) {
  if (a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w < 0) a = {-a.x, -a.y, -a.z, -a.w};
  return quat_mul(quat_inverse(b), a);
}

// Rotation angle 2·acos(w) of a unit quaternion and the sine of its half, as
// SOFA computes them: from the vector part's length through asin when w is above
// `asin_above` (acos loses precision near 1; SOFA's thresholds differ per caller).
struct QuatAngle {
  double angle, sin_half;
};
inline QuatAngle quat_angle(const Quat& q, double asin_above) {
  QuatAngle r;
  if (q.w > asin_above) {
    r.sin_half = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    r.angle = 2.0 * std::asin(r.sin_half);
  } else {
    const double half = std::acos(q.w);
    r.sin_half = std::sin(half);
    r.angle = 2 * half;
  }
  return r;
}

// Axis times angle in [0, 2π) (SOFA's quatToRotationVector; asin branch
// below 5° for accuracy).
inline Vec3 quat_to_rotation_vector(const Quat& in) {
  Quat q = quat_normalized(in);
  if (q.w < 0) q = {-q.x, -q.y, -q.z, -q.w};
  const QuatAngle a = quat_angle(q, 0.999);
  if (a.sin_half < std::numeric_limits<double>::epsilon()) return Vec3::Zero();
  return Vec3(q.x, q.y, q.z) / a.sin_half * a.angle;
}

// Rotation vector taking orientation b to a (SOFA's Quat::angularDisplacement).
inline Vec3 quat_angular_displacement(const Quat& a, const Quat& b) {
  return quat_to_rotation_vector(quat_diff(a, b));
}

// Rotation matrix of a unit quaternion (SOFA's Quat::toMatrix, same arithmetic).
inline Mat3 quat_to_matrix(const Quat& q) {
  Mat3 m;
  m << 1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y - q.z * q.w), 2 * (q.z * q.x + q.y * q.w),
      2 * (q.x * q.y + q.z * q.w), 1 - 2 * (q.z * q.z + q.x * q.x), 2 * (q.y * q.z - q.x * q.w),
      2 * (q.z * q.x - q.y * q.w), 2 * (q.y * q.z + q.x * q.w), 1 - 2 * (q.y * q.y + q.x * q.x);
  return m;
}

// Quaternion of a rotation matrix (SOFA's Quat::fromMatrix): from the trace when
// it is positive, else from the largest diagonal entry; not renormalised.
inline Quat quat_from_matrix(const Mat3& m) {
  Quat q;
  const double tr = m(0, 0) + m(1, 1) + m(2, 2);
  if (tr > 0) {
    double s = std::sqrt(tr + 1);
    q.w = s * 0.5;
    s = 0.5 / s;
    q.x = (m(2, 1) - m(1, 2)) * s;
    q.y = (m(0, 2) - m(2, 0)) * s;
    q.z = (m(1, 0) - m(0, 1)) * s;
  } else if (m(1, 1) > m(0, 0) && m(2, 2) <= m(1, 1)) {
    double s = std::sqrt((m(1, 1) - (m(2, 2) + m(0, 0))) + 1.0);
    q.y = s * 0.5;
    if (s != 0.0) s = 0.5 / s;
    q.z = (m(1, 2) + m(2, 1)) * s;
    q.x = (m(0, 1) + m(1, 0)) * s;
    q.w = (m(0, 2) - m(2, 0)) * s;
  } else if ((m(1, 1) <= m(0, 0) && m(2, 2) > m(0, 0)) || (m(2, 2) > m(1, 1))) {
    double s = std::sqrt((m(2, 2) - (m(0, 0) + m(1, 1))) + 1.0);
    q.z = s * 0.5;
    if (s != 0.0) s = 0.5 / s;
    q.x = (m(2, 0) + m(0, 2)) * s;
    q.y = (m(1, 2) + m(2, 1)) * s;
    q.w = (m(1, 0) - m(0, 1)) * s;
  } else {
    double s = std::sqrt((m(0, 0) - (m(1, 1) + m(2, 2))) + 1.0);
    q.x = s * 0.5;
    if (s != 0.0) s = 0.5 / s;
    q.y = (m(0, 1) + m(1, 0)) * s;
    q.z = (m(2, 0) + m(0, 2)) * s;
    q.w = (m(2, 1) - m(1, 2)) * s;
  }
  return q;
}

// Roll, pitch, yaw (SOFA's Quat::toEulerVector).
inline Vec3 quat_to_euler_vector(const Quat& in) {
  const Quat q = quat_normalized(in);
  const double y = std::max(-1.0, std::min(1.0, 2. * (q.w * q.y - q.z * q.x)));
  return Vec3(std::atan2(2 * (q.w * q.x + q.y * q.z), (1 - 2 * (q.x * q.x + q.y * q.y))), std::asin(y),
              std::atan2(2 * (q.w * q.z + q.x * q.y), (1 - 2 * (q.y * q.y + q.z * q.z))));
}

}  // namespace sinew
