// Reference finite elements of SOFA's element-generic FEM (Sofa/framework/FEM,
// FiniteElement[Tetrahedron|Hexahedron]): shape functions, their reference
// gradients, quadrature rules, and the Jacobian helpers (determinant, 3×3
// inverse) in SOFA's exact evaluation order.
//
// Used by FEMMass (mass matrix) and the LinearSmallStrain/Corotational FEM
// force fields (stiffness). Spec: shared/spec/mechanics.md §1.4 and §2.5.
//
// Everything here must round like SOFA: each sum is written out left to
// right, starting with the first term (SOFA's Mat/Vec loops), and the hexa
// Gauss points use SOFA's truncated √3 = 1.73205080757 (spec trap 6).
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace sinew::fe {

using Vec3d = std::array<double, 3>;
using Mat3d = std::array<std::array<double, 3>, 3>;  // row-major: m[row][col]

// ------------------------------------------------------------ elements
// 4-node linear tetrahedron, reference nodes (0,0,0) (1,0,0) (0,1,0) (0,0,1);
// one quadrature point (¼,¼,¼) with weight 1/6 (the reference volume).
struct Tetra4 {
  static constexpr int kNodes = 4;
  static constexpr int kPoints = 1;
  static std::array<Vec3d, kPoints> points() { return {{{1. / 4., 1. / 4., 1. / 4.}}}; }
  static std::array<double, kPoints> weights() { return {1. / 6.}; }
  static void shape(const Vec3d& q, double (&N)[kNodes]) {
    N[0] = 1.0 - q[0] - q[1] - q[2];
    N[1] = q[0];
    N[2] = q[1];
    N[3] = q[2];
  }
  static void gradient(const Vec3d& /*q*/, double (&g)[kNodes][3]) {
    static constexpr double G[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < kNodes; ++i)
      for (int c = 0; c < 3; ++c) g[i][c] = G[i][c];
  }
};

// 8-node trilinear hexahedron, reference nodes (SOFA's geometry::Hexahedron
// order) (-1,-1,-1) (1,-1,-1) (1,1,-1) (-1,1,-1) (-1,-1,1) (1,-1,1) (1,1,1)
// (-1,1,1); 2×2×2 Gauss points ±1/1.73205080757 in node order, weight 1.
struct Hexa8 {
  static constexpr int kNodes = 8;
  static constexpr int kPoints = 8;
  static constexpr double kRef[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static std::array<Vec3d, kPoints> points() {
    const double sqrt3 = 1.73205080757;  // SOFA's truncated constant, not std::sqrt(3)
    const double s = 1.0 / sqrt3;
    std::array<Vec3d, kPoints> p{};
    for (int k = 0; k < kPoints; ++k)
      for (int c = 0; c < 3; ++c) p[k][c] = kRef[k][c] * s;
    return p;
  }
  static std::array<double, kPoints> weights() { return {1, 1, 1, 1, 1, 1, 1, 1}; }
  static void shape(const Vec3d& q, double (&N)[kNodes]) {
    const double a = q[0], b = q[1], c = q[2];
    N[0] = -0.125 * (a - 1) * (b - 1) * (c - 1);
    N[1] = 0.125 * (a + 1) * (b - 1) * (c - 1);
    N[2] = -0.125 * (a + 1) * (b + 1) * (c - 1);
    N[3] = 0.125 * (a - 1) * (b + 1) * (c - 1);
    N[4] = 0.125 * (a - 1) * (b - 1) * (c + 1);
    N[5] = -0.125 * (a + 1) * (b - 1) * (c + 1);
    N[6] = 0.125 * (a + 1) * (b + 1) * (c + 1);
    N[7] = -0.125 * (a - 1) * (b + 1) * (c + 1);
  }
  static void gradient(const Vec3d& q, double (&g)[kNodes][3]) {
    const double x = q[0], y = q[1], z = q[2];
    for (int i = 0; i < kNodes; ++i) {
      const double xr = kRef[i][0], yr = kRef[i][1], zr = kRef[i][2];
      g[i][0] = xr * (1 + y * yr) * (1 + z * zr) * (1. / 8.);
      g[i][1] = yr * (1 + x * xr) * (1 + z * zr) * (1. / 8.);
      g[i][2] = zr * (1 + x * xr) * (1 + y * yr) * (1. / 8.);
    }
  }
};

// 6-node linear prism (wedge), SOFA's FiniteElement<Prism>: reference nodes
// (0,0,0) (1,0,0) (0,1,0) (0,0,1) (1,0,1) (0,1,1) (triangle 0,1,2 below,
// 3,4,5 above); two quadrature points (⅓, ⅓, ½(1 ∓ 0.57735026919)) with
// weight ¼ each (SOFA's truncated 1/√3; the reference volume is ½).
struct Prism6 {
  static constexpr int kNodes = 6;
  static constexpr int kPoints = 2;
  static std::array<Vec3d, kPoints> points() {
    const double third = 1.0 / 3.0, s = 0.57735026919;
    return {{{third, third, 0.5 * (1.0 - s)}, {third, third, 0.5 * (1.0 + s)}}};
  }
  static std::array<double, kPoints> weights() { return {1. / 4., 1. / 4.}; }
  static void shape(const Vec3d& q, double (&N)[kNodes]) {
    N[0] = q[0] * q[2] - q[0] + q[1] * q[2] - q[1] - q[2] + 1;
    N[1] = (1 - q[2]) * q[0];
    N[2] = (1 - q[2]) * q[1];
    N[3] = (-q[0] - q[1] + 1) * q[2];
    N[4] = q[0] * q[2];
    N[5] = q[1] * q[2];
  }
  static void gradient(const Vec3d& q, double (&g)[kNodes][3]) {
    const double G[6][3] = {{q[2] - 1, q[2] - 1, q[0] + q[1] - 1}, {1 - q[2], 0, -q[0]}, {0, 1 - q[2], -q[1]},
                            {-q[2], -q[2], -q[0] - q[1] + 1},      {q[2], 0, q[0]},      {0, q[2], q[1]}};
    for (int i = 0; i < kNodes; ++i)
      for (int c = 0; c < 3; ++c) g[i][c] = G[i][c];
  }
};

// 5-node pyramid, SOFA's FiniteElement<Pyramid>: reference base (−1,−1,−1)
// (1,−1,−1) (1,1,−1) (−1,1,−1), apex (0,0,1); N_i = ⅛(1 ± x)(1 ± y)(1 − z)
// for the base, ½(1 + z) for the apex (SOFA's collapsed-hexahedron
// functions); the hexahedron's 2×2×2 Gauss points (±1/1.73205080757,
// weight 1), which integrate the (1 − z)² Jacobian exactly.
struct Pyramid5 {
  static constexpr int kNodes = 5;
  static constexpr int kPoints = 8;
  static std::array<Vec3d, kPoints> points() { return Hexa8::points(); }
  static std::array<double, kPoints> weights() { return Hexa8::weights(); }
  static void shape(const Vec3d& q, double (&N)[kNodes]) {
    N[0] = 0.125 * (1 - q[0]) * (1 - q[1]) * (1 - q[2]);
    N[1] = 0.125 * (1 + q[0]) * (1 - q[1]) * (1 - q[2]);
    N[2] = 0.125 * (1 + q[0]) * (1 + q[1]) * (1 - q[2]);
    N[3] = 0.125 * (1 - q[0]) * (1 + q[1]) * (1 - q[2]);
    N[4] = 0.5 * (1 + q[2]);
  }
  static void gradient(const Vec3d& q, double (&g)[kNodes][3]) {
    const double x = q[0], y = q[1], z = q[2];
    const double G[5][3] = {{-0.125 * (1 - y) * (1 - z), -0.125 * (1 - x) * (1 - z), -0.125 * (1 - x) * (1 - y)},
                            {0.125 * (1 - y) * (1 - z), -0.125 * (1 + x) * (1 - z), -0.125 * (1 + x) * (1 - y)},
                            {0.125 * (1 + y) * (1 - z), 0.125 * (1 + x) * (1 - z), -0.125 * (1 + x) * (1 + y)},
                            {-0.125 * (1 + y) * (1 - z), 0.125 * (1 - x) * (1 - z), -0.125 * (1 - x) * (1 + y)},
                            {0, 0, 0.5}};
    for (int i = 0; i < kNodes; ++i)
      for (int c = 0; c < 3; ++c) g[i][c] = G[i][c];
  }
};

// ------------------------------------------------------------ Jacobian helpers
// J(a,b) = Σ_i X_i[a] · ∂N_i/∂q_b, summed over nodes in order.
template <int N, class Point>
Mat3d jacobian(const Point (&X)[N], const double (&g)[N][3]) {
  Mat3d J{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double s = X[0][a] * g[0][b];
      for (int i = 1; i < N; ++i) s += X[i][a] * g[i][b];
      J[a][b] = s;
    }
  return J;
}

// SOFA's 3×3 determinant (type/Mat.h), term order preserved.
inline double determinant(const Mat3d& m) {
  return m[0][0] * m[1][1] * m[2][2] + m[1][0] * m[2][1] * m[0][2] + m[2][0] * m[0][1] * m[1][2] -
         m[0][0] * m[2][1] * m[1][2] - m[1][0] * m[0][1] * m[2][2] - m[2][0] * m[1][1] * m[0][2];
}

// SOFA's 3×3 inverse (cofactors divided by the determinant). Returns false
// when |det| ≤ DBL_EPSILON, SOFA's "zero" (where SOFA silently keeps the
// un-inverted matrix); the caller reports the degenerate element.
inline bool invert(const Mat3d& f, Mat3d& d) {
  const double det = determinant(f);
  if (!(std::abs(det) > std::numeric_limits<double>::epsilon()) || !std::isfinite(det)) return false;
  d[0][0] = (f[1][1] * f[2][2] - f[2][1] * f[1][2]) / det;
  d[1][0] = (f[1][2] * f[2][0] - f[2][2] * f[1][0]) / det;
  d[2][0] = (f[1][0] * f[2][1] - f[2][0] * f[1][1]) / det;
  d[0][1] = (f[2][1] * f[0][2] - f[0][1] * f[2][2]) / det;
  d[1][1] = (f[2][2] * f[0][0] - f[0][2] * f[2][0]) / det;
  d[2][1] = (f[2][0] * f[0][1] - f[0][0] * f[2][1]) / det;
  d[0][2] = (f[0][1] * f[1][2] - f[1][1] * f[0][2]) / det;
  d[1][2] = (f[0][2] * f[1][0] - f[1][2] * f[0][0]) / det;
  d[2][2] = (f[0][0] * f[1][1] - f[1][0] * f[0][1]) / det;
  return true;
}

}  // namespace sinew::fe
