#include "visual/camera.h"

#include <Eigen/Geometry>

#include "core/registry.h"
#include "visual/recorded_camera.h"

namespace sinew {

VecN<4> quat_from_frame(const Vec3& x, const Vec3& y, const Vec3& z) {
  Mat3 m;
  m.col(0) = x, m.col(1) = y, m.col(2) = z;
  Eigen::Quaterniond q(m);
  q.normalize();
  return VecN<4>(q.x(), q.y(), q.z(), q.w());
}

Mat3 quat_matrix(const VecN<4>& q) {
  Eigen::Quaterniond e(q[3], q[0], q[1], q[2]);
  if (e.norm() == 0) return Mat3::Identity();
  return e.normalized().toRotationMatrix();
}

bool BaseCamera::orthographic() const {
  const std::string& t = projection_type.get();
  return t == "1" || t == "Orthographic";
}

// SOFA's BaseCamera::init: the missing one of position / orientation / lookAt is derived from
// the other two; with fewer, the viewer's default view is used.
void BaseCamera::init() {
  default_view_ = false;
  if (position.is_set()) {
    if (!orientation.is_set()) {
      const Vec3 p = position.get(), target = look_at.get();
      distance.set((target - p).norm());
      // getOrientationFromLookAt: z away from the target, y from the current orientation's up.
      const Mat3 r = quat_matrix(orientation.get());
      Vec3 z = p - target;
      if (z.norm() > 0) z.normalize();
      Vec3 x = r.col(1).cross(z);
      if (x.squaredNorm() < 1e-5) x = r.col(0);
      x.normalize();
      const Vec3 y = z.cross(x);
      orientation.set(quat_from_frame(x, y, z));
    } else if (!look_at.is_set()) {
      if (!distance.is_set()) msg_warning("Missing distance parameter ; taking default value (0.0, 0.0, 0.0)");
      look_at.set(position.get() + quat_matrix(orientation.get()) * Vec3(0, 0, -distance.get()));
    } else {
      msg_warning("Too many missing parameters ; taking default ...");
      default_view_ = true;
    }
  } else if (look_at.is_set() && orientation.is_set()) {
    if (!distance.is_set()) msg_warning("Missing distance parameter ; taking default value (0.0, 0.0, 0.0)");
    // SOFA's getPositionFromOrientation returns R·(0,0,−d) − lookAt (sic); kept so that the
    // same scene shows the same view.
    position.set(quat_matrix(orientation.get()) * Vec3(0, 0, -distance.get()) - look_at.get());
  } else {
    msg_warning("Too many missing parameters ; taking default ...");
    default_view_ = true;
  }
}

void register_cameras(Registry& r) {
  const struct {
    const char* name;
    const char* what;
    std::function<std::unique_ptr<Component>(const std::string&)> create;
  } list[] = {
      {"InteractiveCamera", "viewer camera driven by the mouse; its view is used by `sinew render`",
       creator<InteractiveCamera>()},
      {"Camera", "a camera rendering the scene from a given position and orientation", creator<BaseCamera>()},
      {"RecordedCamera", "camera moved along a scripted path (rotation, translation, navigation)",
       creator<RecordedCamera>()},
  };
  for (const auto& e : list) {
    ComponentInfo info;
    info.name = e.name;
    info.category = "Visual";
    info.description = e.what;
    info.create = e.create;
    r.add(std::move(info));
  }
}

}  // namespace sinew
