// FastTetrahedralCorotationalForceField: corotational linear elasticity of
// tetrahedra with the stiffness stored per mesh edge (kernel and formulas in
// forcefield/fem/fast_tetra_corotational.h). Methods: "qr" (default, also
// "large"), "polar", "polar2", "linear" (also "none", "small").
//
// Material as SOFA's linear-elasticity FEM components: youngModulus and
// poissonRatio hold one value or one per tetrahedron (element i uses value i,
// else the first); a negative Young's modulus is replaced by 5000 and a
// Poisson's ratio outside [0, 0.5) by 0.45, with a warning. The topology must
// give its edges and the edges of each tetrahedron (SOFA's edge-based storage);
// when its tetrahedra or edges change the element data are rebuilt from the
// rest positions (the same values SOFA keeps per element). Material rules:
// spec/mechanics.md §0.4.
#pragma once

#include <cstdint>

#include "core/roles.h"
#include "forcefield/fem/fast_tetra_corotational.h"

namespace sinew {

class FastTetrahedralCorotationalForceField final : public ForceField {
 public:
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {5000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.45}, "Poisson's ratio in [0, 0.5): one value, or one per element", "Material", "dimensionless"};
  Field<std::string> method{this, "method", "qr",
                            "rotation: \"qr\" (or \"large\"), \"polar\", \"polar2\" or \"linear\" (or \"none\", \"small\")",
                            "Material"};
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

  void init() override;
  void reinit() override { init(); }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const fem::FastTetraCorotational& kernel() const { return fem_; }

 private:
  // Rebuilds the element data when the topology's tetrahedra or edges moved.
  void follow_topology();
  bool setup();
  fem::FastTetraCorotational fem_;
  fem::FastTetraMethod method_ = fem::FastTetraMethod::qr;  // parsed at init
  std::uint64_t tetra_version_ = 0, edge_version_ = 0;
};

}  // namespace sinew
