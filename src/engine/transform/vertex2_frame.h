// Vertex2Frame: a Rigid3d frame at each vertex of a mesh (SOFA's
// Engine/Transform). With useNormals, z is the vertex normal (negated with
// invertNormals), x = y₀ × z with y₀ = +y (or +z when the normal is along y),
// y = z × x. Without normals, x points to the next vertex, y = z₀ × x with
// z₀ = +x (or +z when x is along it), z = x × y; the last vertex copies the
// previous orientation. The orientation is then turned by rotationAngle
// degrees about the frame's axis `rotation` (0 x, 1 y, 2 z), SOFA's
// q = axisToQuat(axis, angle) · fromFrame(x, y, z).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class Vertex2Frame final : public Engine {
 public:
  Vertex2Frame();

  Field<std::vector<Vec3>> position{this, "position", {}, "vertices of the mesh", "Inputs", "length"};
  Field<std::vector<Vec2>> tex_coords{this, "texCoords", {}, "texture coordinates of the mesh (unused)", "Inputs"};
  Field<std::vector<Vec3>> normals{this, "normals", {}, "normals of the mesh", "Inputs"};
  Field<FlatVec> frames;
  Field<bool> use_normals{this, "useNormals", true, "z axis along the normals (else x towards the next vertex)",
                          "Inputs"};
  Field<bool> invert_normals{this, "invertNormals", false, "negate the normals", "Inputs"};
  Field<int> rotation{this, "rotation", 0, "axis of the extra rotation (0 x, 1 y, 2 z)", "Inputs"};
  Field<double> rotation_angle{this, "rotationAngle", 0.0, "angle of the extra rotation (degrees)", "Inputs",
                               "degrees"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
