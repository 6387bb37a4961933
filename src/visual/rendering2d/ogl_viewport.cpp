#include "visual/rendering2d/ogl_viewport.h"

#include <string>

#include "core/registry.h"

namespace sinew {

void OglViewport::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  const VecNi<2>& s = screen_size.value();
  if (s[0] < 0 || s[1] < 0)
    diag.error(where, describe() + ": screenSize must not be negative (" + std::to_string(s[0]) + " " +
                          std::to_string(s[1]) + ")");
  if (!(fovy.value() > 0.0 && fovy.value() < 180.0)) diag.error(where, describe() + ": fovy must be in (0, 180) degrees");
}

void OglViewport::camera(Vec3& position, VecN<4>& orientation) const {
  if (camera_rigid.is_set() || camera_rigid.parent()) {
    const VecN<7>& r = camera_rigid.get();
    position = Vec3(r[0], r[1], r[2]);
    orientation = VecN<4>(r[3], r[4], r[5], r[6]);
  } else {
    position = camera_position.get();
    orientation = camera_orientation.get();
  }
}

void register_ogl_viewport(Registry& r) {
  ComponentInfo info;
  info.name = "OglViewport";
  info.category = "Visual";
  info.description = "the scene drawn again from a fixed camera in a rectangle of the picture";
  info.create = creator<OglViewport>();
  r.add(std::move(info));
}

}  // namespace sinew
