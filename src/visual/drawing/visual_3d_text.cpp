#include "visual/drawing/visual_3d_text.h"

#include "core/registry.h"
#include "visual/color.h"

namespace sinew {

void Visual3DText::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, color, diag);
}

void register_visual_3d_text(Registry& r) {
  ComponentInfo info;
  info.name = "Visual3DText";
  info.category = "Visual";
  info.description = "a camera-facing text at a 3D position";
  info.create = creator<Visual3DText>();
  r.add(std::move(info));
}

}  // namespace sinew
