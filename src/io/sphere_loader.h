// SphereLoader: sphere centres and radii from a .sph file (spec/mechanics.md §7.5).
// Centres are transformed (T·R·S, rotation in Euler degrees); radii are not scaled.
// Loading is lazy like MeshLoader's: the first read of an output loads the file.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class SphereLoader final : public Engine {
 public:
  SphereLoader();

  Field<std::string> filename{this, "filename", "", "sphere file (.sph) to load", "Loader"};
  Field<std::vector<Vec3>> position{this, "position", {}, "sphere centres", "Vectors", "length"};
  Field<std::vector<double>> list_radius{this, "listRadius", {}, "radius of each sphere", "Vectors"};
  Field<Vec3> scale{this, "scale", Vec3::Ones(), "scale applied to the sphere centres", "Transformation"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation of the centres (Euler angles, degrees)",
                       "Transformation", "degrees"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation applied to the centres", "Transformation", "length"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
