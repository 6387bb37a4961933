// TetrahedronFEMForceField: linear elasticity on tetrahedra, linear (small)
// or corotational (large: 3-node frame, polar, svd), with optional plasticity
// and the hexahedron split fallback (spec/mechanics.md §2.1).
// The numerical kernel lives in forcefield/tetra_fem.h.
#pragma once

#include "core/roles.h"
#include "core/rotation_finder.h"
#include "forcefield/fem/tetra_fem.h"

namespace sinew {

class TetrahedronFEMForceField final : public ForceField, public RotationFinder {
 public:
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {5000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.45}, "Poisson's ratio in [0, 0.5): one value, or one per element", "Material", "dimensionless"};
  Field<std::string> method{this, "method", "large",
                            "\"small\", \"large\" (by QR), \"polar\" or \"svd\" displacements", "Material"};
  Field<std::vector<double>> local_stiffness_factor{
      this, "localStiffnessFactor", {},
      "per-element Young's modulus factor: element i uses localStiffnessFactor[i*M/N] (M values, N elements)",
      "Material"};
  Field<bool> update_stiffness_matrix{this, "updateStiffnessMatrix", false,
                                      "recompute the strain-displacement matrix from the current shape", "Material"};
  Field<bool> assembling{this, "computeGlobalMatrix", false,
                         "compute the force through the assembled element matrix (alias: assembling)", "Material"};
  Field<double> plastic_max_threshold{this, "plasticMaxThreshold", 0.0,
                                      "upper bound on the plastic strain norm; 0 disables plasticity", "Plasticity"};
  Field<double> plastic_yield_threshold{this, "plasticYieldThreshold", static_cast<double>(0.0001f),
                                        "strain norm above which plastic flow starts", "Plasticity"};
  Field<double> plastic_creep{this, "plasticCreep", static_cast<double>(0.9f),
                              "share of the excess strain made plastic per step, in [0, 1] (depends on dt)",
                              "Plasticity"};
  Field<std::string> gather_pt{this, "gatherPt", "", "unused (GPU version only)", "Material"};
  Field<std::string> gather_bsize{this, "gatherBsize", "", "unused (GPU version only)", "Material"};
  Field<bool> update_stiffness{this, "updateStiffness", false,
                               "recompute the material matrices at each time step (same values)", "Material"};
  Field<std::vector<Vec3>> initial_points{this, "initialPoints", {}, "rest positions copied at init (output)",
                                          "Material"};
  Field<int> compute_von_mises_stress{this, "computeVonMisesStress", 0,
                                      "0: no von Mises stress, 1: from the corotational strain, 2: from the Green "
                                      "strain (output only)",
                                      "Stress"};
  Field<std::vector<double>> von_mises_per_element{this, "vonMisesPerElement", {}, "von Mises stress per element",
                                                   "Stress"};
  Field<std::vector<double>> von_mises_per_node{this, "vonMisesPerNode", {}, "von Mises stress per node", "Stress"};
  Field<bool> draw_heterogeneous_tetra{this, "drawHeterogeneousTetra", false,
                                       "draw heterogeneous tetrahedra in different colours (viewer)", "Visualization"};
  Field<std::string> show_stress_color_map{this, "showStressColorMap", "Blue to Red",
                                           "colour map of the stress (viewer)", "Visualization"};
  Field<float> show_stress_alpha{this, "showStressAlpha", 1.0f, "alpha of the stress display (viewer)",
                                 "Visualization"};
  Field<bool> show_von_mises_per_node{this, "showVonMisesStressPerNode", false,
                                      "draw von Mises stress at nodes (viewer)", "Visualization"};
  Field<bool> show_von_mises_per_node_color_map{this, "showVonMisesStressPerNodeColorMap", false,
                                                "draw elements coloured by nodal von Mises stress (viewer)",
                                                "Visualization"};
  Field<bool> show_von_mises_per_element{this, "showVonMisesStressPerElement", false,
                                         "draw elements coloured by their von Mises stress (viewer)",
                                         "Visualization"};
  Field<double> show_element_gap_scale{this, "showElementGapScale", 0.333,
                                       "gap between drawn elements in [0,1] (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the tetrahedra (default: the node's)"};

  TetrahedronFEMForceField();
  void init() override;
  void reinit() override { init(); }  // recompute everything from the fields (SOFA reinit)
  void reset() override;
  void handle_event(Event& ev) override;
  bool wants_events() const override { return listening.value() || von_mises_mode_ != 0; }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  // SOFA's getPotentialEnergy, small method only: ½·Σ_e uᵀ·K_e·u with u = x − X0
  // (plastic strains ignored, as SOFA does). None for the corotational methods.
  std::optional<double> potential_energy() const override;

  const fem::TetraFEM& kernel() const { return fem_; }
  // Per-point rotations for the Warp/PrecomputedWarp preconditioners (SOFA getRotations).
  void node_rotations(std::span<Mat3> out) const override { fem_.node_rotations(out, !fem_.split_from_hexahedra); }
  MechanicalState* rotation_state() const override { return mstate.get(); }

 private:
  void update_von_mises();
  fem::TetraFEM fem_;
  int von_mises_mode_ = 0;  // 0: off; 1, 2: SOFA computeVonMisesStress
};

}  // namespace sinew
