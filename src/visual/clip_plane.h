// ClipPlane: the half-space { p : (p - position)·normal > 0 } is not drawn
// for the visual models of the plane's node and its descendants.
#pragma once

#include "core/roles.h"

namespace sinew {

class ClipPlane final : public VisualComponent {
 public:
  Field<Vec3> position{this, "position", Vec3::Zero(), "a point of the plane", "Visualization", "length"};
  Field<Vec3> normal{this, "normal", Vec3(1, 0, 0), "plane normal, pointing to the removed half-space",
                     "Visualization"};
  Field<int> id{this, "id", 0, "OpenGL clip plane index", "Visualization"};
  Field<bool> active{this, "active", true, "apply the plane", "Visualization"};

  void init() override;
  // True when p lies in the removed half-space of an active, valid plane.
  bool clips(const Vec3& p) const;
};

}  // namespace sinew
