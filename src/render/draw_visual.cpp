// VisualBoundingBox as SOFA draws it: the twelve edges of the box, in its
// colour, unlit. Core-profile OpenGL has no wide lines everywhere, so
// `thickness` is not honoured (lines are one pixel wide).
#include "render/draw_visual.h"

#include "core/node.h"
#include "render/draw_collision.h"
#include "visual/color.h"
#include "visual/visual_bounding_box.h"

namespace sinew::render {

namespace {

void add_box(DrawList& list, const VisualBoundingBox& vb) {
  if (!vb.enable.get() || vb.state() != ComponentState::valid) return;
  const auto box = vb.box();
  if (!box) return;
  Batch& b = fresh_batch(list, &vb, Batch::Kind::lines);
  // The colour text is parsed again only when it changed (parsing allocates).
  if (b.material_version != vb.color.version()) {
    const Rgba c = parse_rgba(vb.color.get()).value_or(Rgba{1, 1, 0, 1});
    b.shading.diffuse = c;
    b.material_version = vb.color.version();
  }
  const Vec3& lo = box->first;
  const Vec3& hi = box->second;
  auto corner = [&](int i) {
    return Vec3(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
  };
  // Edges join corners differing in one coordinate bit.
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit))
        for (const Vec3& p : {corner(i), corner(i | bit)})
          for (int c = 0; c < 3; ++c) b.positions.push_back(static_cast<float>(p[c]));
  close_batch(list, b);
}

}  // namespace

void add_visual_extras(DrawList& list, Node& node) {
  for (const auto& o : node.objects())
    if (const auto* vb = dynamic_cast<const VisualBoundingBox*>(o.get())) add_box(list, *vb);
}

}  // namespace sinew::render
