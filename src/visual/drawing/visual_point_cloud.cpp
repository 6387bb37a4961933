#include "visual/drawing/visual_point_cloud.h"

#include <memory>
#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "core/value_text.h"
#include "visual/color.h"

namespace sinew {

namespace {

int coord_width(const std::string& tmpl) {
  if (tmpl == "Vec1d") return 1;
  if (tmpl == "Vec2d") return 2;
  if (tmpl == "Rigid2d") return 3;
  if (tmpl == "Rigid3d") return 7;
  return 3;
}

FlatVec empty_of(int width) {
  FlatVec v;
  v.width = width;
  return v;
}

}  // namespace

VisualPointCloud::VisualPointCloud(const std::string& tmpl)
    : position(this, "position", empty_of(coord_width(tmpl)), "positions to draw", "Vector", "length"),
      rigid_(tmpl.rfind("Rigid", 0) == 0) {}

void VisualPointCloud::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, color, diag);
  check_color_field(*this, indices_color, diag);
  const std::string& m = draw_mode.value();
  if (m != "Point" && m != "Sphere" && !(rigid_ && m == "Frame"))
    diag.error(where, describe() + ": drawMode " + quote_value(m) + " is not " +
                          (rigid_ ? "Point, Sphere or Frame" : "Point or Sphere"));
  for (double r : sphere_radius.value())
    if (!(r >= 0.0)) diag.error(where, describe() + ": sphereRadius holds a negative radius");
}

void VisualPointCloud::init() {
  // SOFA pads the radii with the last one given (1 when none) and ignores extra ones.
  const std::size_t radii = sphere_radius.get().size(), n = position.get().size();
  if (draw_mode.value() == "Sphere" && radii > 1 && radii != n)
    msg_warning("sphereRadius has " + std::to_string(radii) + " radii for " + std::to_string(n) + " points: " +
                (radii < n ? "the points past them take the last one" : "the extra radii are not used"));
}

Vec3 VisualPointCloud::centre(std::size_t i) const {
  const FlatVec& x = position.get();
  const int w = x.width;
  const double* p = &x.data[i * static_cast<std::size_t>(w)];
  return Vec3(p[0], w >= 2 ? p[1] : 0.0, (w == 3 && !rigid_) || w == 7 ? p[2] : 0.0);
}

void register_visual_point_cloud(Registry& r) {
  ComponentInfo info;
  info.name = "VisualPointCloud";
  info.category = "Visual";
  info.description = "draws positions as points, spheres or frames (viewer only)";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    return std::make_unique<VisualPointCloud>(t);
  };
  r.add(std::move(info));
}

}  // namespace sinew
