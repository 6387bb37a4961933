#include "forcefield/fem/tetra_fem.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <Eigen/Eigenvalues>

#include "core/topology_change.h"
#include "forcefield/fem/sofa_mat3.h"
#include "math/decompose.h"
#include "math/target_clones.h"

namespace sinew::fem {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

inline Vec3 sub(const Vec3& a, const Vec3& b) { return Vec3(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
// SOFA's normalize: divide by the norm when it is above DBL_EPSILON.
inline Vec3 normalized(Vec3 a) {
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (n > kEps) {
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
  }
  return a;
}
// Plain 3×3 product (SOFA's Mat operator*).
inline Mat3 mul(const Mat3& A, const Mat3& B) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = A(i, 0) * B(0, j) + A(i, 1) * B(1, j) + A(i, 2) * B(2, j);
  return r;
}

// Cofactor expression of SOFA's peudo_determinant_for_coef for the 2×3 matrix
// rows (u0 u1 u2), (v0 v1 v2).
inline double pd(double u0, double u1, double u2, double v0, double v1, double v2) {
  return u1 * v2 - v1 * u2 - u0 * v2 + v0 * u2 + u0 * v1 - v0 * u1;
}

// Edge rows of a tetrahedron: (b−a, c−a, d−a).
inline Mat3 edge_rows(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Mat3 A;
  const Vec3 e1 = sub(b, a), e2 = sub(c, a), e3 = sub(d, a);
  for (int k = 0; k < 3; ++k) {
    A(0, k) = e1[k];
    A(1, k) = e2[k];
    A(2, k) = e3[k];
  }
  return A;
}

// Strain Jᵀ·Δ with SOFA's zero pattern and order.
inline void strain(const TetraJ& J, const double* D, double* e) {
  e[0] = J(0, 0) * D[0] + J(3, 0) * D[3] + J(6, 0) * D[6] + J(9, 0) * D[9];
  e[1] = J(1, 1) * D[1] + J(4, 1) * D[4] + J(7, 1) * D[7] + J(10, 1) * D[10];
  e[2] = J(2, 2) * D[2] + J(5, 2) * D[5] + J(8, 2) * D[8] + J(11, 2) * D[11];
  e[3] = J(0, 3) * D[0] + J(1, 3) * D[1] + J(3, 3) * D[3] + J(4, 3) * D[4] + J(6, 3) * D[6] + J(7, 3) * D[7] +
         J(9, 3) * D[9] + J(10, 3) * D[10];
  e[4] = J(1, 4) * D[1] + J(2, 4) * D[2] + J(4, 4) * D[4] + J(5, 4) * D[5] + J(7, 4) * D[7] + J(8, 4) * D[8] +
         J(10, 4) * D[10] + J(11, 4) * D[11];
  e[5] = J(0, 5) * D[0] + J(2, 5) * D[2] + J(3, 5) * D[3] + J(5, 5) * D[5] + J(6, 5) * D[6] + J(8, 5) * D[8] +
         J(9, 5) * D[9] + J(11, 5) * D[11];
}

inline void stress(const TetraMaterial& K, const double* e, double* s) {
  s[0] = K.d * e[0] + K.o * e[1] + K.o * e[2];
  s[1] = K.o * e[0] + K.d * e[1] + K.o * e[2];
  s[2] = K.o * e[0] + K.o * e[1] + K.d * e[2];
  s[3] = K.s * e[3];
  s[4] = K.s * e[4];
  s[5] = K.s * e[5];
}

inline void nodal(const TetraJ& J, const double* s, double* F) {
  for (int k = 0; k < 4; ++k) {
    const int r = 3 * k;
    F[r + 0] = J(r + 0, 0) * s[0] + J(r + 0, 3) * s[3] + J(r + 0, 5) * s[5];
    F[r + 1] = J(r + 1, 1) * s[1] + J(r + 1, 3) * s[3] + J(r + 1, 4) * s[4];
    F[r + 2] = J(r + 2, 2) * s[2] + J(r + 2, 4) * s[4] + J(r + 2, 5) * s[5];
  }
}

// SOFA's polarDecomposition_stable (robust SVD: eigenvectors of FᵀF with V
// made a rotation; U = F·V·S⁻¹ with degenerate columns rebuilt). The
// eigen-solver differs from SOFA's iterative Jacobi, so results may differ
// at round-off in this (degenerate element) path.
Mat3 polar_stable(const Mat3& F) {
  Mat3 FtF;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) FtF(i, j) = F(0, i) * F(0, j) + F(1, i) * F(1, j) + F(2, i) * F(2, j);
  Eigen::SelfAdjointEigenSolver<Mat3> es(FtF);
  Mat3 V = es.eigenvectors();
  Vec3 S = es.eigenvalues();
  if (det3(V) < 0)
    for (int i = 0; i < 3; ++i) V(i, 0) = -V(i, 0);
  int degenerated = 0;
  Vec3 S1;
  const double zero_tol = 1e-8;
  for (int i = 0; i < 3; ++i) {
    if (S[i] < zero_tol) {
      ++degenerated;
      S[i] = 0;
      S1[i] = 1;
    } else {
      S[i] = std::sqrt(S[i]);
      S1[i] = 1.0 / S[i];
    }
  }
  // eigenvalues are sorted ascending by Eigen: order = 0, 1, 2
  Mat3 U;
  if (degenerated == 3) {
    U.setIdentity();
  } else {
    Mat3 VS = V;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) VS(i, j) = V(i, j) * S1[j];
    U = mul(F, VS);
    if (degenerated == 1) {
      const Vec3 c = cross3(Vec3(U(0, 1), U(1, 1), U(2, 1)), Vec3(U(0, 2), U(1, 2), U(2, 2)));
      for (int i = 0; i < 3; ++i) U(i, 0) = c[i];
    } else if (degenerated == 2) {
      Vec3 e2(U(0, 2), U(1, 2), U(2, 2));
      e2 = normalized(e2);
      Vec3 e0 = std::fabs(e2[0]) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
      Vec3 e1 = normalized(cross3(e2, e0));
      e0 = cross3(e1, e2);
      for (int i = 0; i < 3; ++i) {
        U(i, 0) = e0[i];
        U(i, 1) = e1[i];
        U(i, 2) = e2[i];
      }
    }
  }
  Mat3 Q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Q(i, j) = U(i, 0) * V(j, 0) + U(i, 1) * V(j, 1) + U(i, 2) * V(j, 2);
  return Q;
}

}  // namespace

TetraMaterial tetra_material(double young, double poisson, double volume) {
  const double off = poisson / (1 - poisson);
  const double shear = (1 - 2 * poisson) / (2 * (1 - poisson));
  const double scale = (young * (1 - poisson)) / ((1 + poisson) * (1 - 2 * poisson));
  const double div = volume * 36;
  TetraMaterial K;
  K.d = (1.0 * scale) / div;
  K.o = (off * scale) / div;
  K.s = (shear * scale) / div;
  return K;
}

double tetra_signed_volume(const Vec3& n0, const Vec3& n1, const Vec3& n2, const Vec3& n3) {
  const Vec3 a = sub(n1, n0), b = sub(n2, n0), c = sub(n3, n0);
  const Vec3 x = cross3(a, b);
  return (x[0] * c[0] + x[1] * c[1] + x[2] * c[2]) / 6.0;
}

void tetra_strain_displacement(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, TetraJ& J) {
  J = TetraJ{};
  // Node k with the three others (cyclic); SOFA fills M row by row, first with
  // (y, z), then (x, z), then (x, y), reusing the previous rows.
  auto fill = [&](int k, const Vec3& p, const Vec3& q, const Vec3& r, double sign) {
    const int row = 3 * k;
    // pd(y; z)
    double v = pd(p[1], q[1], r[1], p[2], q[2], r[2]);
    const double a0 = sign < 0 ? -v : v;
    J(row + 0, 0) = J(row + 1, 3) = J(row + 2, 5) = a0;
    v = pd(p[0], q[0], r[0], p[2], q[2], r[2]);
    const double a1 = sign < 0 ? v : -v;
    J(row + 0, 3) = J(row + 1, 1) = J(row + 2, 4) = a1;
    v = pd(p[0], q[0], r[0], p[1], q[1], r[1]);
    const double a2 = sign < 0 ? -v : v;
    J(row + 0, 5) = J(row + 1, 4) = J(row + 2, 2) = a2;
  };
  fill(0, b, c, d, -1.0);
  fill(1, c, d, a, +1.0);
  fill(2, d, a, b, -1.0);
  fill(3, a, b, c, +1.0);
}

Mat3 tetra_frame_large(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ex = normalized(sub(b, a));
  Vec3 ey = sub(c, a);
  const Vec3 ez = normalized(cross3(ex, ey));
  ey = cross3(ez, ex);
  Mat3 r;
  for (int k = 0; k < 3; ++k) {
    r(0, k) = ex[k];
    r(1, k) = ey[k];
    r(2, k) = ez[k];
  }
  return r;
}

void tetra_force(const TetraJ& J, const TetraMaterial& K, const double D[12], double F[12]) {
  double e[6], s[6];
  strain(J, D, e);
  stress(K, e, s);
  nodal(J, s, F);
}

void tetra_force_plastic(const TetraJ& J, const TetraMaterial& K, const double D[12], const TetraPlasticity& p,
                         double ps[6], double F[12]) {
  double e[6], s[6];
  strain(J, D, e);
  if (p.max_threshold > 0) {
    double el[6];
    for (int i = 0; i < 6; ++i) el[i] = e[i] - ps[i];
    double n2 = el[0] * el[0];
    for (int i = 1; i < 6; ++i) n2 += el[i] * el[i];
    if (n2 > p.yield_threshold * p.yield_threshold)
      for (int i = 0; i < 6; ++i) ps[i] += p.creep * el[i];
    double pn2 = ps[0] * ps[0];
    for (int i = 1; i < 6; ++i) pn2 += ps[i] * ps[i];
    if (pn2 > p.max_threshold * p.max_threshold) {
      const double f = p.max_threshold / std::sqrt(pn2);
      for (int i = 0; i < 6; ++i) ps[i] *= f;
    }
    for (int i = 0; i < 6; ++i) e[i] -= ps[i];
  }
  stress(K, e, s);
  nodal(J, s, F);
}

void tetra_force_scaled(const TetraJ& J, const TetraMaterial& K, const double D[12], double fact, double F[12]) {
  double e[6], s[6];
  strain(J, D, e);
  stress(K, e, s);
  for (int i = 0; i < 6; ++i) s[i] *= fact;
  nodal(J, s, F);
}

void tetra_jkjt(const TetraJ& J, const TetraMaterial& K, Mat12& out) {
  double Km[6][6] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Km[i][j] = i == j ? K.d : K.o;
  Km[3][3] = Km[4][4] = Km[5][5] = K.s;
  double JK[12][6];
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 6; ++j) {
      double r = 0;
      for (int k = 0; k < 6; ++k) r += J(i, k) * Km[k][j];
      JK[i][j] = r;
    }
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      double r = 0;
      for (int k = 0; k < 6; ++k) r += JK[i][k] * J(j, k);
      out(i, j) = r;
    }
}

void tetra_rotated_stiffness(const Mat12& JKJt, const Mat3& rot, Mat12& S, Mat12& SR) {
  for (int i = 0; i < 12; ++i) {
    const int bi = (i / 3) * 3, li = i % 3;
    for (int j = 0; j < 12; ++j)
      S(i, j) = rot(li, 0) * JKJt(bi, j) + rot(li, 1) * JKJt(bi + 1, j) + rot(li, 2) * JKJt(bi + 2, j);
  }
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const int bj = (j / 3) * 3, lj = j % 3;
      SR(i, j) = S(i, bj) * rot(lj, 0) + S(i, bj + 1) * rot(lj, 1) + S(i, bj + 2) * rot(lj, 2);
    }
}

std::vector<TetraIssue> TetraFEM::init(std::span<const Vec3> X, std::span<const std::array<int, 4>> tets,
                                       std::span<const double> E, std::span<const double> nu, TetraMethod m) {
  std::vector<TetraIssue> issues;
  touch(true);
  method = m;
  const std::size_t ne = tets.size();
  tetra.assign(tets.begin(), tets.end());
  X0.assign(X.begin(), X.end());
  if (E.size() != ne || nu.size() != ne) {
    issues.push_back({-1, true, "material arrays do not match the number of elements"});
    tetra.clear();
    return issues;
  }
  J.assign(ne, TetraJ{});
  K.assign(ne, TetraMaterial{});
  rot.assign(ne, Mat3::Identity());
  rot0.assign(ne, Mat3::Identity());
  rest.assign(ne, {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()});
  plastic.assign(ne, {0, 0, 0, 0, 0, 0});
  T0.assign(m == TetraMethod::svd ? ne : 0, Mat3::Identity());
  rest_volume = 0;
  const std::size_t np = X.size();
  bool index_out_of_range = false;
  int first_inverted = -1;
  std::size_t n_inverted = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    const auto& t = tets[e];
    bool bad = false;
    for (int k = 0; k < 4; ++k)
      if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= np) bad = true;
    if (bad) {
      issues.push_back({static_cast<int>(e), true,
                        "node index out of range (the state has " + std::to_string(np) + " points)"});
      index_out_of_range = true;
      continue;
    }
    const Vec3 &a = X[t[0]], &b = X[t[1]], &c = X[t[2]], &d = X[t[3]];
    const double signed_vol = tetra_signed_volume(a, b, c, d);
    const double vol = signed_vol < 0 ? -signed_vol : signed_vol;
    rest_volume += vol;
    if (!(vol > 0) || !std::isfinite(vol)) {
      issues.push_back({static_cast<int>(e), true, "degenerate element (zero rest volume)"});
      continue;
    }
    if (signed_vol < 0 && n_inverted++ == 0) first_inverted = static_cast<int>(e);
    K[e] = tetra_material(E[e], nu[e], vol);
    switch (m) {
      case TetraMethod::small:
        tetra_strain_displacement(a, b, c, d, J[e]);
        break;
      case TetraMethod::large: {
        const Mat3 R = tetra_frame_large(a, b, c);
        rot0[e] = R.transpose();
        rot[e] = rot0[e];
        auto& q = rest[e];
        q[0] = mul(R, a);
        q[1] = mul(R, b);
        q[2] = mul(R, c);
        q[3] = mul(R, d);
        for (int k = 1; k < 4; ++k) q[k] = sub(q[k], q[0]);
        q[0] = Vec3::Zero();
        tetra_strain_displacement(q[0], q[1], q[2], q[3], J[e]);
        break;
      }
      case TetraMethod::polar:
      case TetraMethod::svd: {
        const Mat3 A = edge_rows(a, b, c, d);
        if (m == TetraMethod::svd) {
          if (!invert3(A, det3(A), T0[e])) {  // SOFA's invertMatrix
            issues.push_back({static_cast<int>(e), true, "degenerate element (singular rest edges)"});
            continue;
          }
        }
        const Mat3 R = polar_rotation(A);
        rot0[e] = R.transpose();
        rot[e] = rot0[e];
        auto& q = rest[e];
        q[0] = mul(R, a);
        q[1] = mul(R, b);
        q[2] = mul(R, c);
        q[3] = mul(R, d);
        tetra_strain_displacement(q[0], q[1], q[2], q[3], J[e]);
        break;
      }
    }
  }
  // Inverted rest elements work (SOFA uses |volume|) but usually mean a badly ordered mesh: say so once
  // (not for SOFA's own split of hexahedra, which yields inverted tetrahedra by construction).
  if (n_inverted > 0 && !split_from_hexahedra)
    issues.push_back({first_inverted, false,
                      "inverted element (negative rest volume: vertices in the wrong order)" +
                          (n_inverted > 1 ? "; " + std::to_string(n_inverted) + " inverted elements in all"
                                          : std::string())});
  // Elements with indices beyond the state are refused: nothing may index the
  // state with them (the incidence lists would be written out of bounds).
  if (index_out_of_range) tetra.clear();
  build_incidence(X.size());
  return issues;
}

void TetraFEM::remove_elements(const std::vector<unsigned>& decreasing) {
  remove_swap_last(tetra, decreasing);
  remove_swap_last(J, decreasing);
  remove_swap_last(K, decreasing);
  remove_swap_last(rot, decreasing);
  remove_swap_last(rot0, decreasing);
  remove_swap_last(rest, decreasing);
  remove_swap_last(plastic, decreasing);
  remove_swap_last(T0, decreasing);
  // Kept per element only within one step or for outputs: rebuilt on next use.
  sr_cache.clear();
  jkjt_cache.clear();
  touch(true);
}

void TetraFEM::remove_points(const std::vector<unsigned>& decreasing) {
  std::size_t n = X0.size();
  for (unsigned i : decreasing) {
    if (i >= n) continue;
    const auto last = static_cast<int>(n - 1);
    if (static_cast<int>(i) != last)
      for (auto& t : tetra)
        for (int& v : t)
          if (v == last) v = static_cast<int>(i);
    --n;
  }
  remove_swap_last(X0, decreasing);
  touch(true);
}

void TetraFEM::end_change() {
  rest_volume = 0;
  for (const auto& t : tetra) rest_volume += std::abs(tetra_signed_volume(X0[t[0]], X0[t[1]], X0[t[2]], X0[t[3]]));
  build_incidence(X0.size());
}

void TetraFEM::reset_plasticity() {
  for (auto& p : plastic) p = {0, 0, 0, 0, 0, 0};
}

bool TetraFEM::forces_supported() const {
  if (assembling && (method == TetraMethod::polar || method == TetraMethod::svd)) return false;
  if (assembling && plasticity.max_threshold > 0) return false;
  return true;
}

template <class Sink>
void TetraFEM::force_range(std::size_t e_begin, std::size_t e_end, std::span<const Vec3> x, Sink& sink) {
  const bool plastic_on = plasticity.max_threshold > 0;
  // SOFA: svd with computeGlobalMatrix returns before anything; small with
  // plasticity and computeGlobalMatrix adds nothing.
  double D[12], F[12];
  Mat12 jkjt, S, SR;
  for (std::size_t e = e_begin; e < e_end; ++e) {
    const auto& t = tetra[e];
    const int a = t[0], b = t[1], c = t[2], d = t[3];
    switch (method) {
      case TetraMethod::small: {
        D[0] = D[1] = D[2] = 0;
        const int idx[3] = {b, c, d};
        for (int k = 0; k < 3; ++k)
          for (int i = 0; i < 3; ++i)
            D[3 + 3 * k + i] = X0[idx[k]][i] - X0[a][i] - x[idx[k]][i] + x[a][i];
        if (!assembling) {
          tetra_force_plastic(J[e], K[e], D, plasticity, plastic[e].data(), F);
        } else {
          tetra_jkjt(J[e], K[e], jkjt);
          tetra_rotated_stiffness(jkjt, Mat3::Identity(), S, SR);
          if (sr_cache.size() == tetra.size()) sr_cache[e] = SR;
          for (int i = 0; i < 12; ++i) {
            double r = 0;
            for (int j = 0; j < 12; ++j) r += S(i, j) * D[j];
            F[i] = r;
          }
        }
        for (int k = 0; k < 4; ++k) sink.add(e, k, t[k], F[3 * k], F[3 * k + 1], F[3 * k + 2]);
        continue;
      }
      case TetraMethod::large: {
        const Mat3 R = tetra_frame_large(x[a], x[b], x[c]);
        rot[e] = R.transpose();
        Vec3 p[4];
        for (int k = 0; k < 4; ++k) p[k] = mul(R, x[t[k]]);
        p[1][0] -= p[0][0];
        p[2][0] -= p[0][0];
        p[2][1] -= p[0][1];
        p[3] = sub(p[3], p[0]);
        const auto& q = rest[e];
        D[0] = D[1] = D[2] = 0;
        D[3] = q[1][0] - p[1][0];
        D[4] = D[5] = 0;
        D[6] = q[2][0] - p[2][0];
        D[7] = q[2][1] - p[2][1];
        D[8] = 0;
        D[9] = q[3][0] - p[3][0];
        D[10] = q[3][1] - p[3][1];
        D[11] = q[3][2] - p[3][2];
        if (update_stiffness_matrix) {
          TetraJ& Je = J[e];
          Je(0, 0) = (-p[2][1] * p[3][2]);
          Je(1, 1) = (p[2][0] * p[3][2] - p[1][0] * p[3][2]);
          Je(2, 2) = (p[2][1] * p[3][0] - p[2][0] * p[3][1] + p[1][0] * p[3][1] - p[1][0] * p[2][1]);
          Je(3, 0) = (p[2][1] * p[3][2]);
          Je(4, 1) = (-p[2][0] * p[3][2]);
          Je(5, 2) = (-p[2][1] * p[3][0] + p[2][0] * p[3][1]);
          Je(7, 1) = (p[1][0] * p[3][2]);
          Je(8, 2) = (-p[1][0] * p[3][1]);
          Je(11, 2) = (p[1][0] * p[2][1]);
          if (symmetric_update) {
            Je(1, 3) = Je(2, 5) = Je(0, 0);
            Je(0, 3) = Je(2, 4) = Je(1, 1);
            Je(0, 5) = Je(1, 4) = Je(2, 2);
            Je(4, 3) = Je(5, 5) = Je(3, 0);
            Je(3, 3) = Je(5, 4) = Je(4, 1);
            Je(3, 5) = Je(4, 4) = Je(5, 2);
            Je(6, 3) = Je(8, 4) = Je(7, 1);
            Je(6, 5) = Je(7, 4) = Je(8, 2);
            Je(9, 5) = Je(10, 4) = Je(11, 2);
          }
        }
        if (!assembling) {
          tetra_force_plastic(J[e], K[e], D, plasticity, plastic[e].data(), F);
          const Mat3& r = rot[e];
          for (int k = 0; k < 4; ++k) {
            const Vec3 fk = mul(r, Vec3(F[3 * k], F[3 * k + 1], F[3 * k + 2]));
            sink.add(e, k, t[k], fk[0], fk[1], fk[2]);
          }
        } else if (!plastic_on) {
          J[e](6, 0) = 0;
          J[e](9, 0) = 0;
          J[e](10, 1) = 0;
          tetra_jkjt(J[e], K[e], jkjt);
          tetra_rotated_stiffness(jkjt, rot[e], S, SR);
          if (sr_cache.size() == tetra.size()) sr_cache[e] = SR;
          for (int i = 0; i < 12; ++i) {
            double r = 0;
            for (int j = 0; j < 12; ++j) r += S(i, j) * D[j];
            F[i] = r;
          }
          for (int k = 0; k < 4; ++k) sink.add(e, k, t[k], F[3 * k], F[3 * k + 1], F[3 * k + 2]);
        }
        continue;
      }
      case TetraMethod::polar:
      case TetraMethod::svd: {
        const Mat3 A = edge_rows(x[a], x[b], x[c], x[d]);
        Mat3 R;
        if (method == TetraMethod::svd) {
          const Mat3 Fd = mul(A, T0[e]);
          if (det3(Fd) < 1e-6) {
            // R = polarStable(F) · R0 (rot0 = R0ᵀ, so multTransposed(rot0) = ·R0)
            const Mat3 Q = polar_stable(Fd);
            R = mul(Q, Mat3(rot0[e].transpose()));
          } else {
            R = polar_rotation(A);
          }
        } else {
          R = polar_rotation(A);
        }
        rot[e] = R.transpose();
        Vec3 p[4];
        for (int k = 0; k < 4; ++k) p[k] = mul(R, x[t[k]]);
        const auto& q = rest[e];
        for (int k = 0; k < 4; ++k)
          for (int i = 0; i < 3; ++i) D[3 * k + i] = q[k][i] - p[k][i];
        if (update_stiffness_matrix) tetra_strain_displacement(p[0], p[1], p[2], p[3], J[e]);
        if (assembling) continue;  // polar: SOFA reports an error and adds no force
        tetra_force_plastic(J[e], K[e], D, plasticity, plastic[e].data(), F);
        const Mat3& r = rot[e];
        for (int k = 0; k < 4; ++k) {
          const Vec3 fk = mul(r, Vec3(F[3 * k], F[3 * k + 1], F[3 * k + 2]));
          sink.add(e, k, t[k], fk[0], fk[1], fk[2]);
        }
        continue;
      }
    }
  }
}

template <class Sink>
void TetraFEM::dforce_range(std::size_t e_begin, std::size_t e_end, std::span<const Vec3> dx, double kfactor,
                            Sink& sink) const {
  double X[12], F[12];
  if (method == TetraMethod::small) {
    for (std::size_t e = e_begin; e < e_end; ++e) {
      const auto& t = tetra[e];
      for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i) X[3 * k + i] = dx[t[k]][i];
      tetra_force_scaled(J[e], K[e], X, kfactor, F);
      // x + (−F) and x − F are the same IEEE operation.
      for (int k = 0; k < 4; ++k) sink.sub(e, k, t[k], F[3 * k], F[3 * k + 1], F[3 * k + 2]);
    }
    return;
  }
  for (std::size_t e = e_begin; e < e_end; ++e) {
    const auto& t = tetra[e];
    const Mat3& r = rot[e];
    for (int k = 0; k < 4; ++k) {
      const Vec3& v = dx[t[k]];
      X[3 * k + 0] = r(0, 0) * v[0] + r(1, 0) * v[1] + r(2, 0) * v[2];
      X[3 * k + 1] = r(0, 1) * v[0] + r(1, 1) * v[1] + r(2, 1) * v[2];
      X[3 * k + 2] = r(0, 2) * v[0] + r(1, 2) * v[1] + r(2, 2) * v[2];
    }
    tetra_force_scaled(J[e], K[e], X, kfactor, F);
    for (int k = 0; k < 4; ++k) {
      const double* Fk = F + 3 * k;
      sink.sub(e, k, t[k], r(0, 0) * Fk[0] + r(0, 1) * Fk[1] + r(0, 2) * Fk[2],
               r(1, 0) * Fk[0] + r(1, 1) * Fk[1] + r(1, 2) * Fk[2], r(2, 0) * Fk[0] + r(2, 1) * Fk[1] + r(2, 2) * Fk[2]);
    }
  }
}

namespace {
// Writes element contributions straight into the output (sequential order).
struct DirectSink {
  std::span<Vec3> out;
  void add(std::size_t, int, int node, double a, double b, double c) {
    Vec3& o = out[node];
    o[0] += a, o[1] += b, o[2] += c;
  }
  void sub(std::size_t, int, int node, double a, double b, double c) {
    Vec3& o = out[node];
    o[0] -= a, o[1] -= b, o[2] -= c;
  }
};
// Stores them per (element, corner); gather_slots adds them per point in element order.
struct SlotSink {
  std::vector<std::array<Vec3, 4>>& slots;
  void add(std::size_t e, int k, int, double a, double b, double c) { slots[e][k] = Vec3(a, b, c); }
  void sub(std::size_t e, int k, int, double a, double b, double c) { slots[e][k] = Vec3(a, b, c); }
};
constexpr std::size_t kGrain = 512;
}  // namespace

namespace {
// kLanes doubles; GCC lowers the operations to SSE2 pairs (baseline) or AVX
// (avx2 clone). Each lane is an independent element: plain IEEE mul/add per
// lane, no contraction (-ffp-contract=off), so every lane is bit-identical to
// the scalar code.
typedef double v4d __attribute__((vector_size(32), aligned(32)));
static_assert(TetraFEM::kLanes == 4);
#define ld(p) (*reinterpret_cast<const v4d*>(p))
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// One block: X = Rᵀ-rotated dx (kRot), strain, stress, ·fact, nodal, rotate back.
template <bool kRot>
SINEW_AVX2_CLONES void tetra_dforce_block(const TetraFEM::HotBlock& B,
                                                                          const double (*in)[4], double fact,
                                                                          double (*out)[4]) {
  // Everything is loaded straight from the block (local arrays of vectors
  // make GCC copy them around with rep movs).
#define SINEW_R(i) ld(B.r[i])
#define SINEW_J(i) ld(B.j[i])
  v4d X[12];
  for (int k = 0; k < 4; ++k) {
    const v4d v0 = ld(in[3 * k]), v1 = ld(in[3 * k + 1]), v2 = ld(in[3 * k + 2]);
    if constexpr (kRot) {
      X[3 * k + 0] = SINEW_R(0) * v0 + SINEW_R(3) * v1 + SINEW_R(6) * v2;
      X[3 * k + 1] = SINEW_R(1) * v0 + SINEW_R(4) * v1 + SINEW_R(7) * v2;
      X[3 * k + 2] = SINEW_R(2) * v0 + SINEW_R(5) * v1 + SINEW_R(8) * v2;
    } else {
      X[3 * k + 0] = v0;
      X[3 * k + 1] = v1;
      X[3 * k + 2] = v2;
    }
  }
  // strain (J(r, c) mapped to b_k = j[3k], c_k = j[3k+1], d_k = j[3k+2] as in
  // tetra_strain_displacement)
  const v4d e0 = SINEW_J(0) * X[0] + SINEW_J(3) * X[3] + SINEW_J(6) * X[6] + SINEW_J(9) * X[9];
  const v4d e1 = SINEW_J(1) * X[1] + SINEW_J(4) * X[4] + SINEW_J(7) * X[7] + SINEW_J(10) * X[10];
  const v4d e2 = SINEW_J(2) * X[2] + SINEW_J(5) * X[5] + SINEW_J(8) * X[8] + SINEW_J(11) * X[11];
  const v4d e3 = SINEW_J(1) * X[0] + SINEW_J(0) * X[1] + SINEW_J(4) * X[3] + SINEW_J(3) * X[4] +
                 SINEW_J(7) * X[6] + SINEW_J(6) * X[7] + SINEW_J(10) * X[9] + SINEW_J(9) * X[10];
  const v4d e4 = SINEW_J(2) * X[1] + SINEW_J(1) * X[2] + SINEW_J(5) * X[4] + SINEW_J(4) * X[5] +
                 SINEW_J(8) * X[7] + SINEW_J(7) * X[8] + SINEW_J(11) * X[10] + SINEW_J(10) * X[11];
  const v4d e5 = SINEW_J(2) * X[0] + SINEW_J(0) * X[2] + SINEW_J(5) * X[3] + SINEW_J(3) * X[5] +
                 SINEW_J(8) * X[6] + SINEW_J(6) * X[8] + SINEW_J(11) * X[9] + SINEW_J(9) * X[11];
  // stress, then scaled
  const v4d Kd = ld(B.k[0]), Ko = ld(B.k[1]), Ks = ld(B.k[2]);
  const v4d f = {fact, fact, fact, fact};
  const v4d s0 = (Kd * e0 + Ko * e1 + Ko * e2) * f;
  const v4d s1 = (Ko * e0 + Kd * e1 + Ko * e2) * f;
  const v4d s2 = (Ko * e0 + Ko * e1 + Kd * e2) * f;
  const v4d s3 = (Ks * e3) * f;
  const v4d s4 = (Ks * e4) * f;
  const v4d s5 = (Ks * e5) * f;
  // nodal, rotated back
  for (int k = 0; k < 4; ++k) {
    const v4d bk = SINEW_J(3 * k), ck = SINEW_J(3 * k + 1), dk = SINEW_J(3 * k + 2);
    const v4d f0 = bk * s0 + ck * s3 + dk * s5;
    const v4d f1 = ck * s1 + bk * s3 + dk * s4;
    const v4d f2 = dk * s2 + ck * s4 + bk * s5;
    if constexpr (kRot) {
      *reinterpret_cast<v4d*>(out[3 * k + 0]) = SINEW_R(0) * f0 + SINEW_R(1) * f1 + SINEW_R(2) * f2;
      *reinterpret_cast<v4d*>(out[3 * k + 1]) = SINEW_R(3) * f0 + SINEW_R(4) * f1 + SINEW_R(5) * f2;
      *reinterpret_cast<v4d*>(out[3 * k + 2]) = SINEW_R(6) * f0 + SINEW_R(7) * f1 + SINEW_R(8) * f2;
    } else {
      *reinterpret_cast<v4d*>(out[3 * k + 0]) = f0;
      *reinterpret_cast<v4d*>(out[3 * k + 1]) = f1;
      *reinterpret_cast<v4d*>(out[3 * k + 2]) = f2;
    }
  }
#undef SINEW_R
#undef SINEW_J
}
#undef ld
}  // namespace

namespace {
// Method large, no plasticity, no stiffness update: frame, rotated
// displacement, J·K·Jᵀ·Δ and rotation back for kLanes elements (lane = element,
// every lane doing force_range's scalar sequence). in[c][l]: node k component i
// at c = 3k + i; q: q[1][0], q[2][0], q[2][1], q[3][0..2]. Writes rot (r[3i+j]
// = R(j, i), as rot[e] = Rᵀ) and the 12 force components.
SINEW_AVX2_CLONES void tetra_force_block_large(const TetraFEM::HotBlock& B,
                                                                              const double (*in)[4],
                                                                              const double (*q)[4], double (*r)[4],
                                                                              double (*out)[4]) {
#define ld(p) (*reinterpret_cast<const v4d*>(p))
#define st(p, v) (*reinterpret_cast<v4d*>(p) = (v))
  const v4d eps = {kEps, kEps, kEps, kEps};
  const v4d ax = ld(in[0]), ay = ld(in[1]), az = ld(in[2]);
  // SOFA normalize: divide by the norm when it is above DBL_EPSILON (per lane).
  auto normalize = [&](v4d& u0, v4d& u1, v4d& u2) {
    const v4d s2 = u0 * u0 + u1 * u1 + u2 * u2;
    v4d n;
    for (int l = 0; l < 4; ++l) n[l] = std::sqrt(s2[l]);
    const auto big = n > eps;
    const v4d d0 = u0 / n, d1 = u1 / n, d2 = u2 / n;
    u0 = big ? d0 : u0;
    u1 = big ? d1 : u1;
    u2 = big ? d2 : u2;
  };
  // ex = normalized(b − a), ey = c − a, ez = normalized(ex × ey), ey = ez × ex
  v4d ex0 = ld(in[3]) - ax, ex1 = ld(in[4]) - ay, ex2 = ld(in[5]) - az;
  normalize(ex0, ex1, ex2);
  v4d ey0 = ld(in[6]) - ax, ey1 = ld(in[7]) - ay, ey2 = ld(in[8]) - az;
  v4d ez0 = ex1 * ey2 - ex2 * ey1, ez1 = ex2 * ey0 - ex0 * ey2, ez2 = ex0 * ey1 - ex1 * ey0;
  normalize(ez0, ez1, ez2);
  ey0 = ez1 * ex2 - ez2 * ex1;
  ey1 = ez2 * ex0 - ez0 * ex2;
  ey2 = ez0 * ex1 - ez1 * ex0;
  // rot = Rᵀ: rot(i, j) = R(j, i), R rows ex, ey, ez
  st(r[0], ex0); st(r[1], ey0); st(r[2], ez0);
  st(r[3], ex1); st(r[4], ey1); st(r[5], ez1);
  st(r[6], ex2); st(r[7], ey2); st(r[8], ez2);
  // p_k = R·x_k
  v4d p[4][3];
  for (int k = 0; k < 4; ++k) {
    const v4d x0 = ld(in[3 * k]), x1 = ld(in[3 * k + 1]), x2 = ld(in[3 * k + 2]);
    p[k][0] = ex0 * x0 + ex1 * x1 + ex2 * x2;
    p[k][1] = ey0 * x0 + ey1 * x1 + ey2 * x2;
    p[k][2] = ez0 * x0 + ez1 * x1 + ez2 * x2;
  }
  p[1][0] -= p[0][0];
  p[2][0] -= p[0][0];
  p[2][1] -= p[0][1];
  p[3][0] -= p[0][0];
  p[3][1] -= p[0][1];
  p[3][2] -= p[0][2];
  const v4d z = {0, 0, 0, 0};
  v4d X[12];
  X[0] = X[1] = X[2] = z;
  X[3] = ld(q[0]) - p[1][0];
  X[4] = X[5] = z;
  X[6] = ld(q[1]) - p[2][0];
  X[7] = ld(q[2]) - p[2][1];
  X[8] = z;
  X[9] = ld(q[3]) - p[3][0];
  X[10] = ld(q[4]) - p[3][1];
  X[11] = ld(q[5]) - p[3][2];
#define SINEW_J(i) ld(B.j[i])
  const v4d e0 = SINEW_J(0) * X[0] + SINEW_J(3) * X[3] + SINEW_J(6) * X[6] + SINEW_J(9) * X[9];
  const v4d e1 = SINEW_J(1) * X[1] + SINEW_J(4) * X[4] + SINEW_J(7) * X[7] + SINEW_J(10) * X[10];
  const v4d e2 = SINEW_J(2) * X[2] + SINEW_J(5) * X[5] + SINEW_J(8) * X[8] + SINEW_J(11) * X[11];
  const v4d e3 = SINEW_J(1) * X[0] + SINEW_J(0) * X[1] + SINEW_J(4) * X[3] + SINEW_J(3) * X[4] +
                 SINEW_J(7) * X[6] + SINEW_J(6) * X[7] + SINEW_J(10) * X[9] + SINEW_J(9) * X[10];
  const v4d e4 = SINEW_J(2) * X[1] + SINEW_J(1) * X[2] + SINEW_J(5) * X[4] + SINEW_J(4) * X[5] +
                 SINEW_J(8) * X[7] + SINEW_J(7) * X[8] + SINEW_J(11) * X[10] + SINEW_J(10) * X[11];
  const v4d e5 = SINEW_J(2) * X[0] + SINEW_J(0) * X[2] + SINEW_J(5) * X[3] + SINEW_J(3) * X[5] +
                 SINEW_J(8) * X[6] + SINEW_J(6) * X[8] + SINEW_J(11) * X[9] + SINEW_J(9) * X[11];
  const v4d Kd = ld(B.k[0]), Ko = ld(B.k[1]), Ks = ld(B.k[2]);
  const v4d s0 = Kd * e0 + Ko * e1 + Ko * e2;
  const v4d s1 = Ko * e0 + Kd * e1 + Ko * e2;
  const v4d s2 = Ko * e0 + Ko * e1 + Kd * e2;
  const v4d s3 = Ks * e3, s4 = Ks * e4, s5 = Ks * e5;
  for (int k = 0; k < 4; ++k) {
    const v4d bk = SINEW_J(3 * k), ck = SINEW_J(3 * k + 1), dk = SINEW_J(3 * k + 2);
    const v4d f0 = bk * s0 + ck * s3 + dk * s5;
    const v4d f1 = ck * s1 + bk * s3 + dk * s4;
    const v4d f2 = dk * s2 + ck * s4 + bk * s5;
    // fk = rot·F_k, rot(i, j) = R(j, i)
    st(out[3 * k + 0], ex0 * f0 + ey0 * f1 + ez0 * f2);
    st(out[3 * k + 1], ex1 * f0 + ey1 * f1 + ez1 * f2);
    st(out[3 * k + 2], ex2 * f0 + ey2 * f1 + ez2 * f2);
  }
#undef SINEW_J
#undef ld
#undef st
}
}  // namespace

bool TetraFEM::refresh_hot(bool rot_written) const {
  const std::size_t ne = tetra.size();
  if (ne == 0 || J.size() != ne || K.size() != ne || rot.size() != ne) return false;
  const std::size_t nb = (ne + kLanes - 1) / kLanes;
  const bool j_stale = hot_j_gen != j_gen || hot.size() != nb;
  if (j_stale) {
    hot_ok = true;
    for (std::size_t e = 0; e < ne && hot_ok; ++e) {
      const TetraJ& Je = J[e];
      for (int k = 0; k < 4 && hot_ok; ++k) {
        const int r = 3 * k;
        // structural zeros must be zeros, copies must be bitwise copies
        hot_ok = same_bits(Je(r, 0), Je(r + 1, 3)) && same_bits(Je(r, 0), Je(r + 2, 5)) &&
                 same_bits(Je(r + 1, 1), Je(r, 3)) && same_bits(Je(r + 1, 1), Je(r + 2, 4)) &&
                 same_bits(Je(r + 2, 2), Je(r + 1, 4)) && same_bits(Je(r + 2, 2), Je(r, 5));
      }
    }
    hot_j_gen = j_gen;
    if (!hot_ok) {
      hot.clear();
      hot.shrink_to_fit();
      return false;
    }
    hot.assign(nb, HotBlock{});
    for (std::size_t e = 0; e < ne; ++e) {
      HotBlock& B = hot[e / kLanes];
      const int l = static_cast<int>(e % kLanes);
      for (int k = 0; k < 4; ++k) {
        B.j[3 * k + 0][l] = J[e](3 * k, 0);
        B.j[3 * k + 1][l] = J[e](3 * k + 1, 1);
        B.j[3 * k + 2][l] = J[e](3 * k + 2, 2);
        B.n[k][l] = tetra[e][k];
      }
      B.k[0][l] = K[e].d;
      B.k[1][l] = K[e].o;
      B.k[2][l] = K[e].s;
    }
    hot_r_gen = 0;
  }
  if (!hot_ok) return false;
  if (rot_written) hot_r_gen = r_gen;  // the caller writes every rotation into the blocks
  if (hot_r_gen != r_gen) {
    for (std::size_t e = 0; e < ne; ++e) {
      HotBlock& B = hot[e / kLanes];
      const int l = static_cast<int>(e % kLanes);
      const Mat3& r = rot[e];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) B.r[3 * i + j][l] = r(i, j);
    }
    hot_r_gen = r_gen;
  }
  return true;
}

template <class Sink>
void TetraFEM::force_blocks_large(std::size_t b_begin, std::size_t b_end, std::span<const Vec3> x, Sink& sink) {
  const std::size_t ne = tetra.size();
  alignas(32) double in[12][4];
  alignas(32) double q[6][4];
  alignas(32) double out[12][4];
  for (std::size_t b = b_begin; b < b_end; ++b) {
    HotBlock& B = hot[b];
    const std::size_t e0 = b * kLanes;
    const int nl = static_cast<int>(std::min<std::size_t>(kLanes, ne - e0));
    for (int l = 0; l < kLanes; ++l) {
      for (int k = 0; k < 4; ++k) {
        const Vec3& v = x[B.n[k][l]];
        in[3 * k + 0][l] = v[0];
        in[3 * k + 1][l] = v[1];
        in[3 * k + 2][l] = v[2];
      }
      const auto& qe = rest[l < nl ? e0 + l : e0];
      q[0][l] = qe[1][0];
      q[1][l] = qe[2][0];
      q[2][l] = qe[2][1];
      q[3][l] = qe[3][0];
      q[4][l] = qe[3][1];
      q[5][l] = qe[3][2];
    }
    tetra_force_block_large(B, in, q, B.r, out);
    for (int l = 0; l < nl; ++l) {
      Mat3& r = rot[e0 + l];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = B.r[3 * i + j][l];
      for (int k = 0; k < 4; ++k) sink.add(e0 + l, k, B.n[k][l], out[3 * k][l], out[3 * k + 1][l], out[3 * k + 2][l]);
    }
  }
}

template <bool kRot, class Sink>
void TetraFEM::dforce_blocks(std::size_t b_begin, std::size_t b_end, std::span<const Vec3> dx, double kfactor,
                             Sink& sink) const {
  const std::size_t ne = tetra.size();
  alignas(32) double in[12][4];
  alignas(32) double out[12][4];
  for (std::size_t b = b_begin; b < b_end; ++b) {
    const HotBlock& B = hot[b];
    for (int k = 0; k < 4; ++k)
      for (int l = 0; l < kLanes; ++l) {
        const Vec3& v = dx[B.n[k][l]];
        in[3 * k + 0][l] = v[0];
        in[3 * k + 1][l] = v[1];
        in[3 * k + 2][l] = v[2];
      }
    tetra_dforce_block<kRot>(B, in, kfactor, out);
    const std::size_t e0 = b * kLanes;
    const int nl = static_cast<int>(std::min<std::size_t>(kLanes, ne - e0));
    for (int l = 0; l < nl; ++l)
      for (int k = 0; k < 4; ++k) sink.sub(e0 + l, k, B.n[k][l], out[3 * k][l], out[3 * k + 1][l], out[3 * k + 2][l]);
  }
}

bool TetraFEM::parallel() const {
  return tetra.size() >= kParallelMinElements &&
         tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1 &&
         tbb::this_task_arena::max_concurrency() > 1;
}

void TetraFEM::build_incidence(std::size_t n_points) {
  // Point → (element·4 + corner) slots in element order: gathering them in this
  // order adds contributions exactly as the sequential loop does.
  node_start.assign(n_points + 1, 0);
  for (const auto& t : tetra)
    for (int k = 0; k < 4; ++k) ++node_start[t[k] + 1];
  for (std::size_t p = 0; p < n_points; ++p) node_start[p + 1] += node_start[p];
  node_slot.assign(node_start[n_points], 0);
  std::vector<std::uint32_t> fill(node_start.begin(), node_start.end() - 1);
  for (std::size_t e = 0; e < tetra.size(); ++e)
    for (int k = 0; k < 4; ++k) node_slot[fill[tetra[e][k]]++] = static_cast<std::uint32_t>(e * 4 + k);
  slots.assign(tetra.size(), {});
}

void TetraFEM::gather_slots(std::span<Vec3> out, bool subtract) const {
  const std::size_t n = std::min(out.size(), node_start.empty() ? 0 : node_start.size() - 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& range) {
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      Vec3& o = out[p];
      for (std::uint32_t s = node_start[p]; s < node_start[p + 1]; ++s) {
        const Vec3& c = slots[node_slot[s] / 4][node_slot[s] % 4];
        if (subtract) o[0] -= c[0], o[1] -= c[1], o[2] -= c[2];
        else o[0] += c[0], o[1] += c[1], o[2] += c[2];
      }
    }
  });
}

void TetraFEM::add_force(std::span<const Vec3> x, std::span<Vec3> f) {
  // computeGlobalMatrix (large) zeroes three J entries in force_range.
  touch(update_stiffness_matrix || assembling);
  sr_r_gen = sr_j_gen = 0;
  const bool plastic_on = plasticity.max_threshold > 0;
  // SOFA: svd with computeGlobalMatrix returns before anything; small with
  // plasticity and computeGlobalMatrix adds nothing.
  if (assembling && method == TetraMethod::svd) return;
  if (assembling && plastic_on && method == TetraMethod::small) return;
  // Elements that add nothing leave their slots untouched: clear them first.
  if (assembling) {
    DirectSink sink{f};
    if ((method == TetraMethod::small || method == TetraMethod::large) && !plastic_on) {
      sr_cache.resize(tetra.size());
      force_range(0, tetra.size(), x, sink);
      sr_j_gen = j_gen;  // every element stored its SR
      sr_r_gen = r_gen;
      return;
    }
    force_range(0, tetra.size(), x, sink);
    return;
  }
  // Packed path: large, no plasticity, no stiffness update, compact J.
  const bool packed =
      method == TetraMethod::large && !plastic_on && !update_stiffness_matrix && refresh_hot(/*rot_written=*/true);
  auto run = [&](std::size_t e_begin, std::size_t e_end, auto& sink) {
    if (!packed) {
      force_range(e_begin, e_end, x, sink);
      return;
    }
    force_blocks_large(e_begin / kLanes, (e_end + kLanes - 1) / kLanes, x, sink);
  };
  if (!parallel()) {
    DirectSink sink{f};
    run(0, tetra.size(), sink);
  } else {
    for (auto& s : slots) s.fill(Vec3::Zero());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tetra.size(), kGrain), [&](const auto& range) {
      SlotSink sink{slots};
      const std::size_t eb = range.begin() - range.begin() % kLanes;
      const std::size_t ee = range.end() == tetra.size() ? range.end() : range.end() - range.end() % kLanes;
      run(eb, ee, sink);
    });
    gather_slots(f, false);
  }
  if (packed) hot_r_gen = r_gen;  // the blocks hold the new rotations
}

void TetraFEM::add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) const {
  const bool fast = refresh_hot();
  const bool rotated = method != TetraMethod::small;
  auto run = [&](std::size_t e_begin, std::size_t e_end, auto& sink) {
    if (!fast) {
      dforce_range(e_begin, e_end, dx, kfactor, sink);
      return;
    }
    // e_begin is a multiple of kLanes (kGrain is); e_end is one or the end.
    const std::size_t b0 = e_begin / kLanes, b1 = (e_end + kLanes - 1) / kLanes;
    if (rotated) dforce_blocks<true>(b0, b1, dx, kfactor, sink);
    else dforce_blocks<false>(b0, b1, dx, kfactor, sink);
  };
  if (!parallel()) {
    DirectSink sink{df};
    run(0, tetra.size(), sink);
    return;
  }
  static_assert(kGrain % kLanes == 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tetra.size(), kGrain), [&](const auto& range) {
    SlotSink sink{slots};
    const std::size_t eb = range.begin() - range.begin() % kLanes;
    const std::size_t ee = range.end() == tetra.size() ? range.end() : range.end() - range.end() % kLanes;
    run(eb, ee, sink);
  });
  gather_slots(df, true);
}

void TetraFEM::node_rotations(std::span<Mat3> out, bool average) const {
  const std::size_t np = out.size();
  if (method == TetraMethod::small || tetra.empty()) {
    for (auto& r : out) r = Mat3::Identity();
    return;
  }
  // rot·R0 with R0 = rot0ᵀ (SOFA: rotations[e] * transpose(_initialRotations[e])).
  auto element_rotation = [&](std::size_t e) { return mul(rot[e], Mat3(rot0[e].transpose())); };
  std::vector<Mat3> sum(average ? np : 0, Mat3::Zero());
  std::vector<int> count(np, 0);
  std::vector<std::size_t> last(np, 0);
  for (std::size_t e = 0; e < tetra.size(); ++e) {
    const Mat3 r = average ? element_rotation(e) : Mat3::Zero();
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = static_cast<std::size_t>(tetra[e][k]);
      if (i >= np) continue;
      last[i] = e;
      if (!average) continue;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sum[i](a, b) += r(a, b);
      ++count[i];
    }
  }
  for (std::size_t i = 0; i < np; ++i) {
    if (!average || count[i] == 0) {
      out[i] = element_rotation(last[i]);
      continue;
    }
    Mat3 m = sum[i];
    const double n = static_cast<double>(count[i]);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) m(a, b) = m(a, b) / n;
    out[i] = polar_rotation(m);
  }
}

void TetraFEM::prepare_von_mises(std::span<const double> E, std::span<const double> nu) {
  const std::size_t ne = tetra.size();
  lame_lambda.assign(ne, 0.0);
  lame_mu.assign(ne, 0.0);
  shape_inv.assign(ne, Eigen::Matrix4d::Identity());
  for (std::size_t e = 0; e < ne && e < E.size() && e < nu.size(); ++e) {
    const double v = nu[e];
    const double scale = (E[e] * (1 - v)) / ((1 + v) * (1 - 2 * v));
    lame_lambda[e] = (v / (1 - v)) * scale;
    lame_mu[e] = ((1 - 2 * v) / (2 * (1 - v))) * scale;
    Eigen::Matrix4d m;
    for (int k = 0; k < 4; ++k) {
      const Vec3& p = X0[tetra[e][k]];
      m(k, 0) = 1.0;
      m(k, 1) = p[0];
      m(k, 2) = p[1];
      m(k, 3) = p[2];
    }
    if (std::fabs(m.determinant()) > 0) shape_inv[e] = m.inverse();
  }
}

void TetraFEM::von_mises(std::span<const Vec3> x, int mode, std::vector<double>& vme, std::vector<double>& vmn) {
  touch(false);
  const std::size_t ne = tetra.size();
  vme.assign(ne, 0.0);
  if (shape_inv.size() != ne) return;
  for (std::size_t e = 0; e < ne; ++e) {
    const auto& t = tetra[e];
    // TetrahedralCorotational only computes its shape functions for the large method (zero otherwise).
    const Eigen::Matrix4d shf = mode == 3 && method != TetraMethod::large ? Eigen::Matrix4d::Zero() : shape_inv[e];
    double U[12];
    if (mode == 2) {
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) U[3 * k + c] = x[t[k]][c] - X0[t[k]][c];
    } else {
      Mat3 R;
      if (method == TetraMethod::large || mode == 3) {
        R = tetra_frame_large(x[t[0]], x[t[1]], x[t[2]]);
        Vec3 p[4];
        for (int k = 0; k < 4; ++k) p[k] = mul(R, x[t[k]]);
        p[1][0] -= p[0][0];
        p[2][0] -= p[0][0];
        p[2][1] -= p[0][1];
        p[3] = sub(p[3], p[0]);
        const auto& q = rest[e];
        for (double& u : U) u = 0;
        U[3] = q[1][0] - p[1][0];
        U[6] = q[2][0] - p[2][0];
        U[7] = q[2][1] - p[2][1];
        U[9] = q[3][0] - p[3][0];
        U[10] = q[3][1] - p[3][1];
        U[11] = q[3][2] - p[3][2];
      } else {
        R = polar_rotation(edge_rows(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
        const auto& q = rest[e];
        for (int k = 0; k < 4; ++k) {
          const Vec3 p = mul(R, x[t[k]]);
          for (int c = 0; c < 3; ++c) U[3 * k + c] = q[k][c] - p[c];
        }
      }
      if (method != TetraMethod::small && mode == 1) rot[e] = R.transpose();
    }
    Mat3 g;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        double v = 0.0;
        for (int m = 0; m < 4; ++m) v += shf(l + 1, m) * U[3 * m + k];
        g(k, l) = v;
      }
    Mat3 strain;
    if (mode == 2) {
      const Mat3 gtg = mul(Mat3(g.transpose()), g);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) strain(i, j) = 0.5 * (g(i, j) + g(j, i) + gtg(i, j));
    } else {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) strain(i, j) = 0.5 * (g(i, j) + g(j, i));
    }
    const double vs[6] = {strain(0, 0), strain(1, 1), strain(2, 2), strain(1, 2), strain(0, 2), strain(0, 1)};
    // TetrahedralCorotational (mode 3) uses its material matrix entries, already divided by 36·V0.
    const double lambda = mode == 3 ? K[e].o : lame_lambda[e], mu = mode == 3 ? K[e].s : lame_mu[e];
    double sg[6];
    double tr = 0.0;
    for (int k = 0; k < 3; ++k) {
      tr += vs[k];
      sg[k] = vs[k] * 2 * mu;
    }
    for (int k = 3; k < 6; ++k) sg[k] = vs[k] * 2 * mu;
    for (int k = 0; k < 3; ++k) sg[k] += lambda * tr;
    double v = std::sqrt(sg[0] * sg[0] + sg[1] * sg[1] + sg[2] * sg[2] - sg[0] * sg[1] - sg[1] * sg[2] -
                         sg[2] * sg[0] + 3 * sg[3] * sg[3] + 3 * sg[4] * sg[4] + 3 * sg[5] * sg[5]);
    if (v < 1e-10) v = 0.0;
    vme[e] = v;
  }
  vmn.assign(x.size(), 0.0);
  vm_count.assign(x.size(), 0);
  for (std::size_t e = 0; e < ne; ++e)
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = static_cast<std::size_t>(tetra[e][k]);
      if (i >= vmn.size()) continue;
      vmn[i] += vme[e];
      ++vm_count[i];
    }
  for (std::size_t i = 0; i < vmn.size(); ++i)
    if (vm_count[i] > 0) vmn[i] /= static_cast<double>(vm_count[i]);
}

std::vector<std::array<int, 4>> split_hexahedra(std::span<const std::array<unsigned, 8>> hexa, int nx, int ny) {
  static constexpr int kX[4][2] = {{0, 1}, {4, 5}, {3, 2}, {7, 6}};
  static constexpr int kY[4][2] = {{4, 7}, {5, 6}, {1, 2}, {0, 3}};
  static constexpr int kZ[4][2] = {{4, 0}, {5, 1}, {6, 2}, {7, 3}};
  if (nx <= 0) nx = 1;
  if (ny <= 0) ny = 1;
  std::vector<std::array<int, 4>> out;
  out.reserve(hexa.size() * 6);
  for (std::size_t i = 0; i < hexa.size(); ++i) {
    std::array<int, 8> c;
    for (int k = 0; k < 8; ++k) c[k] = static_cast<int>(hexa[i][k]);
    const std::size_t ux = static_cast<std::size_t>(nx), uy = static_cast<std::size_t>(ny);
    if (!((i % ux) & 1))
      for (auto& p : kX) std::swap(c[p[0]], c[p[1]]);
    if (((i / ux) % uy) & 1)
      for (auto& p : kY) std::swap(c[p[0]], c[p[1]]);
    if ((i / (ux * uy)) & 1)
      for (auto& p : kZ) std::swap(c[p[0]], c[p[1]]);
    out.push_back({c[0], c[5], c[1], c[6]});
    out.push_back({c[0], c[1], c[3], c[6]});
    out.push_back({c[1], c[3], c[6], c[2]});
    out.push_back({c[6], c[3], c[0], c[7]});
    out.push_back({c[6], c[7], c[0], c[5]});
    out.push_back({c[7], c[5], c[4], c[0]});
  }
  return out;
}

}  // namespace sinew::fem
