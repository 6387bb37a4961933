// TetrahedralCorotationalFEMForceField: the older tetrahedral corotational FEM
// (methods large, polar, small), same kernel as TetrahedronFEMForceField
// without plasticity, svd or hexahedron split (spec/mechanics.md §2.2).
#pragma once

#include "core/roles.h"
#include "core/topology_change.h"
#include "forcefield/fem/tetra_fem.h"

namespace sinew {

class TetrahedralCorotationalFEMForceField final : public ForceField {
 public:
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {5000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.45}, "Poisson's ratio in [0, 0.5): one value, or one per element", "Material", "dimensionless"};
  Field<std::string> method{this, "method", "large", "\"small\", \"large\" (by QR) or \"polar\" displacements",
                            "Material"};
  Field<std::vector<double>> local_stiffness_factor{
      this, "localStiffnessFactor", {},
      "per-element Young's modulus factor: element i uses localStiffnessFactor[i*M/N] (M values, N elements)",
      "Material"};
  Field<bool> update_stiffness_matrix{this, "updateStiffnessMatrix", false,
                                      "recompute the strain-displacement matrix from the current shape", "Material"};
  Field<bool> assembling{this, "computeGlobalMatrix", false,
                         "compute the force through the assembled element matrix (alias: assembling)", "Material"};
  Field<bool> compute_von_mises_stress{this, "computeVonMisesStress", false,
                                       "compute the von Mises stress (output only)", "Stress"};
  Field<std::vector<double>> von_mises_per_element{this, "vonMisesPerElement", {}, "von Mises stress per element",
                                                   "Stress"};
  Field<std::vector<double>> von_mises_per_node{this, "vonMisesPerNode", {}, "von Mises stress per node", "Stress"};
  Field<bool> drawing{this, "drawing", true, "draw the force field (viewer)", "Visualization"};
  Field<std::vector<double>> draw_color1{this, "drawColor1", {0.0, 0.0, 1.0, 1.0}, "colour of faces 1 (viewer)",
                                         "Visualization"};
  Field<std::vector<double>> draw_color2{this, "drawColor2", {0.0, 0.5, 1.0, 1.0}, "colour of faces 2 (viewer)",
                                         "Visualization"};
  Field<std::vector<double>> draw_color3{this, "drawColor3", {0.0, 1.0, 1.0, 1.0}, "colour of faces 3 (viewer)",
                                         "Visualization"};
  Field<std::vector<double>> draw_color4{this, "drawColor4", {0.5, 1.0, 1.0, 1.0}, "colour of faces 4 (viewer)",
                                         "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the tetrahedra (default: the node's)"};

  TetrahedralCorotationalFEMForceField();
  void init() override;
  void reinit() override { init(); }  // recompute everything from the fields (SOFA reinit)
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const fem::TetraFEM& kernel() const { return fem_; }

 private:
  // Topological changes. Removals are followed element by element (SOFA's per-element data:
  // swap-with-last of the element arrays, points renamed) by a handler on the container, so a
  // few removed elements do not cost a re-initialisation; anything else that moves the
  // tetrahedron list (additions, per-element materials, von Mises outputs) rebuilds the
  // element data from the rest positions, which follow the points: the same values.
  class Follower final : public TopologyHandler {
   public:
    explicit Follower(TetrahedralCorotationalFEMForceField& ff) : ff_(ff) {}
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override { ff_.on_change(c); }

   private:
    TetrahedralCorotationalFEMForceField& ff_;
  };
  void on_change(const TopologyChange& c);
  void follow_topology();
  fem::TetraFEM fem_;
  std::uint64_t tetra_version_ = 0;
  Follower follower_{*this};
  bool per_element_ = false;   // removals followed element by element
  bool needs_init_ = false;    // a change the follower cannot apply: rebuild at the next use
  bool changed_ = false;       // removals applied since the last ending event
};

}  // namespace sinew
