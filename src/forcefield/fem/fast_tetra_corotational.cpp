#include "forcefield/fem/fast_tetra_corotational.h"

#include <cmath>
#include <limits>

#include "forcefield/fem/sofa_mat3.h"
#include "math/decompose.h"

namespace sinew::fem {

namespace {

// SOFA's local edge table of a tetrahedron.
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// A·B, each entry summed over k = 0, 1, 2 in that order (SOFA's Mat product).
inline Mat3 mul(const Mat3& A, const Mat3& B) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = A(i, 0) * B(0, j) + A(i, 1) * B(1, j) + A(i, 2) * B(2, j);
  return r;
}

// Aᵀ·B, same order (SOFA's multTranspose).
inline Mat3 tmul(const Mat3& A, const Mat3& B) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = A(0, i) * B(0, j) + A(1, i) * B(1, j) + A(2, i) * B(2, j);
  return r;
}

// Aᵀ·v.
inline Vec3 tmulv(const Mat3& A, const Vec3& v) {
  return Vec3(A(0, 0) * v[0] + A(1, 0) * v[1] + A(2, 0) * v[2], A(0, 1) * v[0] + A(1, 1) * v[1] + A(2, 1) * v[2],
              A(0, 2) * v[0] + A(1, 2) * v[1] + A(2, 2) * v[2]);
}

// SOFA's Vec::normalized(): divided by its norm unless the norm is ≤ DBL_EPSILON.
inline Vec3 normalized(const Vec3& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(n > std::numeric_limits<double>::epsilon())) return v;
  return Vec3(v[0] / n, v[1] / n, v[2] / n);
}

// Rows: unit first edge, unit normal × it, unit normal of the first two edges.
inline Mat3 qr_frame(const Vec3* edge) {
  const Vec3 ex = normalized(edge[0]);
  const Vec3 ez = normalized(cross3(ex, edge[1]));
  const Vec3 ey = cross3(ez, ex);
  Mat3 r;
  r.row(0) = ex.transpose();
  r.row(1) = ey.transpose();
  r.row(2) = ez.transpose();
  return r;
}

}  // namespace

namespace fast_tetra_detail {
Mat3 rt_m_r(const Mat3& R, const Mat3& M) { return mul(tmul(R, M), R); }
}  // namespace fast_tetra_detail

bool parse_fast_tetra_method(const std::string& name, FastTetraMethod& out) {
  if (name == "polar") out = FastTetraMethod::polar;
  else if (name == "qr" || name == "large") out = FastTetraMethod::qr;
  else if (name == "polar2") out = FastTetraMethod::polar2;
  else if (name == "none" || name == "linear" || name == "small") out = FastTetraMethod::linear;
  else return false;
  return true;
}

std::string FastTetraCorotational::init(std::span<const Vec3> rest, const std::vector<std::array<unsigned, 4>>& tetra,
                                        const std::vector<std::array<unsigned, 2>>& edges,
                                        const std::vector<std::array<unsigned, 6>>& tetra_edges,
                                        const std::vector<double>& young, const std::vector<double>& poisson,
                                        FastTetraMethod method) {
  method_ = method;
  points_ = rest.size();
  tetra_ = tetra;
  edges_ = edges;
  tetra_edges_ = tetra_edges;
  elem_.assign(tetra.size(), Element{});
  edge_dfdx_.assign(edges.size(), Mat3::Zero());
  point_dfdx_.assign(points_, Mat3::Zero());
  update_matrix_ = true;
  if (tetra_edges_.size() != tetra_.size()) return "the topology gives no edges of its tetrahedra";

  for (std::size_t t = 0; t < tetra_.size(); ++t) {
    const auto& tv = tetra_[t];
    for (unsigned v : tv)
      if (v >= points_)
        return "tetrahedron " + std::to_string(t) + " uses point " + std::to_string(v) + " beyond the " +
               std::to_string(points_) + " points of the state";
    for (unsigned e : tetra_edges_[t])
      if (e >= edges_.size()) return "tetrahedron " + std::to_string(t) + " refers to a missing edge";
    Element& el = elem_[t];
    el.rotation.setIdentity();
    el.rest_rotation.setIdentity();

    const double E = young[t], nu = poisson[t];
    double mu = E / (2 * (1 + nu));
    double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));

    Vec3 p[4];
    for (int j = 0; j < 4; ++j) p[j] = rest[tv[j]];
    const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
    const double volume = -(dot3(cross3(a, b), c) / 6.0);
    // A flat element has no shape vectors (SOFA divides by its zero volume).
    const std::string which = "tetrahedron " + std::to_string(t) + " (points " + std::to_string(tv[0]) + " " +
                              std::to_string(tv[1]) + " " + std::to_string(tv[2]) + " " + std::to_string(tv[3]) + ")";
    if (!std::isfinite(volume)) return which + " has a non-finite rest position";
    if (volume == 0.0) return which + " is flat: zero volume at rest";
    el.rest_volume = volume;
    mu *= std::fabs(volume);
    lambda *= std::fabs(volume);

    for (int j = 0; j < 4; ++j) {
      const Vec3 cr = cross3(p[(j + 2) % 4] - p[(j + 1) % 4], p[(j + 3) % 4] - p[(j + 1) % 4]);
      const Vec3 v = (j % 2) == 0 ? cr : Vec3(-cr);
      const double d = volume * 6;
      el.shape[j] = Vec3(v[0] / d, v[1] / d, v[2] / d);
    }

    for (int j = 0; j < 4; ++j) {
      const Vec3& s = el.shape[j];
      const double val = mu * dot3(s, s);
      Mat3& D = el.diag[j];
      for (int m = 0; m < 3; ++m)
        for (int n = m; n < 3; ++n) {
          D(m, n) = lambda * s[n] * s[m] + mu * s[n] * s[m];
          if (m == n) D(m, m) += val;
          else D(n, m) = D(m, n);
        }
    }

    for (int e = 0; e < 6; ++e) {
      const int k = kEdge[e][0], l = kEdge[e][1];
      el.rest_edge[e] = p[l] - p[k];
      const Vec3 &sk = el.shape[k], &sl = el.shape[l];
      const double val = mu * dot3(sl, sk);
      Mat3& K = el.edge_k[e];
      for (int m = 0; m < 3; ++m)
        for (int n = 0; n < 3; ++n) {
          K(m, n) = lambda * sk[n] * sl[m] + mu * sl[n] * sk[m];
          if (m == n) K(m, m) += val;
        }
      el.orientation[e] = tv[k] == edges_[tetra_edges_[t][e]][0] ? 1.0 : -1.0;
    }

    if (method_ == FastTetraMethod::qr) {
      el.rest_rotation = qr_frame(el.rest_edge);
    } else if (method_ == FastTetraMethod::polar2) {
      Mat3 T;
      T.row(0) = (p[1] - p[0]).transpose();
      T.row(1) = (p[2] - p[0]).transpose();
      T.row(2) = (p[3] - p[0]).transpose();
      el.rest_rotation = polar_rotation(T);
    }
  }
  return {};
}

void FastTetraCorotational::add_force(const double* x, double* f) {
  const Vec3* X = reinterpret_cast<const Vec3*>(x);
  Vec3* F = reinterpret_cast<Vec3*>(f);
  for (std::size_t t = 0; t < tetra_.size(); ++t) {
    Element& el = elem_[t];
    const auto& tv = tetra_[t];
    const Vec3 v[4] = {X[tv[0]], X[tv[1]], X[tv[2]], X[tv[3]]};
    Vec3 displ[6];
    for (int e = 0; e < 6; ++e) displ[e] = v[kEdge[e][1]] - v[kEdge[e][0]];

    Mat3 R = Mat3::Identity();  // linear: no rotation
    switch (method_) {
      case FastTetraMethod::polar: {
        // Deformation gradient Σ_j (x_j − x_0) ⊗ s_j, from the three edges at vertex 0.
        Mat3 G;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) G(k, l) = displ[0][k] * el.shape[1][l];
        for (int j = 1; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) G(k, l) += displ[j][k] * el.shape[j + 1][l];
        R = polar_rotation(G);
        break;
      }
      case FastTetraMethod::qr:
        R = tmul(qr_frame(displ), el.rest_rotation);
        break;
      case FastTetraMethod::polar2: {
        Mat3 S;
        S.row(0) = displ[0].transpose();
        S.row(1) = displ[1].transpose();
        S.row(2) = displ[2].transpose();
        R = tmul(polar_rotation(S), el.rest_rotation);
        break;
      }
      case FastTetraMethod::linear:
        break;
    }
    el.rotation = R.transpose();

    Vec3 force[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (int e = 0; e < 6; ++e) {
      const Vec3 d = mul(el.rotation, displ[e]) - el.rest_edge[e];
      force[kEdge[e][1]] += mul(el.edge_k[e], d);
      force[kEdge[e][0]] -= tmulv(el.edge_k[e], d);
    }
    for (int j = 0; j < 4; ++j) F[tv[j]] += mul(R, force[j]);
  }
  update_matrix_ = true;
}

void FastTetraCorotational::update_edge_matrices() {
  update_matrix_ = false;
  for (Mat3& m : edge_dfdx_) m.setZero();
  for (std::size_t t = 0; t < tetra_.size(); ++t) {
    const Element& el = elem_[t];
    for (int e = 0; e < 6; ++e) {
      const Mat3 tmp = mul(el.edge_k[e], el.rotation);
      // The mesh edge may run the other way: its matrix is then the transpose.
      edge_dfdx_[tetra_edges_[t][e]] += el.orientation[e] == 1.0 ? tmul(el.rotation, tmp) : tmul(tmp, el.rotation);
    }
  }
}

void FastTetraCorotational::add_dforce(const double* dx, double* df, double kfactor) {
  if (update_matrix_) update_edge_matrices();
  const Vec3* DX = reinterpret_cast<const Vec3*>(dx);
  Vec3* DF = reinterpret_cast<Vec3*>(df);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const auto& ed = edges_[e];
    const Vec3 d = (DX[ed[1]] - DX[ed[0]]) * kfactor;
    DF[ed[1]] += mul(edge_dfdx_[e], d);
    DF[ed[0]] -= tmulv(edge_dfdx_[e], d);
  }
}

}  // namespace sinew::fem
