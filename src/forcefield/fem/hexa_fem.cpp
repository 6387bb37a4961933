#include "forcefield/fem/hexa_fem.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>

#include "forcefield/fem/sofa_mat3.h"
#include "math/decompose.h"
#include "math/target_clones.h"

namespace sinew::fem {

namespace {

// Corner signs (ξ1, ξ2, ξ3) of the 8 nodes in the reference cube [-1,1]³.
constexpr int kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Small 3D helpers with SOFA's evaluation order (left-to-right sums).
inline double norm3(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// SOFA's normalize: divides by the norm, leaves the vector untouched when the
// norm is ≤ DBL_EPSILON.
inline void normalize3(Vec3& a) {
  const double n = norm3(a);
  if (n > kEps) {
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
  }
}

// Rᵀ·v (R·v is fem::mul, forcefield/sofa_mat3.h).
inline Vec3 mul_t(const Mat3& R, double v0, double v1, double v2) {
  return Vec3(R(0, 0) * v0 + R(1, 0) * v1 + R(2, 0) * v2, R(0, 1) * v0 + R(1, 1) * v1 + R(2, 1) * v2,
              R(0, 2) * v0 + R(1, 2) * v1 + R(2, 2) * v2);
}

// Averaged edges of the element along the three cell axes. SOFA writes each as
// one chain n1−n0+n2−n3+n5−n4+n6−n7 evaluated left to right (not as a sum of
// pair differences), then scales by 0.25.
inline Vec3 edge_chain(const std::array<Vec3, 8>& n, int a0, int a1, int b0, int b1, int c0, int c1, int d0,
                       int d1) {
  Vec3 r;
  for (int c = 0; c < 3; ++c)
    r[c] = (n[a0][c] - n[a1][c] + n[b0][c] - n[b1][c] + n[c0][c] - n[c1][c] + n[d0][c] - n[d1][c]) * 0.25;
  return r;
}
inline Vec3 edge_x(const std::array<Vec3, 8>& n) { return edge_chain(n, 1, 0, 2, 3, 5, 4, 6, 7); }
inline Vec3 edge_y(const std::array<Vec3, 8>& n) { return edge_chain(n, 3, 0, 2, 1, 7, 4, 6, 5); }
inline Vec3 edge_z(const std::array<Vec3, 8>& n) { return edge_chain(n, 4, 0, 5, 1, 7, 3, 6, 2); }

// F = K·D with each F[i] summed left to right from K(i,0)·D[0], as SOFA does.
// K is exactly symmetric (its lower half is a copy of the upper half), so
// row c of the storage is column c: accumulating column by column keeps every
// row's summation order while letting the 24 rows proceed independently
// (vectorised, no dependency chain), for bit-identical results.
// Compiled twice (runtime choice): the AVX2 clone only widens the
// row-wise vectorisation (4 rows per instruction instead of 2); every row
// still gets k·D0, then += col·d in column order, no FMA (-ffp-contract=off,
// and avx2 does not enable fma): bit-identical to the default clone.
// The 24 accumulators stay in registers (6 vectors of 4 rows; plain arrays
// through pointers made GCC load/store F for every column).
typedef double v4u __attribute__((vector_size(32), aligned(8)));
SINEW_AVX2_CLONES void mul24_clones(const double* k, const double* D, double* F) {
  const v4u d0 = {D[0], D[0], D[0], D[0]};
  v4u a0 = *reinterpret_cast<const v4u*>(k + 0) * d0;
  v4u a1 = *reinterpret_cast<const v4u*>(k + 4) * d0;
  v4u a2 = *reinterpret_cast<const v4u*>(k + 8) * d0;
  v4u a3 = *reinterpret_cast<const v4u*>(k + 12) * d0;
  v4u a4 = *reinterpret_cast<const v4u*>(k + 16) * d0;
  v4u a5 = *reinterpret_cast<const v4u*>(k + 20) * d0;
  for (int c = 1; c < 24; ++c) {
    const double* col = k + 24 * c;
    const v4u d = {D[c], D[c], D[c], D[c]};
    a0 += *reinterpret_cast<const v4u*>(col + 0) * d;
    a1 += *reinterpret_cast<const v4u*>(col + 4) * d;
    a2 += *reinterpret_cast<const v4u*>(col + 8) * d;
    a3 += *reinterpret_cast<const v4u*>(col + 12) * d;
    a4 += *reinterpret_cast<const v4u*>(col + 16) * d;
    a5 += *reinterpret_cast<const v4u*>(col + 20) * d;
  }
  *reinterpret_cast<v4u*>(F + 0) = a0;
  *reinterpret_cast<v4u*>(F + 4) = a1;
  *reinterpret_cast<v4u*>(F + 8) = a2;
  *reinterpret_cast<v4u*>(F + 12) = a3;
  *reinterpret_cast<v4u*>(F + 16) = a4;
  *reinterpret_cast<v4u*>(F + 20) = a5;
}

// element_dforce with a row-reordered stiffness kp (rows: x of nodes 0..7,
// y, z) and node-major inputs v[i][k]: X = R·dx per node, F = K·X (each row
// k·X0 then += col·X_c for c = 3k + i in column order, as mul24), t = Rᵀ·F per
// node, times kfactor. Every value gets the scalar sequence of operations of
// element_dforce; only independent nodes/rows share the vector instructions.
SINEW_AVX2_CLONES void hexa_dforce_soa(const double* kp, const Mat3& R, bool rotate,
                                                                      const double (*v)[8], double kfactor,
                                                                      double (*o)[8]) {
#define L(p) (*reinterpret_cast<const v4u*>(p))
#define S(x) (v4u{(x), (x), (x), (x)})
  alignas(32) double X[3][8];
  for (int h = 0; h < 8; h += 4) {
    const v4u v0 = L(v[0] + h), v1 = L(v[1] + h), v2 = L(v[2] + h);
    for (int i = 0; i < 3; ++i) {
      const v4u x = rotate ? S(R(i, 0)) * v0 + S(R(i, 1)) * v1 + S(R(i, 2)) * v2 : (i == 0 ? v0 : i == 1 ? v1 : v2);
      *reinterpret_cast<v4u*>(X[i] + h) = x;
    }
  }
  const v4u d0 = S(X[0][0]);
  v4u a0 = L(kp + 0) * d0, a1 = L(kp + 4) * d0, a2 = L(kp + 8) * d0;
  v4u a3 = L(kp + 12) * d0, a4 = L(kp + 16) * d0, a5 = L(kp + 20) * d0;
  for (int c = 1; c < 24; ++c) {
    const double* col = kp + 24 * c;
    const v4u d = S(X[c % 3][c / 3]);
    a0 += L(col + 0) * d;
    a1 += L(col + 4) * d;
    a2 += L(col + 8) * d;
    a3 += L(col + 12) * d;
    a4 += L(col + 16) * d;
    a5 += L(col + 20) * d;
  }
  const v4u fx[2] = {a0, a1}, fy[2] = {a2, a3}, fz[2] = {a4, a5};
  const v4u kf = S(kfactor);
  for (int q = 0; q < 2; ++q)
    for (int i = 0; i < 3; ++i) {
      const v4u t = rotate ? S(R(0, i)) * fx[q] + S(R(1, i)) * fy[q] + S(R(2, i)) * fz[q]
                           : (i == 0 ? fx[q] : i == 1 ? fy[q] : fz[q]);
      *reinterpret_cast<v4u*>(o[i] + 4 * q) = t * kf;
    }
#undef L
#undef S
}

bool all_finite(const Mat24& K) {
  for (int i = 0; i < 24 * 24; ++i)
    if (!std::isfinite(K.data()[i])) return false;
  return true;
}

}  // namespace

HexaMaterial hexa_material(double young, double poisson) {
  const double off = poisson / (1 - poisson);
  const double shear = (1 - 2 * poisson) / (2 * (1 - poisson));
  const double scale = (young * (1 - poisson)) / ((1 + poisson) * (1 - 2 * poisson));
  return {1.0 * scale, off * scale, shear * scale};
}

HexaJacobianInfo hexa_element_stiffness(const std::array<Vec3, 8>& n, const HexaMaterial& mat, double coef,
                                        Mat24& K) {
  HexaJacobianInfo info;
  K.setZero();
  Mat3 J = Mat3::Zero();
  Mat3 Ji = Mat3::Zero();  // stays at its last value when an inversion fails, as in SOFA
  double detJ = 1.0;

  // Parallelepiped shortcut: constant Jacobian. The first test is relative to
  // |lx|, the four others to |lz|; ly is not tested (SOFA's choice).
  const Vec3 lx = n[1] - n[0];
  const Vec3 ly = n[3] - n[0];
  const Vec3 lz = n[4] - n[0];
  auto gap = [](const Vec3& a, const Vec3& l, const Vec3& b) {
    return norm3(Vec3(a[0] + l[0] - b[0], a[1] + l[1] - b[1], a[2] + l[2] - b[2]));
  };
  const bool parallel = gap(n[3], lx, n[2]) < norm3(lx) * 0.001 && gap(n[0], lz, n[4]) < norm3(lz) * 0.001 &&
                        gap(n[1], lz, n[5]) < norm3(lz) * 0.001 && gap(n[2], lz, n[6]) < norm3(lz) * 0.001 &&
                        gap(n[3], lz, n[7]) < norm3(lz) * 0.001;
  info.parallelepiped = parallel;
  info.min_det = std::numeric_limits<double>::infinity();
  if (parallel) {
    for (int c = 0; c < 3; ++c) {
      J(c, 0) = lx[c] / 2;
      J(c, 1) = ly[c] / 2;
      J(c, 2) = lz[c] / 2;
    }
    detJ = det3(J);
    if (!invert3(J, detJ, Ji)) info.singular = true;
    info.min_det = detJ;
  }

  const double U = mat.u, V = mat.v, W = mat.w;
  const double inv_sqrt3 = 1.0 / std::sqrt(3.0);
  for (int g1 = -1; g1 <= 1; g1 += 2)
    for (int g2 = -1; g2 <= 1; g2 += 2)
      for (int g3 = -1; g3 <= 1; g3 += 2) {
        const double x1 = g1 * inv_sqrt3;
        const double x2 = g2 * inv_sqrt3;
        const double x3 = g3 * inv_sqrt3;
        if (!parallel) {
          for (int c = 0; c < 3; ++c) {
            J(c, 0) = (n[1][c] - n[0][c]) * (1 - x2) * (1 - x3) / 8 + (n[2][c] - n[3][c]) * (1 + x2) * (1 - x3) / 8 +
                      (n[5][c] - n[4][c]) * (1 - x2) * (1 + x3) / 8 + (n[6][c] - n[7][c]) * (1 + x2) * (1 + x3) / 8;
            J(c, 1) = (n[3][c] - n[0][c]) * (1 - x1) * (1 - x3) / 8 + (n[2][c] - n[1][c]) * (1 + x1) * (1 - x3) / 8 +
                      (n[7][c] - n[4][c]) * (1 - x1) * (1 + x3) / 8 + (n[6][c] - n[5][c]) * (1 + x1) * (1 + x3) / 8;
            J(c, 2) = (n[4][c] - n[0][c]) * (1 - x1) * (1 - x2) / 8 + (n[5][c] - n[1][c]) * (1 + x1) * (1 - x2) / 8 +
                      (n[6][c] - n[2][c]) * (1 + x1) * (1 + x2) / 8 + (n[7][c] - n[3][c]) * (1 - x1) * (1 + x2) / 8;
          }
          detJ = det3(J);
          if (!invert3(J, detJ, Ji)) info.singular = true;
          if (detJ < info.min_det) info.min_det = detJ;
        }

        // Physical shape-function gradients q = J⁻ᵀ dN/dξ.
        double qx[8], qy[8], qz[8];
        for (int i = 0; i < 8; ++i) {
          const double s1 = kCorner[i][0], s2 = kCorner[i][1], s3 = kCorner[i][2];
          const double d1 = s1 * (1 + s2 * x2) * (1 + s3 * x3) / 8.0;
          const double d2 = (1 + s1 * x1) * s2 * (1 + s3 * x3) / 8.0;
          const double d3 = (1 + s1 * x1) * (1 + s2 * x2) * s3 / 8.0;
          qx[i] = d1 * Ji(0, 0) + d2 * Ji(1, 0) + d3 * Ji(2, 0);
          qy[i] = d1 * Ji(0, 1) + d2 * Ji(1, 1) + d3 * Ji(2, 1);
          qz[i] = d1 * Ji(0, 2) + d2 * Ji(1, 2) + d3 * Ji(2, 2);
        }

        for (int i = 0; i < 8; ++i) {
          // D·B_i (6×3), only the entries that are not structurally zero.
          const double m00 = U * qx[i], m01 = V * qy[i], m02 = V * qz[i];
          const double m10 = V * qx[i], m11 = U * qy[i], m12 = V * qz[i];
          const double m20 = V * qx[i], m21 = V * qy[i], m22 = U * qz[i];
          const double m30 = W * qy[i], m31 = W * qx[i];
          const double m41 = W * qz[i], m42 = W * qy[i];
          const double m50 = W * qz[i], m52 = W * qx[i];
          for (int j = i; j < 8; ++j) {
            // k = B_jᵀ·(D·B_i), scaled by detJ before accumulation; it enters
            // block (i, j) transposed.
            double k[3][3];
            k[0][0] = qx[j] * m00 + qy[j] * m30 + qz[j] * m50;
            k[0][1] = qx[j] * m01 + qy[j] * m31;
            k[0][2] = qx[j] * m02 + qz[j] * m52;
            k[1][0] = qy[j] * m10 + qx[j] * m30;
            k[1][1] = qy[j] * m11 + qx[j] * m31 + qz[j] * m41;
            k[1][2] = qy[j] * m12 + qz[j] * m42;
            k[2][0] = qz[j] * m20 + qx[j] * m50;
            k[2][1] = qz[j] * m21 + qy[j] * m41;
            k[2][2] = qz[j] * m22 + qy[j] * m42 + qx[j] * m52;
            for (int m = 0; m < 3; ++m)
              for (int l = 0; l < 3; ++l) K(3 * i + m, 3 * j + l) += k[l][m] * detJ;
          }
        }
      }

  // Only the upper triangle was integrated: copy it down (this also replaces
  // the lower half of the diagonal blocks).
  for (int i = 0; i < 24; ++i)
    for (int j = i + 1; j < 24; ++j) K(j, i) = K(i, j);
  for (int i = 0; i < 24 * 24; ++i) K.data()[i] *= coef;
  return info;
}

Mat3 hexa_frame_large(const std::array<Vec3, 8>& n) {
  Vec3 ex = edge_x(n);
  const Vec3 w = edge_y(n);
  normalize3(ex);
  Vec3 ez = cross3(ex, w);
  normalize3(ez);
  const Vec3 ey = cross3(ez, ex);
  Mat3 R;
  R.row(0) = ex.transpose();
  R.row(1) = ey.transpose();
  R.row(2) = ez.transpose();
  return R;
}

Mat3 hexa_frame_polar(const std::array<Vec3, 8>& n) {
  Mat3 A;
  A.row(0) = edge_x(n).transpose();
  A.row(1) = edge_y(n).transpose();
  A.row(2) = edge_z(n).transpose();
  return polar_rotation(A);
}

namespace {

Mat3 element_frame(HexaMethod m, const std::array<Vec3, 8>& n) {
  switch (m) {
    case HexaMethod::large: return hexa_frame_large(n);
    case HexaMethod::polar: return hexa_frame_polar(n);
    case HexaMethod::small: break;
  }
  return Mat3::Identity();
}

}  // namespace

std::vector<HexaIssue> HexaFEM::init(std::span<const Vec3> X0, std::span<const std::array<int, 8>> elems,
                                     std::span<const double> E, std::span<const double> nu, HexaMethod m,
                                     std::span<const double> stiffness_coef) {
  touch_stiffness();
  std::vector<HexaIssue> issues;
  method = m;
  potential_energy = 0;
  const std::size_t ne = elems.size();
  const std::size_t np = X0.size();
  auto clear_all = [&] {
    hexa.clear(), rest.clear(), R0.clear(), R.clear(), K.clear();
    material.clear(), coef.clear(), active.clear(), node_hexa_count.assign(np, 0);
  };
  if (E.size() < ne || nu.size() < ne) {
    issues.push_back({-1, true,
                      "youngModulus/poissonRatio must be broadcast to one value per hexahedron (" +
                          std::to_string(ne) + " hexahedra, " + std::to_string(E.size()) + " E, " +
                          std::to_string(nu.size()) + " nu)"});
    clear_all();
    return issues;
  }
  if (!stiffness_coef.empty() && stiffness_coef.size() < ne) {
    issues.push_back({-1, true, "stiffness coefficients: " + std::to_string(stiffness_coef.size()) + " for " +
                                    std::to_string(ne) + " hexahedra"});
    clear_all();
    return issues;
  }

  hexa = std::vector<std::array<int, 8>>(elems.begin(), elems.end());  // safe even if elems views hexa
  rest.assign(ne, {});
  R0.assign(ne, Mat3::Identity());
  R.assign(ne, Mat3::Identity());
  K.assign(ne, Mat24::Zero());
  material.assign(ne, {});
  coef.assign(ne, 1.0);
  active.assign(ne, 1);
  node_hexa_count.assign(np, 0);

  for (std::size_t e = 0; e < ne; ++e) {
    const int ei = static_cast<int>(e);
    const auto& h = hexa[e];
    bool in_range = true;
    for (int k = 0; k < 8; ++k)
      if (h[k] < 0 || static_cast<std::size_t>(h[k]) >= np) {
        issues.push_back({ei, true,
                          "node " + std::to_string(k) + " index " + std::to_string(h[k]) + " out of range (" +
                              std::to_string(np) + " points)"});
        in_range = false;
        break;
      }
    if (!in_range) {
      active[e] = 0;
      continue;
    }
    for (int k = 0; k < 8; ++k) ++node_hexa_count[h[k]];

    std::array<Vec3, 8> nodes;
    for (int k = 0; k < 8; ++k) nodes[k] = X0[h[k]];
    R0[e] = element_frame(m, nodes);
    R[e] = R0[e];
    for (int k = 0; k < 8; ++k) rest[e][k] = mul(R0[e], nodes[k]);
    material[e] = hexa_material(E[e], nu[e]);
    if (!stiffness_coef.empty()) coef[e] = stiffness_coef[e];

    const HexaJacobianInfo info = hexa_element_stiffness(rest[e], material[e], coef[e], K[e]);
    if (info.singular) {
      issues.push_back({ei, true,
                        "degenerate hexahedron (zero Jacobian determinant): flat, collapsed or badly numbered"});
    } else if (!R0[e].allFinite() || !all_finite(K[e])) {
      issues.push_back({ei, true, "non-finite stiffness or frame (check E, nu and positions)"});
    } else if (info.min_det < 0) {
      issues.push_back({ei, false,
                        "inverted hexahedron (negative Jacobian determinant): its stiffness is not positive"});
    }
  }
  build_incidence(X0.size());
  return issues;
}

void HexaFEM::element_force(std::size_t e, std::span<const Vec3> x, Vec3* out, double& energy) {
  std::array<Vec3, 8> nodes;
  std::array<Vec3, 8> deformed;
  double D[24], F[24];
  const auto& h = hexa[e];
  for (int k = 0; k < 8; ++k) nodes[k] = x[h[k]];
  Mat3& Re = R[e];
  if (method == HexaMethod::small) {
    deformed = nodes;
  } else {
    Re = element_frame(method, nodes);
    for (int k = 0; k < 8; ++k) deformed[k] = mul(Re, nodes[k]);
  }
  // Absolute displacement in the element frame (no centering).
  const auto& r = rest[e];
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c) D[3 * k + c] = r[k][c] - deformed[k][c];

  if (update_stiffness) hexa_element_stiffness(deformed, material[e], coef[e], K[e]);
  mul24_clones(K[e].data(), D, F);

  for (int k = 0; k < 8; ++k)
    out[k] = method == HexaMethod::small ? Vec3(F[3 * k], F[3 * k + 1], F[3 * k + 2])
                                         : mul_t(Re, F[3 * k], F[3 * k + 1], F[3 * k + 2]);
  // SOFA accumulates Σ F_k·(−D_k) node by node, then divides by −2.
  for (int k = 0; k < 8; ++k)
    energy += F[3 * k] * -D[3 * k] + F[3 * k + 1] * -D[3 * k + 1] + F[3 * k + 2] * -D[3 * k + 2];
}

void HexaFEM::element_dforce(std::size_t e, std::span<const Vec3> dx, double kfactor, Vec3* out) const {
  if (!k_index.empty()) {
    alignas(32) double v[3][8], o[3][8];
    const auto& h = hexa[e];
    for (int k = 0; k < 8; ++k) {
      const Vec3& d = dx[h[k]];
      v[0][k] = d[0], v[1][k] = d[1], v[2][k] = d[2];
    }
    hexa_dforce_soa(k_shared[k_index[e]].data(), R[e], method != HexaMethod::small, v, kfactor, o);
    for (int k = 0; k < 8; ++k) out[k] = Vec3(o[0][k], o[1][k], o[2][k]);
    return;
  }
  double X[24], F[24];
  const bool rotate = method != HexaMethod::small;  // small: R = I, product skipped (exact)
  const auto& h = hexa[e];
  const Mat3& Re = R[e];
  for (int k = 0; k < 8; ++k) {
    const Vec3 v = rotate ? mul(Re, dx[h[k]]) : dx[h[k]];
    X[3 * k] = v[0];
    X[3 * k + 1] = v[1];
    X[3 * k + 2] = v[2];
  }
  mul24_clones(K[e].data(), X, F);
  for (int k = 0; k < 8; ++k) {
    const Vec3 t = rotate ? mul_t(Re, F[3 * k], F[3 * k + 1], F[3 * k + 2]) : Vec3(F[3 * k], F[3 * k + 1], F[3 * k + 2]);
    out[k] = Vec3(t[0] * kfactor, t[1] * kfactor, t[2] * kfactor);
  }
}

bool HexaFEM::parallel() const {
  return hexa.size() >= kParallelMinElements &&
         tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1 &&
         tbb::this_task_arena::max_concurrency() > 1;
}

void HexaFEM::build_incidence(std::size_t n_points) {
  // For each point, the (element, corner) slots touching it, in element order:
  // gathering them in this order adds contributions exactly as the sequential loop does.
  node_start.assign(n_points + 1, 0);
  for (std::size_t e = 0; e < hexa.size(); ++e)
    if (active[e])
      for (int k = 0; k < 8; ++k) ++node_start[hexa[e][k] + 1];
  for (std::size_t p = 0; p < n_points; ++p) node_start[p + 1] += node_start[p];
  node_slot.assign(node_start[n_points], 0);
  std::vector<std::uint32_t> fill(node_start.begin(), node_start.end() - 1);
  for (std::size_t e = 0; e < hexa.size(); ++e)
    if (active[e])
      for (int k = 0; k < 8; ++k) node_slot[fill[hexa[e][k]]++] = static_cast<std::uint32_t>(e * 8 + k);
  scratch.assign(hexa.size(), {});
  element_energy.assign(hexa.size(), 0.0);
}

void HexaFEM::add_force(std::span<const Vec3> x, std::span<Vec3> f) {
  if (update_stiffness) touch_stiffness();
  double energy = 0;
  if (!parallel()) {
    Vec3 out[8];
    for (std::size_t e = 0; e < hexa.size(); ++e) {
      if (!active[e]) continue;
      element_force(e, x, out, energy);
      const auto& h = hexa[e];
      for (int k = 0; k < 8; ++k) {
        Vec3& fk = f[h[k]];
        fk[0] += out[k][0];
        fk[1] += out[k][1];
        fk[2] += out[k][2];
      }
    }
  } else {
    // Elements in parallel into per-element slots, then points in parallel,
    // each summing its slots in element order: identical to the sequential result.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, hexa.size(), 256), [&](const auto& range) {
      for (std::size_t e = range.begin(); e != range.end(); ++e) {
        element_energy[e] = 0;
        if (active[e]) element_force(e, x, scratch[e].data(), element_energy[e]);
      }
    });
    gather(f, +1.0);
    for (std::size_t e = 0; e < hexa.size(); ++e) energy += element_energy[e];
  }
  potential_energy = energy / -2.0;
}

void HexaFEM::refresh_shared_stiffness() const {
  if (shared_gen == k_gen && (k_index.empty() || k_index.size() == K.size())) return;
  shared_gen = k_gen;
  k_index.clear();
  k_shared.clear();
  k_rep.clear();
  if (update_stiffness || K.empty()) return;
  // Group bitwise-equal matrices (hash of the bytes, then memcmp).
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> groups;
  std::vector<std::uint32_t> index(K.size());
  for (std::size_t e = 0; e < K.size(); ++e) {
    std::uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < 24 * 24; ++i) {
      std::uint64_t w;
      std::memcpy(&w, K[e].data() + i, sizeof w);
      h = (h ^ w) * 1099511628211ull;
    }
    auto& g = groups[h];
    std::uint32_t found = UINT32_MAX;
    for (std::uint32_t u : g)
      if (std::memcmp(K[k_rep[u]].data(), K[e].data(), sizeof(double) * 24 * 24) == 0) {
        found = u;
        break;
      }
    if (found == UINT32_MAX) {
      if (k_shared.size() * 4 >= K.size() + 64) {  // hardly shared: keep K
        k_shared.clear();
        k_rep.clear();
        return;
      }
      found = static_cast<std::uint32_t>(k_shared.size());
      auto& kp = k_shared.emplace_back();
      const double* k = K[e].data();
      for (int c = 0; c < 24; ++c)
        for (int rp = 0; rp < 24; ++rp) kp[24 * c + rp] = k[24 * c + 3 * (rp % 8) + rp / 8];
      k_rep.push_back(static_cast<std::uint32_t>(e));
      g.push_back(found);
    }
    index[e] = found;
  }
  k_index = std::move(index);
}

void HexaFEM::add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) const {
  refresh_shared_stiffness();
  if (!parallel()) {
    Vec3 out[8];
    for (std::size_t e = 0; e < hexa.size(); ++e) {
      if (!active[e]) continue;
      element_dforce(e, dx, kfactor, out);
      const auto& h = hexa[e];
      for (int k = 0; k < 8; ++k) {
        Vec3& d = df[h[k]];
        d[0] -= out[k][0];
        d[1] -= out[k][1];
        d[2] -= out[k][2];
      }
    }
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, hexa.size(), 256), [&](const auto& range) {
    for (std::size_t e = range.begin(); e != range.end(); ++e)
      if (active[e]) element_dforce(e, dx, kfactor, scratch[e].data());
  });
  gather(df, -1.0);
}

void HexaFEM::gather(std::span<Vec3> f, double sign) const {
  const std::size_t n = std::min(f.size(), node_start.empty() ? 0 : node_start.size() - 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& range) {
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      Vec3& fp = f[p];
      for (std::uint32_t s = node_start[p]; s < node_start[p + 1]; ++s) {
        const Vec3& c = scratch[node_slot[s] / 8][node_slot[s] % 8];
        if (sign > 0) {
          fp[0] += c[0], fp[1] += c[1], fp[2] += c[2];
        } else {
          fp[0] -= c[0], fp[1] -= c[1], fp[2] -= c[2];
        }
      }
    }
  });
}

void HexaFEM::node_rotations(std::span<Mat3> out) const {
  for (std::size_t p = 0; p < out.size(); ++p) out[p] = Mat3::Identity();
  for (std::size_t e = 0; e < hexa.size(); ++e) {
    if (!active[e]) continue;
    const Mat3& A = R[e];
    const Mat3& B = R0[e];  // used transposed
    Mat3 prod;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) prod(i, j) = A(i, 0) * B(j, 0) + A(i, 1) * B(j, 1) + A(i, 2) * B(j, 2);
    for (int k = 0; k < 8; ++k) {
      Mat3& o = out[hexa[e][k]];
      for (int i = 0; i < 9; ++i) o.data()[i] += prod.data()[i];
    }
  }
  for (std::size_t p = 0; p < out.size(); ++p) {
    const int count = p < node_hexa_count.size() ? node_hexa_count[p] : 0;
    if (count == 0) continue;  // identity (SOFA: division by zero)
    const double n = static_cast<double>(count);
    for (int i = 0; i < 9; ++i) out[p].data()[i] /= n;
    out[p] = polar_rotation(out[p]);
  }
}

}  // namespace sinew::fem
