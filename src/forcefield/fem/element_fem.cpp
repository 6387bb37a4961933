#include "forcefield/fem/element_fem.h"

#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/decompose.h"

namespace sinew::fem {

void lame_parameters(double young, double poisson, double& lambda, double& mu) {
  mu = young / (2 * (1 + poisson));
  lambda = young * poisson / ((1 + poisson) * (1 - 2.0 * poisson));
}

namespace {

// Voigt index → tensor indices, SOFA's 3D order.
constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

inline double delta(int i, int j) { return i == j ? 1.0 : 0.0; }

// Isotropic elasticity tensor in Voigt form, each entry as SOFA's lambda:
// μ(δik δjl + δil δjk) + λ δij δkl.
void isotropic_tensor(double lambda, double mu, double (&C)[6][6]) {
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      const int i = kVoigt[a][0], j = kVoigt[a][1], k = kVoigt[b][0], l = kVoigt[b][1];
      C[a][b] = mu * (delta(i, k) * delta(j, l) + delta(i, l) * delta(j, k)) + lambda * delta(i, j) * delta(k, l);
    }
}

// SOFA's Vec::normalize: divide by the norm unless it is ≤ DBL_EPSILON.
inline void normalize(Vec3& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (n > std::numeric_limits<double>::epsilon()) {
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
  }
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

// Centroid: nodes summed in order, then divided by their count.
template <int N>
inline Vec3 centroid(const Vec3 (&p)[N]) {
  Vec3 c = p[0];
  for (int k = 1; k < N; ++k) {
    c[0] += p[k][0];
    c[1] += p[k][1];
    c[2] += p[k][2];
  }
  c[0] /= static_cast<double>(N);
  c[1] /= static_cast<double>(N);
  c[2] /= static_cast<double>(N);
  return c;
}

// r = Aᵀ·B (SOFA's 3×3 multTranspose).
inline Mat3 mult_transpose(const Mat3& A, const Mat3& B) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = A(0, i) * B(0, j) + A(1, i) * B(1, j) + A(2, i) * B(2, j);
  return r;
}

template <int N>
Mat3 element_rotation(RotationMethod m, const Mat3& F0, const Vec3 (&x)[N], const Vec3 (&X0)[N]) {
  switch (m) {
    case RotationMethod::triangle:
      return mult_transpose(frame_from_3_points(x[0], x[1], x[2]), F0);
    case RotationMethod::hexahedron:
      if constexpr (N == 8) {
        std::array<Vec3, 8> n;
        for (int k = 0; k < 8; ++k) n[k] = x[k];
        return mult_transpose(frame_from_hexahedron(n), F0);
      } else {
        return Mat3::Identity();
      }
    case RotationMethod::polar:
    case RotationMethod::stable_polar: {
      const Vec3 t = centroid<N>(x), t0 = centroid<N>(X0);
      Vec3 P[N], Q[N];
      for (int k = 0; k < N; ++k) {
        P[k] = Vec3(x[k][0] - t[0], x[k][1] - t[1], x[k][2] - t[2]);
        Q[k] = Vec3(X0[k][0] - t0[0], X0[k][1] - t0[1], X0[k][2] - t0[2]);
      }
      Mat3 H;  // Pᵀ·Q
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double s = P[0][i] * Q[0][j];
          for (int k = 1; k < N; ++k) s += P[k][i] * Q[k][j];
          H(i, j) = s;
        }
      return m == RotationMethod::polar ? polar_rotation(H) : stable_polar_rotation(H);
    }
    case RotationMethod::identity:
    case RotationMethod::none:
      break;
  }
  return Mat3::Identity();
}

// y = K·v, each row summed from its first column (SOFA's Mat·Vec).
template <int D>
inline void mat_vec(const double* K, const double (&v)[D], double* y) {
  for (int i = 0; i < D; ++i) {
    const double* row = K + i * D;
    double s = row[0] * v[0];
    for (int j = 1; j < D; ++j) s += row[j] * v[j];
    y[i] = s;
  }
}

template <class F>
void for_elements(bool parallel, std::size_t n, F&& f) {
  if (parallel && n > 64) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t e = r.begin(); e < r.end(); ++e) f(e);
    });
  } else {
    for (std::size_t e = 0; e < n; ++e) f(e);
  }
}

}  // namespace

Mat3 frame_from_3_points(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  Vec3 x(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]);
  normalize(x);
  Vec3 y(p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]);
  Vec3 z = cross(x, y);
  normalize(z);
  y = cross(z, x);
  Mat3 F;
  F.row(0) = x.transpose();
  F.row(1) = y.transpose();
  F.row(2) = z.transpose();
  return F;
}

Mat3 frame_from_hexahedron(const std::array<Vec3, 8>& n) {
  Vec3 x, y;
  for (int c = 0; c < 3; ++c) {
    x[c] = (n[1][c] - n[0][c] + n[2][c] - n[3][c] + n[5][c] - n[4][c] + n[6][c] - n[7][c]) * 0.25;
    y[c] = (n[3][c] - n[0][c] + n[2][c] - n[1][c] + n[7][c] - n[4][c] + n[6][c] - n[5][c]) * 0.25;
  }
  normalize(x);
  Vec3 z = cross(x, y);
  normalize(z);
  y = cross(z, x);
  Mat3 F;
  F.row(0) = x.transpose();
  F.row(1) = y.transpose();
  F.row(2) = z.transpose();
  return F;
}

template <class E>
bool element_stiffness(const std::array<Vec3, E::kNodes>& X, double lambda, double mu, double* K, bool* inverted) {
  constexpr int N = E::kNodes;
  constexpr int D = 3 * N;
  double C[6][6];
  isotropic_tensor(lambda, mu, C);
  for (int i = 0; i < D * D; ++i) K[i] = 0.0;

  Vec3 Xa[N];
  for (int k = 0; k < N; ++k) Xa[k] = X[k];
  const auto points = E::points();
  const auto weights = E::weights();
  for (int q = 0; q < E::kPoints; ++q) {
    double g[N][3];
    E::gradient(points[q], g);
    const fe::Mat3d J = fe::jacobian<N>(Xa, g);
    const double signed_det = fe::determinant(J);
    if (inverted && signed_det < 0) *inverted = true;
    const double detJ = std::abs(signed_det);
    fe::Mat3d Ji;
    if (!fe::invert(J, Ji)) return false;
    // ∇N_i = J⁻ᵀ·∇_ref N_i
    double dN[N][3];
    for (int i = 0; i < N; ++i)
      for (int a = 0; a < 3; ++a) dN[i][a] = Ji[0][a] * g[i][0] + Ji[1][a] * g[i][1] + Ji[2][a] * g[i][2];
    // strain-displacement B (6×D), engineering shear
    double B[6][D] = {};
    for (int v = 0; v < 6; ++v) {
      const int i = kVoigt[v][0], j = kVoigt[v][1];
      for (int n = 0; n < N; ++n) {
        B[v][3 * n + i] = dN[n][j];
        if (i != j) B[v][3 * n + j] = dN[n][i];
      }
    }
    double CB[6][D];
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < D; ++j) {
        double s = 0.0;
        for (int k = 0; k < 6; ++k) s += C[i][k] * B[k][j];
        CB[i][j] = s;
      }
    const double s = weights[q] * detJ;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) {
        double t = B[0][i] * CB[0][j];
        for (int k = 1; k < 6; ++k) t += B[k][i] * CB[k][j];
        K[i * D + j] += t * s;
      }
  }
  for (int i = 0; i < D * D; ++i)
    if (!std::isfinite(K[i])) return false;
  return true;
}

template bool element_stiffness<fe::Tetra4>(const std::array<Vec3, 4>&, double, double, double*, bool*);
template bool element_stiffness<fe::Hexa8>(const std::array<Vec3, 8>&, double, double, double*, bool*);
template bool element_stiffness<fe::Prism6>(const std::array<Vec3, 6>&, double, double, double*, bool*);
template bool element_stiffness<fe::Pyramid5>(const std::array<Vec3, 5>&, double, double, double*, bool*);

template <class E>
std::vector<ElementIssue> ElementFEM<E>::init(std::span<const Vec3> X0, std::span<const std::array<unsigned, N>> elems,
                                              std::span<const double> young, std::span<const double> poisson,
                                              RotationMethod method) {
  std::vector<ElementIssue> issues;
  std::size_t n_inverted = 0;
  int first_inverted = -1;
  rotation = method;
  const std::size_t ne = elems.size();
  elements.assign(elems.begin(), elems.end());
  K.assign(ne, Stiffness{});
  F0.assign(ne, Mat3::Identity());
  R.assign(ne, Mat3::Identity());
  fe.assign(ne, ElementVector{});
  dfe.assign(ne, ElementVector{});
  if (young.size() < ne || poisson.size() < ne) {
    issues.push_back({-1, true, "material arrays shorter than the element list"});
    return issues;
  }
  for (std::size_t e = 0; e < ne; ++e) {
    std::array<Vec3, N> X;
    bool ok = true;
    for (int k = 0; k < N; ++k) {
      if (elems[e][k] >= X0.size()) {
        issues.push_back({static_cast<int>(e), true,
                          "node index " + std::to_string(elems[e][k]) + " is out of range (the state has " +
                              std::to_string(X0.size()) + " points)"});
        ok = false;
        break;
      }
      X[k] = X0[elems[e][k]];
    }
    if (!ok) continue;
    double lambda, mu;
    lame_parameters(young[e], poisson[e], lambda, mu);
    bool inv = false;
    if (!element_stiffness<E>(X, lambda, mu, K[e].data(), &inv)) {
      issues.push_back({static_cast<int>(e), true, "degenerate element (zero Jacobian determinant at rest)"});
      continue;
    }
    if (inv) {
      if (n_inverted == 0) first_inverted = static_cast<int>(e);
      ++n_inverted;
    }
    // Rest frame: SOFA computes the rotation of the rest shape against the identity, then transposes it.
    Vec3 Xa[N];
    for (int k = 0; k < N; ++k) Xa[k] = X[k];
    if (method == RotationMethod::triangle) {
      F0[e] = mult_transpose(frame_from_3_points(Xa[0], Xa[1], Xa[2]), Mat3::Identity()).transpose();
    } else if (method == RotationMethod::hexahedron && N == 8) {
      std::array<Vec3, 8> n;
      for (int k = 0; k < 8 && k < N; ++k) n[k] = Xa[k];
      F0[e] = mult_transpose(frame_from_hexahedron(n), Mat3::Identity()).transpose();
    }
  }
  if (n_inverted > 0)
    issues.push_back({first_inverted, false,
                      std::to_string(n_inverted) + " element(s) inverted at rest (negative Jacobian determinant; "
                      "first one reported), integrated with |det J| as SOFA does"});
  return issues;
}

template <class E>
void ElementFEM<E>::element_force(std::size_t e, std::span<const Vec3> x, std::span<const Vec3> X0) {
  const auto& el = elements[e];
  double u[D];
  if (rotation == RotationMethod::none) {
    for (int j = 0; j < N; ++j)
      for (int c = 0; c < 3; ++c) u[3 * j + c] = x[el[j]][c] - X0[el[j]][c];
    mat_vec<D>(K[e].data(), u, fe[e].data());
    return;
  }
  Vec3 xe[N], X0e[N];
  for (int j = 0; j < N; ++j) {
    xe[j] = x[el[j]];
    X0e[j] = X0[el[j]];
  }
  const Mat3 r = element_rotation<N>(rotation, F0[e], xe, X0e);
  R[e] = r;
  const Vec3 t = centroid<N>(xe), t0 = centroid<N>(X0e);
  for (int j = 0; j < N; ++j) {
    const double d0 = xe[j][0] - t[0], d1 = xe[j][1] - t[1], d2 = xe[j][2] - t[2];
    for (int c = 0; c < 3; ++c) {
      const double rot = r(0, c) * d0 + r(1, c) * d1 + r(2, c) * d2;  // Rᵀ(x − t)
      u[3 * j + c] = rot - (X0e[j][c] - t0[c]);
    }
  }
  double* f = fe[e].data();
  mat_vec<D>(K[e].data(), u, f);
  for (int n = 0; n < N; ++n) {
    const double a = f[3 * n], b = f[3 * n + 1], c = f[3 * n + 2];
    for (int i = 0; i < 3; ++i) f[3 * n + i] = r(i, 0) * a + r(i, 1) * b + r(i, 2) * c;
  }
}

template <class E>
void ElementFEM<E>::element_dforce(std::size_t e, std::span<const Vec3> dx) {
  const auto& el = elements[e];
  double u[D];
  double* f = dfe[e].data();
  if (rotation == RotationMethod::none) {
    for (int j = 0; j < N; ++j)
      for (int c = 0; c < 3; ++c) u[3 * j + c] = dx[el[j]][c];
    mat_vec<D>(K[e].data(), u, f);
    return;
  }
  const Mat3& r = R[e];
  for (int j = 0; j < N; ++j) {
    const Vec3& d = dx[el[j]];
    for (int c = 0; c < 3; ++c) u[3 * j + c] = r(0, c) * d[0] + r(1, c) * d[1] + r(2, c) * d[2];
  }
  mat_vec<D>(K[e].data(), u, f);
  for (int n = 0; n < N; ++n) {
    const double a = f[3 * n], b = f[3 * n + 1], c = f[3 * n + 2];
    for (int i = 0; i < 3; ++i) f[3 * n + i] = r(i, 0) * a + r(i, 1) * b + r(i, 2) * c;
  }
}

template <class E>
void ElementFEM<E>::add_force(std::span<const Vec3> x, std::span<const Vec3> X0, std::span<Vec3> f) {
  const std::size_t ne = elements.size();
  for_elements(parallel_force, ne, [&](std::size_t e) { element_force(e, x, X0); });
  // Scatter: sequential, element order (identical for both strategies).
  for (std::size_t e = 0; e < ne; ++e) {
    const auto& el = elements[e];
    const auto& v = fe[e];
    for (int j = 0; j < N; ++j) {
      Vec3& node = f[el[j]];
      node[0] -= v[3 * j];
      node[1] -= v[3 * j + 1];
      node[2] -= v[3 * j + 2];
    }
  }
}

template <class E>
void ElementFEM<E>::add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) {
  const std::size_t ne = elements.size();
  for_elements(parallel_dforce, ne, [&](std::size_t e) { element_dforce(e, dx); });
  for (std::size_t e = 0; e < ne; ++e) {
    const auto& el = elements[e];
    const auto& v = dfe[e];
    for (int j = 0; j < N; ++j) {
      Vec3& node = df[el[j]];
      node[0] -= kfactor * v[3 * j];
      node[1] -= kfactor * v[3 * j + 1];
      node[2] -= kfactor * v[3 * j + 2];
    }
  }
}

template struct ElementFEM<fe::Tetra4>;
template struct ElementFEM<fe::Hexa8>;
template struct ElementFEM<fe::Prism6>;
template struct ElementFEM<fe::Pyramid5>;

}  // namespace sinew::fem
