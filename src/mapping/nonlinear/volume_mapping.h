// VolumeMapping: the signed volume of every tetrahedron of a topology,
// out_t = (x1 − x0)·((x2 − x0) × (x3 − x0))/6, negative when inverted (SOFA's
// Sofa.Component.Mapping.NonLinear). Input Vec3d, output Vec1d.
//
// - The topology is `topology`, else the node's (with SOFA's warning); it must have
//   tetrahedra and no hexahedra.
// - J row t, from the last apply: with v_k = x_k − x0, c0 = v2 × v3/6, c1 = v3 × v1/6,
//   c2 = v1 × v2/6: ∂V/∂x0 = −(c0 + c1 + c2), ∂V/∂x1 = c0, ∂V/∂x2 = c1,
//   ∂V/∂x3 = c2, entries in increasing vertex order as SOFA inserts them.
// - Geometric stiffness: λ_t·∂²V/∂x², whose blocks are skew matrices
//   (H01 = [x2 − x3]×/6, ...; zero diagonal blocks), for every tetrahedron with Exact,
//   for λ < 0 with Stabilized (the default).
#pragma once

#include <array>

#include "mapping/mapping_base.h"

namespace sinew {

class VolumeMapping final : public MappingBase {
 public:
  VolumeMapping() : MappingBase(StateType::vec3, StateType::vec1) {}

  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Stabilized",
                                         "geometric stiffness: None, Exact or Stabilized (0, 1, 2)", "Mapping"};
  Link<MeshTopologyBase> topology{this, "topology", "topology whose tetrahedra are measured (default: the node's)"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool build_geometric_stiffness(MatrixSink& K) override;

  // ∂²V/∂xi∂xj of the tetrahedron x (4 points, 12 scalars) for i < j: h[i][j] row-major 3×3
  // (h[j][i] is its transpose; the diagonal blocks are zero).
  static void second_derivative(const double* x, double h[4][4][9]);

 protected:
  bool init_mapping() override;

 private:
  std::vector<Tetra> tets_;
  std::vector<std::array<unsigned, 4>> sorted_;  // vertices of each row in increasing order
  std::vector<double> grad_;                     // 12 per tetrahedron, in sorted_ order
  std::vector<double> verts_;                    // 12 per tetrahedron: the vertices at the last apply
  int gs_ = 2;
};

}  // namespace sinew
