// ClipPlane (SOFA's Sofa.GL.Component.Rendering3D): removes, from the models
// of its node and below, the half-space its normal points to. Sinew's
// renderer honours it with gl_ClipDistance (docs/render.md); batch runs are
// unaffected.
#include "visual/clip_plane.h"

#include "core/registry.h"

namespace sinew {

void ClipPlane::init() {
  // SOFA disables a plane with a negative OpenGL id.
  if (id.value() < 0) {
    msg_error("plane id cannot be negative (" + std::to_string(id.value()) + "): the component is disabled");
    set_state(ComponentState::invalid);
    return;
  }
  if (id.value() > 7) {
    msg_error("plane id " + std::to_string(id.value()) +
              " is beyond OpenGL's eight clip planes (0 to 7): the component is disabled");
    set_state(ComponentState::invalid);
    return;
  }
  if (normal.value().norm() == 0.0) {
    msg_error("normal is zero: the component is disabled");
    set_state(ComponentState::invalid);
  }
}

bool ClipPlane::clips(const Vec3& p) const {
  return active.value() && state() == ComponentState::valid && (p - position.value()).dot(normal.value()) > 0.0;
}

void register_clip_plane(Registry& r) {
  ComponentInfo info;
  info.name = "ClipPlane";
  info.category = "Visual";
  info.description = "clipping plane of the models of its node (drawn pictures only)";
  info.create = creator<ClipPlane>();
  r.add(std::move(info));
}

}  // namespace sinew
