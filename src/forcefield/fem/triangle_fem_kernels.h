// Kernels shared by TriangularFEMForceField and TriangleFEMForceField, with
// SOFA's TriangleFEMUtils formulas and evaluation order: the corotational frame
// of a triangle, the strain-displacement matrix J of a triangle in its local
// frame, and the strain → stress → force products (full, or restricted to the
// non-zero pattern of J and of the isotropic material matrix).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "core/matrix_sink.h"
#include "math/types.h"

namespace sinew::trifem {

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
inline Vec3 normalized(Vec3 v) {
  const double n = std::sqrt(dot(v, v));
  if (n > std::numeric_limits<double>::epsilon())
    for (int c = 0; c < 3; ++c) v[c] /= n;
  return v;
}
inline Vec3 at(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }
inline Vec3 minus(const Vec3& a, const Vec3& b) { return Vec3(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
// Rows (ex, ey, ez): ex along AB, ez along ex × AC, ey = ez × ex (SOFA's computeRotationLarge).
inline Mat3 frame_large(const Vec3& pA, const Vec3& pB, const Vec3& pC) {
  const Vec3 ex = normalized(minus(pB, pA));
  const Vec3 ez = normalized(cross(ex, minus(pC, pA)));
  const Vec3 ey = cross(ez, ex);
  Mat3 r;
  r << ex[0], ex[1], ex[2], ey[0], ey[1], ey[2], ez[0], ez[1], ez[2];
  return r;
}
inline Vec3 mul(const Mat3& m, const Vec3& v) {
  return Vec3(m(0, 0) * v[0] + m(0, 1) * v[1] + m(0, 2) * v[2], m(1, 0) * v[0] + m(1, 1) * v[1] + m(1, 2) * v[2],
              m(2, 0) * v[0] + m(2, 1) * v[1] + m(2, 2) * v[2]);
}
// J from the local shape (A at 0, B on x, C in the plane); false when det ≈ 0.
inline bool local_j(double bx, double cx, double cy, std::array<double, 18>& J) {
  const double det = bx * cy;
  if (std::fabs(det) < std::numeric_limits<double>::epsilon()) return false;
  const double inv = 1 / det;
  J.fill(0.0);
  J[0 * 3 + 0] = J[1 * 3 + 2] = -cy * inv;
  J[0 * 3 + 2] = J[1 * 3 + 1] = (cx - bx) * inv;
  J[2 * 3 + 0] = J[3 * 3 + 2] = cy * inv;
  J[2 * 3 + 2] = J[3 * 3 + 1] = -cx * inv;
  J[4 * 3 + 0] = J[5 * 3 + 2] = 0;
  J[4 * 3 + 2] = J[5 * 3 + 1] = bx * inv;
  return true;
}
// Full products (small method): strain = Jᵀ·D, stress = K·strain, F = J·stress.
inline void kernel_full(const std::array<double, 18>& J, const std::array<double, 9>& K, const double* D, double* F) {
  double e[3], s[3];
  for (int j = 0; j < 3; ++j) {
    e[j] = J[0 * 3 + j] * D[0];
    for (int i = 1; i < 6; ++i) e[j] += J[i * 3 + j] * D[i];
  }
  for (int i = 0; i < 3; ++i) s[i] = K[i * 3] * e[0] + K[i * 3 + 1] * e[1] + K[i * 3 + 2] * e[2];
  for (int i = 0; i < 6; ++i) F[i] = J[i * 3] * s[0] + J[i * 3 + 1] * s[1] + J[i * 3 + 2] * s[2];
}
// SOFA's sparse kernel: strain = Jᵀ·D, stress = K·strain, F = J·stress (zero pattern of J and K).
inline void kernel(const std::array<double, 18>& J, const std::array<double, 9>& K, const double* D, double* F) {
  auto j = [&](int r, int c) { return J[r * 3 + c]; };
  const double e0 = j(0, 0) * D[0] + j(2, 0) * D[2];
  const double e1 = j(1, 1) * D[1] + j(3, 1) * D[3] + j(5, 1) * D[5];
  const double e2 = j(0, 2) * D[0] + j(1, 2) * D[1] + j(2, 2) * D[2] + j(3, 2) * D[3] + j(4, 2) * D[4];
  const double s0 = K[0] * e0 + K[1] * e1;
  const double s1 = K[3] * e0 + K[4] * e1;
  const double s2 = K[8] * e2;
  F[0] = j(0, 0) * s0 + j(0, 2) * s2;
  F[1] = j(1, 1) * s1 + j(1, 2) * s2;
  F[2] = j(2, 0) * s0 + j(2, 2) * s2;
  F[3] = j(3, 1) * s1 + j(3, 2) * s2;
  F[4] = j(4, 2) * s2;
  F[5] = j(5, 1) * s1;
}
// −R·(J·K·Jᵀ expanded to 3D)·Rᵀ into K, in 3×3 blocks (SOFA's
// computeElementStiffnessMatrix then addToMatrix / buildStiffnessMatrix);
// `rotation` is local → world.
inline void add_element_stiffness(MatrixSink& K, const MechanicalState* s, const std::array<unsigned, 3>& v,
                                  const std::array<double, 18>& Jr, const std::array<double, 9>& Dr,
                                  const Mat3& rotation) {
  using Mat63 = Eigen::Matrix<double, 6, 3>;
  using Mat9 = Eigen::Matrix<double, 9, 9>;
  Mat63 J;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 3; ++c) J(r, c) = Jr[r * 3 + c];
  Mat3 D;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) D(r, c) = Dr[r * 3 + c];
  const Eigen::Matrix<double, 6, 6> JKJt = J * D * J.transpose();
  Mat9 Ke = Mat9::Zero(), RR = Mat9::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) Ke(3 * i + k, 3 * j + l) = JKJt(2 * i + k, 2 * j + l);
  for (int b = 0; b < 3; ++b) RR.block<3, 3>(3 * b, 3 * b) = rotation;
  const Mat9 SR = RR * Ke * RR.transpose();
  for (int n1 = 0; n1 < 3; ++n1)
    for (int n2 = 0; n2 < 3; ++n2)
      K.add_block(s, 3 * v[n1], s, 3 * v[n2], -SR.block<3, 3>(3 * n1, 3 * n2));
}

}  // namespace sinew::trifem
