// TriangularTensorMassForceField: linear elastic membrane on a triangle mesh
// (SOFA's component of that name, Vec3d), written as one 3×3 tensor per edge.
//
// Per triangle (rest positions p, rest area A₀, rest cotangents c_j,
// λ = Eν/(1−ν²), μ = E(1−ν)/(1−ν²)), the edge opposite vertex j (between
// k = j+1 and l = j+2) receives
//   λ/(4A₀)·(p_j−p_k)(p_j−p_l)ᵀ + μ/(8A₀)·(p_j−p_l)(p_j−p_k)ᵀ − c_j(λ+μ)/2·I,
// transposed when the edge is stored from p_k to p_l. With u = x − x₀ (x₀ the
// rest positions at init), edge (v0, v1) gives f[v1] += D·(u₁−u₀) and
// f[v0] −= Dᵀ·(u₁−u₀); add_dforce applies the same tensors to dx (exact: the
// force is linear). SOFA's getPotentialEnergy returns 0; potential_energy()
// here returns −½·u·f(u).
// The tensors, forces and topology following are EdgeTensorForceField's.
#pragma once

#include "forcefield/fem/edge_tensor_force_field.h"

namespace sinew {

class TriangularTensorMassForceField final : public EdgeTensorForceField {
 public:
  TriangularTensorMassForceField()
      : EdgeTensorForceField({"triangles", "a triangular mesh is required", TopologyChangeType::triangles_added,
                              TopologyChangeType::triangles_removed}) {}

 private:
  bool elements_ready(const MeshTopologyBase& t) override;
  bool lame(double E, double nu, double& lambda, double& mu) override;
  std::size_t element_count(const MeshTopologyBase& t) const override { return t.triangles().size(); }
  bool element_terms(unsigned i, const MeshTopologyBase& t, double sign) override;
};

}  // namespace sinew
