// AreaMapping: the area of every triangle of a topology, out_t = ½|(x1 − x0) × (x2 − x0)|
// (SOFA's Sofa.Component.Mapping.NonLinear). Input Vec3d, output Vec1d.
//
// - The topology is `topology`, else the node's (with SOFA's warning); it must have
//   triangles and no quads.
// - J row t, from the last apply: with N = (x1 − x0) × (x2 − x0) and k = 1/(2|N|),
//   ∂A/∂x0 = k (x1 − x2) × N, ∂A/∂x1 = k (x2 − x0) × N, ∂A/∂x2 = −k (x1 − x0) × N,
//   entries in increasing vertex order as SOFA inserts them.
// - Geometric stiffness: λ_t·∂²A/∂x² (SOFA's closed form, 3×3 blocks of 3×3), for every
//   triangle with Exact, for triangles with λ < 0 with Stabilized (the default).
// - A triangle of zero area has no derivative: Sinew gives it a zero row and no
//   geometric stiffness (one warning) where SOFA's formulas divide by zero.
#pragma once

#include <array>

#include "mapping/mapping_base.h"

namespace sinew {

class AreaMapping final : public MappingBase {
 public:
  AreaMapping() : MappingBase(StateType::vec3, StateType::vec1) {}

  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Stabilized",
                                         "geometric stiffness: None, Exact or Stabilized (0, 1, 2)", "Mapping"};
  Link<MeshTopologyBase> topology{this, "topology", "topology whose triangles are measured (default: the node's)"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool build_geometric_stiffness(MatrixSink& K) override;

  // ∂²A/∂xi∂xj of the triangle (v0, v1, v2): h[i][j] is a row-major 3×3 block.
  static void second_derivative(const double* v0, const double* v1, const double* v2, double h[3][3][9]);

 protected:
  bool init_mapping() override;

 private:
  std::vector<Triangle> tris_;
  std::vector<std::array<unsigned, 3>> sorted_;  // vertices of each row in increasing order
  std::vector<double> grad_;                     // 9 per triangle, in sorted_ order
  std::vector<double> verts_;                    // 9 per triangle: the vertices at the last apply
  std::vector<unsigned char> degenerate_;
  bool warned_degenerate_ = false;
  int gs_ = 2;
};

}  // namespace sinew
