#include "visual/drawing/ogl_scene_frame.h"

#include "visual/choice.h"

namespace sinew {

void OglSceneFrame::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_choice(*this, style, {"Arrows", "Cylinders", "CubeCones"}, diag);
  check_choice(*this, alignment, {"BottomLeft", "BottomRight", "TopRight", "TopLeft"}, diag);
  if (viewport_size.value() < 1) diag.error(where, describe() + ": viewportSize must be at least 1");
}

}  // namespace sinew
