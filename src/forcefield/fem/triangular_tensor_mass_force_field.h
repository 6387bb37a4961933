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
// The edge tensors follow topological changes as SOFA's edge data do: a
// removed triangle subtracts its terms (recomputed from the rest positions),
// removed edges swap with the last, added edges start at 0 and added triangles
// add their terms. As in SOFA, x₀ is taken once at init and does not follow
// point removal (a warning says so); added points get their rest position
// (SOFA would read past its array).
#pragma once

#include <optional>
#include <vector>

#include "core/roles.h"
#include "core/topology_change.h"

namespace sinew {

class TriangularTensorMassForceField final : public ForceField {
 public:
  Field<double> poisson_ratio{this, "poissonRatio", 0.3, "Poisson ratio in Hooke's law", "Physics"};
  Field<double> young_modulus{this, "youngModulus", 1000.0, "Young's modulus in Hooke's law", "Physics",
                              "pressure (force/length²)"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  std::optional<double> potential_energy() const override { return energy_; }

  double lambda() const { return lambda_; }
  double mu() const { return mu_; }
  // The edge tensors D (SOFA's EdgeRestInformation::DfDx), one per edge of the topology.
  const std::vector<Mat3>& edge_tensors() const { return edge_tensor_; }
  const std::vector<Vec3>& initial_points() const { return initial_points_; }

 private:
  void rebuild();
  // Adds (sign +1) or subtracts (−1) triangle i's terms to its edges; false for a degenerate triangle.
  bool triangle_terms(unsigned i, const MeshTopologyBase& t, double sign);

  double lambda_ = 0, mu_ = 0;
  std::vector<Mat3> edge_tensor_;
  std::vector<Vec3> initial_points_;
  double energy_ = 0;
  bool warned_points_ = false;

  struct Follow final : TopologyHandler {
    TriangularTensorMassForceField* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
};

}  // namespace sinew
