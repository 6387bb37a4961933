// TrianglePressureForceField: a pressure (force per unit area, a vector) on a
// list of topology triangles: each vertex receives P·A/3 with A the rest area
// (useConstantForce), or σ·((x1−x0)×(x2−x0))/6 with the Cauchy stress σ
// (spec/mechanics.md §3.10). No stiffness.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class TrianglePressureForceField final : public ForceField {
 public:
  Field<Vec3> pressure{this, "pressure", Vec3::Zero(), "pressure vector (force per unit area)", "Load", "pressure (force/length²)"};
  Field<std::vector<double>> cauchy_stress{
      this,
      "cauchyStress",
      {0, 0, 0, 0, 0, 0},
      "Cauchy stress (xx xy yy xz yz zz) whose traction on each triangle normal is applied",
      "Load"};
  Field<std::vector<unsigned>> triangle_list{this, "triangleList", {}, "indices of the loaded triangles", "Load"};
  Field<bool> show_forces{this, "showForces", false, "draw the loaded triangles (viewer)", "Visualization"};
  Field<bool> use_constant_force{this, "useConstantForce", true, "apply constant forces computed on the rest shape",
                                 "Load"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

 private:
  bool rebuild(bool read_list);
  std::vector<unsigned> list_;      // triangle indices in use
  std::vector<Triangle> tris_;      // their vertices
  std::vector<Vec3> force_;         // P·A per triangle
  Vec3 pressure_seen_ = Vec3::Zero();  // pressure read at init
  std::uint64_t triangles_version_ = 0;  // of the list the elements were built from
};

}  // namespace sinew
