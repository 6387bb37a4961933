// TetrahedralTensorMassForceField: linear elasticity on a tetrahedral mesh
// (SOFA's component of that name, Vec3d), written as one 3×3 tensor per edge.
//
// Per tetrahedron (rest positions p, V6 = (p1−p0)×(p2−p0)·(p0−p3) six times
// the signed rest volume, λ = Eν/((1−2ν)(1+ν)), μ = E/(2(1+ν))), the shape
// vectors are s_j = ±(p_{j+2}−p_{j+1})×(p_{j+3}−p_{j+1})/V6 (indices mod 4,
// + for even j), λ* = λ|V6|/6, μ* = μ|V6|/6, and the edge (k, l) of local
// edge j receives
//   λ*·s_l s_kᵀ + μ*·s_k s_lᵀ + μ*(s_k·s_l)·I,
// transposed when the edge is stored from p_l to p_k. Forces, tensors
// following topological changes and energy: EdgeTensorForceField.
// One difference from SOFA, on purpose: when a tetrahedron is removed, SOFA
// adds its terms back (instead of subtracting them) on the edges stored from
// p_l to p_k, a sign slip that leaves the remaining body stiffer than its
// elements; Sinew subtracts them (removal then equals a rebuild, tested).
#pragma once

#include "forcefield/fem/edge_tensor_force_field.h"

namespace sinew {

class TetrahedralTensorMassForceField final : public EdgeTensorForceField {
 public:
  TetrahedralTensorMassForceField()
      : EdgeTensorForceField({"tetrahedra", "a tetrahedral mesh is required", TopologyChangeType::tetrahedra_added,
                              TopologyChangeType::tetrahedra_removed}) {}

 private:
  bool elements_ready(const MeshTopologyBase& t) override;
  bool lame(double E, double nu, double& lambda, double& mu) override;
  std::size_t element_count(const MeshTopologyBase& t) const override { return t.tetrahedra().size(); }
  bool element_terms(unsigned i, const MeshTopologyBase& t, double sign) override;
};

}  // namespace sinew
