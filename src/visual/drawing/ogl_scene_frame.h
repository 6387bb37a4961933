// OglSceneFrame (Sofa.GL.Component.Rendering3D): the axes x (red), y (green), z (blue) turned
// as the camera sees the world, drawn unlit in a square viewport of `viewportSize` pixels in a
// corner of the picture (src/render), over the scene.
#pragma once

#include <string>

#include "core/roles.h"

namespace sinew {

class OglSceneFrame final : public VisualComponent {
 public:
  Field<bool> draw{this, "draw", true, "display the frame", "Visualization"};
  Field<std::string> style{this, "style", "Cylinders", "Arrows, Cylinders or CubeCones", "Visualization"};
  Field<std::string> alignment{this, "alignment", "BottomRight", "BottomLeft, BottomRight, TopRight or TopLeft",
                               "Visualization"};
  Field<int> viewport_size{this, "viewportSize", 150, "size of the frame's viewport (pixels)", "Visualization"};
  void parse(AttributeMap& attrs, Diagnostics& diag) override;
};

}  // namespace sinew
