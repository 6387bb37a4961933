// VisualBoundingBox (SOFA's Sofa.Component.Visual): draws the twelve edges of
// an axis-aligned box, usually linked to a model's box (bbox="@model.bbox").
#include "visual/drawing/visual_bounding_box.h"

#include "core/registry.h"
#include "visual/color.h"

namespace sinew {

void VisualBoundingBox::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, color, diag);
  if (!(thickness.value() > 0.0)) diag.error(where, describe() + ": thickness must be positive");
  const std::size_t n = bbox.value().size();
  if (bbox.link_path().empty() && n != 0 && n != 6)
    diag.error(where, describe() + ": bbox needs 6 numbers (min x y z, max x y z), not " + std::to_string(n));
}

std::optional<std::pair<Vec3, Vec3>> VisualBoundingBox::box() const {
  const std::vector<double>& b = bbox.get();
  if (b.size() != 6) return std::nullopt;
  const Vec3 lo(b[0], b[1], b[2]), hi(b[3], b[4], b[5]);
  // SOFA's BoundingBox starts inverted (min > max) until something is added: nothing to draw.
  if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) return std::nullopt;
  return std::make_pair(lo, hi);
}

void register_visual_bounding_box(Registry& r) {
  ComponentInfo info;
  info.name = "VisualBoundingBox";
  info.category = "Visual";
  info.description = "draws an axis-aligned bounding box (drawn pictures only)";
  info.create = creator<VisualBoundingBox>();
  r.add(std::move(info));
}

}  // namespace sinew
