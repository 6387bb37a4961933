// Kernel of FastTetrahedralCorotationalForceField (SOFA's component of that
// name; the spec has no section on it): linear elasticity of 4-node tetrahedra
// written with shape vectors, corotated per element by one of four rotations,
// the stiffness stored per mesh edge.
//
// Per tetrahedron, at rest (positions X, signed volume V = −det/6 of SOFA's
// geometry helper, Lamé λ, μ scaled by |V|):
//   shape vector s_j = ±(X_{j+2} − X_{j+1}) × (X_{j+3} − X_{j+1}) / (6V)   (+ for even j)
//   edge e = (k, l) (SOFA's local edge table):  K_e = λ s_l⊗s_k + μ s_k⊗s_l + μ (s_l·s_k) I
//   vertex j:                                   D_j = (λ+μ) s_j⊗s_j + μ (s_j·s_j) I
// Force: with Rᵀ the rotation current → rest of the element and d_e the
// current edge vector rotated back (Rᵀ(x_l − x_k)) minus the rest edge vector,
//   F_l += K_e d_e,  F_k −= K_eᵀ d_e,  then f_j += R F_j.
// dF is accumulated per mesh edge: E = Σ Rᵀ K_e R over the tetrahedra sharing
// it (transposed when the tetrahedron runs the edge the other way), and
// df_b += kfactor·E (dx_b − dx_a), df_a −= kfactor·Eᵀ (dx_b − dx_a): the vertex
// blocks never appear (they are minus the sum of the edge blocks). The
// assembled matrix uses them: diagonal block i = −Σ Rᵀ D_j R.
//
// Every product is written out in SOFA's order (results are compared with
// SOFA's to round-off).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "math/types.h"

namespace sinew::fem {

enum class FastTetraMethod {
  polar,   // polar decomposition of the deformation gradient
  qr,      // frame of the first two edges, relative to the same frame at rest
  polar2,  // polar decomposition of the three edges from vertex 0, relative to the same at rest
  linear   // no rotation (small displacements)
};

// SOFA's method names: "polar", "qr"/"large", "polar2", "none"/"linear"/"small".
// Returns false for any other name.
bool parse_fast_tetra_method(const std::string& name, FastTetraMethod& out);

class FastTetraCorotational {
 public:
  struct Element {
    Vec3 shape[4];           // shape vectors at rest (1/length)
    double rest_volume = 0;  // signed, as SOFA stores it
    Vec3 rest_edge[6];       // X_l − X_k for local edge (k, l)
    Mat3 diag[4];            // D_j (force/length)
    Mat3 edge_k[6];          // K_e (force/length)
    Mat3 rotation;           // Rᵀ of the last add_force: current → rest
    Mat3 rest_rotation;      // qr and polar2: rotation of the rest shape
    double orientation[6];   // +1 when local edge e runs as the mesh edge does, else −1
  };

  // Builds the per-element data. `young`, `poisson`: one value per tetrahedron
  // (already validated by the caller). `tetra_edges[t][e]`: mesh edge of local
  // edge e of tetrahedron t. Returns an empty string, or the problem (a flat
  // tetrahedron, an index beyond the points) naming the element.
  std::string init(std::span<const Vec3> rest, const std::vector<std::array<unsigned, 4>>& tetra,
                   const std::vector<std::array<unsigned, 2>>& edges,
                   const std::vector<std::array<unsigned, 6>>& tetra_edges, const std::vector<double>& young,
                   const std::vector<double>& poisson, FastTetraMethod method);

  // f += internal force at positions x (both length 3·points).
  void add_force(const double* x, double* f);
  // df += kfactor · K · dx, K from the rotations of the last add_force.
  void add_dforce(const double* dx, double* df, double kfactor);
  // Raw blocks of K = ∂f/∂x: block(i, j, B) adds B at point rows i, columns j.
  // Diagonal blocks first (one per point), then two per mesh edge, as SOFA.
  template <class Block>
  void stiffness_blocks(Block&& block);

  std::size_t size() const { return tetra_.size(); }
  const std::vector<Element>& elements() const { return elem_; }
  FastTetraMethod method() const { return method_; }

 private:
  void update_edge_matrices();

  FastTetraMethod method_ = FastTetraMethod::qr;
  std::size_t points_ = 0;
  std::vector<std::array<unsigned, 4>> tetra_;
  std::vector<std::array<unsigned, 2>> edges_;
  std::vector<std::array<unsigned, 6>> tetra_edges_;
  std::vector<Element> elem_;
  std::vector<Mat3> edge_dfdx_;   // E per mesh edge
  std::vector<Mat3> point_dfdx_;  // Σ Rᵀ D R per point (assembly only)
  bool update_matrix_ = true;     // rotations moved since E was summed
};

// ---- inline: the assembly walk

namespace fast_tetra_detail {
Mat3 rt_m_r(const Mat3& R, const Mat3& M);  // Rᵀ·M·R evaluated as (Rᵀ·M)·R
}

template <class Block>
void FastTetraCorotational::stiffness_blocks(Block&& block) {
  if (update_matrix_) update_edge_matrices();
  for (Mat3& p : point_dfdx_) p.setZero();
  for (std::size_t t = 0; t < tetra_.size(); ++t)
    for (int j = 0; j < 4; ++j)
      point_dfdx_[tetra_[t][j]] += fast_tetra_detail::rt_m_r(elem_[t].rotation, elem_[t].diag[j]);
  for (std::size_t i = 0; i < points_; ++i) block(i, i, Mat3(-point_dfdx_[i]));
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    block(edges_[e][0], edges_[e][1], Mat3(-edge_dfdx_[e].transpose()));
    block(edges_[e][1], edges_[e][0], Mat3(-edge_dfdx_[e]));
  }
}

}  // namespace sinew::fem
