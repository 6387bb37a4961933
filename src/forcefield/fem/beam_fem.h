// Kernel of BeamFEMForceField (spec/mechanics.md §2.9): 3D beam elements between
// two Rigid3d frames, corotated with the orientation of the first node.
//
// Quaternions are (x, y, z, w) with SOFA's conventions (type::Quat): Hamilton
// product, inverse = conjugate / |q| (not |q|²), normalisation skipped when
// |q|² is within 1e-10 of 1, and rotate/inverse_rotate valid for unit
// quaternions only. The operation orders below follow SOFA's so that results
// agree to the last digits; they are not meant to be rearranged.
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace sinew::beam {

using Quat = std::array<double, 4>;
using V3 = std::array<double, 3>;
using Mat12 = std::array<double, 144>;  // row-major

inline Quat qmul(const Quat& a, const Quat& b) {
  Quat r;
  r[3] = a[3] * b[3] - (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  r[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
  r[1] = a[3] * b[1] + a[1] * b[3] + a[2] * b[0] - a[0] * b[2];
  r[2] = a[3] * b[2] + a[2] * b[3] + a[0] * b[1] - a[1] * b[0];
  return r;
}

inline Quat qinverse(const Quat& q) {
  double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n == 0.0) return {0, 0, 0, 0};
  n = 1.0 / n;
  return {-q[0] * n, -q[1] * n, -q[2] * n, q[3] * n};
}

inline void qnormalize(Quat& q) {
  const double mag = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  if (std::abs(mag - 1.0) > 1e-10) {
    if (mag != 0.0) {
      const double s = 1.0 / std::sqrt(mag);
      for (double& c : q) c *= s;
    } else {
      q[3] = 1.0;
    }
  }
}

// t = 2·(q⃗ × v); r = v + w·t + q⃗ × t
inline V3 qrotate(const Quat& q, const V3& v) {
  const double t0 = (q[1] * v[2] - q[2] * v[1]) * 2;
  const double t1 = (q[2] * v[0] - q[0] * v[2]) * 2;
  const double t2 = (q[0] * v[1] - q[1] * v[0]) * 2;
  return {v[0] + q[3] * t0 + (q[1] * t2 - q[2] * t1), v[1] + q[3] * t1 + (q[2] * t0 - q[0] * t2),
          v[2] + q[3] * t2 + (q[0] * t1 - q[1] * t0)};
}
inline V3 qinverse_rotate(const Quat& q, const V3& v) { return qrotate({-q[0], -q[1], -q[2], q[3]}, v); }

// Rotation matrix (row-major 3×3) of a unit quaternion, as SOFA's Quat::toMatrix.
inline std::array<double, 9> qmatrix(const Quat& q) {
  return {1 - 2 * (q[1] * q[1] + q[2] * q[2]), 2 * (q[0] * q[1] - q[2] * q[3]), 2 * (q[2] * q[0] + q[1] * q[3]),
          2 * (q[0] * q[1] + q[2] * q[3]),     1 - 2 * (q[2] * q[2] + q[0] * q[0]), 2 * (q[1] * q[2] - q[0] * q[3]),
          2 * (q[2] * q[0] - q[1] * q[3]),     2 * (q[1] * q[2] + q[0] * q[3]), 1 - 2 * (q[1] * q[1] + q[0] * q[0])};
}

// b⁻¹·a, with a flipped first when it lies in the other hemisphere than b.
inline Quat qdiff(Quat a, const Quat& b) {
  if (a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0)
    for (double& c : a) c = -c;
  return qmul(qinverse(b), a);
}

// Axis·angle with angle in [0, 2π]: asin of the vector part below ~5° (w > 0.999), acos above.
inline V3 rotation_vector(Quat q) {
  qnormalize(q);
  if (q[3] < 0)
    for (double& c : q) c = -c;
  double s, angle;
  if (q[3] > 0.999) {
    s = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    angle = 2.0 * std::asin(s);
  } else {
    const double half = std::acos(q[3]);
    s = std::sin(half);
    angle = 2 * half;
  }
  if (s < std::numeric_limits<double>::epsilon()) return {0, 0, 0};
  return {q[0] / s * angle, q[1] / s * angle, q[2] / s * angle};
}

// Quaternion of the rotation by `phi` about `axis` (identity for a null axis).
inline Quat axis_angle(V3 a, double phi) {
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (n < std::numeric_limits<double>::epsilon()) return {0, 0, 0, 1};
  a = {a[0] / n, a[1] / n, a[2] / n};
  const double sp = std::sin(phi / 2.0), cp = std::cos(phi / 2.0);
  return {a[0] * sp, a[1] * sp, a[2] * sp, cp};
}

// Section and material of one beam.
struct BeamSection {
  double E, nu, L, r, r_inner;
  double G, Iy, Iz, J, A, Asy, Asz;  // Asy = Asz = 0: no shear area, so φ = 0 (Euler–Bernoulli)
};

inline BeamSection make_section(double E, double L, double nu, double r, double ri) {
  BeamSection s{};
  s.E = E, s.nu = nu, s.L = L, s.r = r, s.r_inner = ri;
  s.G = s.E / (2.0 * (1.0 + s.nu));
  s.Iz = M_PI * (r * r * r * r - ri * ri * ri * ri) / 4.0;
  s.Iy = s.Iz;
  s.J = s.Iz + s.Iy;
  s.A = M_PI * (r * r - ri * ri);
  s.Asy = 0.0, s.Asz = 0.0;
  return s;
}

// Local 12×12 Timoshenko stiffness, dofs [u_a, θ_a, u_b, θ_b] (x along the beam).
Mat12 local_stiffness(const BeamSection& s);

// y = K·d with SOFA's row-by-row summation order.
inline void mat12_mul(const Mat12& K, const double* d, double* y) {
  for (int i = 0; i < 12; ++i) {
    const double* row = &K[i * 12];
    double acc = row[0] * d[0];
    for (int j = 1; j < 12; ++j) acc += row[j] * d[j];
    y[i] = acc;
  }
}

}  // namespace sinew::beam
