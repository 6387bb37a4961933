// EdgeTensorForceField: the linear elastic "tensor-mass" models of SOFA
// (TriangularTensorMassForceField, TetrahedralTensorMassForceField), which
// store the stiffness as one 3×3 tensor D per edge of the mesh.
//
// With u = x − x₀ (x₀ the rest positions taken once at init), an edge
// (v0, v1) gives f[v1] += D·(u₁−u₀) and f[v0] −= Dᵀ·(u₁−u₀); add_dforce
// applies the same tensors to dx (exact: the force is linear). The element
// kind supplies the terms each element adds to its edges (element_terms) and
// the topological events that add and remove its elements; this class keeps
// the tensors following the topology as SOFA's edge data do: a removed element
// subtracts its terms (recomputed from the rest positions), removed edges swap
// with the last, added edges start at 0, added elements add their terms. As in
// SOFA, x₀ does not follow point removal (a warning says so); added points get
// their rest position (SOFA would read past its array). potential_energy()
// is −½·u·f(u), as SOFA's tetrahedral getPotentialEnergy (its triangular one
// returns 0).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "core/roles.h"
#include "core/topology_change.h"

namespace sinew {

class EdgeTensorForceField : public ForceField {
 public:
  Field<double> poisson_ratio{this, "poissonRatio", 0.3, "Poisson ratio in Hooke's law", "Physics"};
  Field<double> young_modulus{this, "youngModulus", 1000.0, "Young's modulus in Hooke's law", "Physics",
                              "pressure (force/length²)"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the elements (default: the node's)"};

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

 protected:
  struct ElementKind {
    std::string_view plural;               // "triangles", "tetrahedra" (messages)
    std::string_view requirement;          // what the topology must be ("a triangular mesh is required")
    TopologyChangeType added, removed;     // the events of this element kind
  };
  explicit EdgeTensorForceField(ElementKind kind) : kind_(kind) {}

  // The element lists of `t` index the state and `t` gives each element's edges; the
  // Lamé pair is finite. False, with an error, otherwise (the component becomes invalid).
  virtual bool elements_ready(const MeshTopologyBase& t) = 0;
  virtual bool lame(double E, double nu, double& lambda, double& mu) = 0;
  virtual std::size_t element_count(const MeshTopologyBase& t) const = 0;
  // Adds (sign +1) or subtracts (−1) element i's terms to its edges, from the rest
  // positions; false, with an error naming the element, for a degenerate one.
  virtual bool element_terms(unsigned i, const MeshTopologyBase& t, double sign) = 0;

  std::vector<Mat3> edge_tensor_;
  double lambda_ = 0, mu_ = 0;

 private:
  void rebuild();

  ElementKind kind_;
  std::vector<Vec3> initial_points_;
  double energy_ = 0;
  bool warned_points_ = false;

  struct Follow final : TopologyHandler {
    EdgeTensorForceField* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
};

}  // namespace sinew
