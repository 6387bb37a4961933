#include "visual/drawing/cylinder_visual_model.h"

#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

void CylinderVisualModel::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, color, diag);
  if (!(radius.value() > 0.0)) diag.error(where, describe() + ": radius must be positive");
}

void CylinderVisualModel::init() {
  const std::size_t n = position.get().size();
  for (const Edge& e : edges.get())
    if (e[0] >= n || e[1] >= n) {
      msg_error("edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ") refers past the " +
                std::to_string(n) + " positions");
      set_state(ComponentState::invalid);
      return;
    }
}

void register_cylinder_visual_model(Registry& r) {
  ComponentInfo info;
  info.name = "CylinderVisualModel";
  info.category = "Visual";
  info.description = "draws a cylinder along each edge (viewer only)";
  info.create = creator<CylinderVisualModel>();
  r.add(std::move(info));
}

}  // namespace sinew
