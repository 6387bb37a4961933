#include "visual/drawing/visual_grid.h"

#include "core/registry.h"
#include "visual/choice.h"
#include "visual/color.h"

namespace sinew {

void VisualGrid::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_choice(*this, plane, {"x", "y", "z"}, diag);
  check_color_field(*this, color, diag);
  if (nb_subdiv.value() < 1) diag.error(where, describe() + ": nbSubdiv must be at least 1");
  if (nb_line_segments.value() < 1) diag.error(where, describe() + ": nbLineSegments must be at least 1");
  if (!(size.value() >= 0)) diag.error(where, describe() + ": size must not be negative");
}

void VisualGrid::lines(std::vector<Vec3>& out) const {
  out.clear();
  const int nb = nb_subdiv.get(), nl = nb_line_segments.get();
  if (nb < 1 || nl < 1) return;
  // SOFA computes in float.
  const float s = static_cast<float>(size.get()), hs = s / 2, step = s / static_cast<float>(nb),
              ls = s / static_cast<float>(nl);
  // Axes (a, b) of the plane, in SOFA's order: plane x draws lines along z then along y, ...
  int a = 0, b = 1;  // plane z: lines along x at each y, then along y at each x
  const std::string& p = plane.get();
  if (p == "x") a = 2, b = 1;
  if (p == "y") a = 0, b = 2;
  auto point = [&](float u, float v, int au, int av) {
    Vec3 q = Vec3::Zero();
    q[au] = u, q[av] = v;
    return q;
  };
  // First family: lines along axis `a` at each subdivision of `b`.
  for (int i = 0; i <= nb; ++i)
    for (int j = 0; j < nl; ++j) {
      out.push_back(point(-hs + j * ls, -hs + i * step, a, b));
      out.push_back(point(-hs + (j + 1) * ls, -hs + i * step, a, b));
    }
  // Second family: lines along `b` at each subdivision of `a`.
  for (int i = 0; i <= nb; ++i)
    for (int j = 0; j < nl; ++j) {
      out.push_back(point(-hs + i * step, -hs + j * ls, a, b));
      out.push_back(point(-hs + i * step, -hs + (j + 1) * ls, a, b));
    }
}

void register_visual_grid(Registry& r) {
  ComponentInfo info;
  info.name = "VisualGrid";
  info.category = "Visual";
  info.description = "a square grid of lines in a coordinate plane (viewer only)";
  info.create = creator<VisualGrid>();
  r.add(std::move(info));
}

}  // namespace sinew
