// PointSplatModel (SOFA's Sofa.GL.Component.Rendering3D): draws the points of
// the node's state as soft round billboards (a cosine falloff texture of
// textureSize² texels), optionally modulated by a per-point scalar. A
// viewer-side component: batch runs only check its inputs.
#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

namespace {

class PointSplatModel final : public VisualComponent {
 public:
  Field<double> radius{this, "radius", 1.0, "radius of the billboards", "Visualization", "length"};
  Field<int> texture_size{this, "textureSize", 32, "size in texels of the billboard texture", "Visualization"};
  Field<double> alpha{this, "alpha", 1.0, "opacity of the billboards (1: opaque)", "Visualization"};
  Field<std::string> color{this, "color", "1 1 1 1", "billboard colour", "Visualization"};
  Field<std::vector<unsigned>> point_data{this, "pointData", {}, "per-point values (0-255) modulating the colour",
                                          "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the points", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    Component::parse(attrs, diag);
    check_color_field(*this, color, diag);
    if (!(radius.value() > 0.0)) diag.error(where, describe() + ": radius must be positive");
    if (texture_size.value() < 2) diag.error(where, describe() + ": textureSize must be at least 2");
    if (!(alpha.value() >= 0.0 && alpha.value() <= 1.0)) diag.error(where, describe() + ": alpha is not in [0, 1]");
    for (unsigned v : point_data.value())
      if (v > 255) {
        diag.error(where, describe() + ": pointData holds " + std::to_string(v) + ", past 255 (one byte per point)");
        break;
      }
  }
};

}  // namespace

void register_point_splat_model(Registry& r) {
  ComponentInfo info;
  info.name = "PointSplatModel";
  info.category = "Visual";
  info.description = "draws the node's points as soft billboards (viewer only)";
  info.create = creator<PointSplatModel>();
  r.add(std::move(info));
}

}  // namespace sinew
