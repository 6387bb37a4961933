#include "visual/drawing/point_splat_model.h"

#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

void PointSplatModel::parse(AttributeMap& attrs, Diagnostics& diag) {
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

void register_point_splat_model(Registry& r) {
  ComponentInfo info;
  info.name = "PointSplatModel";
  info.category = "Visual";
  info.description = "draws the node's points as soft billboards (viewer only)";
  info.create = creator<PointSplatModel>();
  r.add(std::move(info));
}

}  // namespace sinew
