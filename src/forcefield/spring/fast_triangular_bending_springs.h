// FastTriangularBendingSprings: Volino's linear bending force on each edge
// shared by two triangles (spec/mechanics.md §3.6). For the 4 vertices
// (A, B opposite the edge, C, D on it) the weights α and stiffness λ come
// from the rest shape; the force is f_k −= λ·α_k·Σ α_j x_j (flat rest shape),
// with the constant stiffness K_jk = −λ·α_j·α_k·I.
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"
#include "forcefield/spring/triangle_adjacency.h"

namespace sinew {

class FastTriangularBendingSprings final : public ForceField {
 public:
  Field<double> bending_stiffness{this, "bendingStiffness", 1.0, "bending stiffness", "Material"};
  Field<double> min_dist_validity{this, "minDistValidity", 0.000001, "bending springs shorter than this are ignored",
                                  "Material"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  struct EdgeSpring {
    std::array<unsigned, 4> vid{};  // A, B (opposite vertices), C, D (edge)
    std::array<double, 4> alpha{};
    double lambda = 0;
    bool active = false;
  };

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<EdgeSpring>& edge_springs() const { return springs_; }
  // Energy of the last add_force (SOFA's m_potentialEnergy).
  std::optional<double> potential_energy() const override { return energy_; }

 private:
  bool rebuild();
  void check_topology();
  std::vector<EdgeSpring> springs_;  // one per topology edge (inactive where not between 2 triangles)
  // Versions of the lists the springs/elements were built from (topology changes).
  std::uint64_t triangles_version_ = 0, edges_version_ = 0;
  double energy_ = 0;
};

}  // namespace sinew
