// HexahedronFEMForceField: linear elasticity on hexahedra, corotational
// (method large or polar) or linear (small) (spec/mechanics.md §2.3).
// The numerical kernel lives in forcefield/hexa_fem.h.
#pragma once

#include "core/roles.h"
#include "core/rotation_finder.h"
#include "forcefield/hexa_fem.h"

namespace sinew {

class HexahedronFEMForceField final : public ForceField, public RotationFinder {
 public:
  Field<std::vector<double>> young_modulus{this, "youngModulus", {5000.0},
                                           "Young's modulus (Pa), one value or one per element", "Material"};
  Field<std::vector<double>> poisson_ratio{this, "poissonRatio", {0.45},
                                           "Poisson's ratio in [0, 0.5), one value or one per element", "Material"};
  Field<std::string> method{this, "method", "large", "large (corotational), polar or small (linear)", "Material"};
  Field<bool> update_stiffness_matrix{this, "updateStiffnessMatrix", false,
                                      "recompute element stiffness from current positions each step", "Material"};
  Field<std::string> gather_pt{this, "gatherPt", " ", "unused (kept for SOFA compatibility)", "Material"};
  Field<std::string> gather_bsize{this, "gatherBsize", " ", "unused (kept for SOFA compatibility)", "Material"};
  Field<bool> drawing{this, "drawing", true, "draw the elements (viewer)", "Visualization"};
  Field<double> draw_percentage_offset{this, "drawPercentageOffset", 0.15, "element shrink factor (viewer)",
                                       "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the hexahedra (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const fem::HexaFEM& kernel() const { return fem_; }
  // Per-point rotations for the Warp/PrecomputedWarp preconditioners (SOFA getRotations).
  void node_rotations(std::span<Mat3> out) const override { fem_.node_rotations(out); }
  MechanicalState* rotation_state() const override { return mstate.get(); }

 private:
  fem::HexaFEM fem_;
};

}  // namespace sinew
