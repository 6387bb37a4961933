// PointSplatModel (SOFA's Sofa.GL.Component.Rendering3D): draws the points of the node's state
// as soft round billboards facing the camera (a cosine falloff of opacity `alpha` at the centre),
// optionally brightened per point by pointData, sorted back to front and blended in SOFA's
// transparent pass. Drawn by src/render; batch runs only check its inputs.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class PointSplatModel final : public VisualComponent {
 public:
  Field<double> radius{this, "radius", 1.0, "radius of the billboards", "Visualization", "length"};
  Field<int> texture_size{this, "textureSize", 32, "size in texels of the billboard texture", "Visualization"};
  Field<double> alpha{this, "alpha", 1.0, "opacity of the billboards (1: opaque)", "Visualization"};
  Field<std::string> color{this, "color", "1 1 1 1", "billboard colour", "Visualization"};
  Field<std::vector<unsigned>> point_data{this, "pointData", {}, "per-point values (0-255) modulating the colour",
                                          "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the points", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;

};

}  // namespace sinew
