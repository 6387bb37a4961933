// QuadPressureForceField: a pressure (force per unit area, a vector) on
// quads of the topology, SOFA's QuadPressureForceField (template Vec3d):
// each of a quad's four vertices receives P·A/4, A the quad's rest area
// (the two triangles (0,1,2) and (0,2,3)). The quads are `quadList`, or when
// `dmin` ≠ `dmax` those whose four rest vertices lie strictly between the
// planes normal·x = dmin and normal·x = dmax. No stiffness; the forces are
// computed on the rest shape, so they do not follow the deformation.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class QuadPressureForceField final : public ForceField {
 public:
  Field<Vec3> pressure{this, "pressure", Vec3::Zero(), "pressure vector (force per unit area)", "Load",
                       "pressure (force/length²)"};
  Field<std::vector<unsigned>> quad_list{this, "quadList", {}, "indices of the loaded quads", "Load"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "normal of the planes selecting quads (dmin ≠ dmax)", "Load"};
  Field<double> dmin{this, "dmin", 0.0, "lower plane offset along the normal", "Load", "length"};
  Field<double> dmax{this, "dmax", 0.0, "upper plane offset along the normal", "Load", "length"};
  Field<bool> show_forces{this, "showForces", false, "draw the loaded quads (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the quads (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

  const std::vector<unsigned>& loaded_quads() const { return list_; }

 private:
  std::vector<unsigned> list_;
  std::vector<Quad> quads_;
  std::vector<double> area_;
};

}  // namespace sinew
