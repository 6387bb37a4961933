#include "render/camera_view.h"

#include <cmath>

#include <Eigen/Geometry>

#include "core/node.h"
#include "visual/camera.h"

namespace sinew::render {

namespace {

// BaseCamera::setDefaultView.
CameraFrame default_frame(const Vec3& gravity, const Vec3& min, const Vec3& max) {
  CameraFrame f;
  const Vec3 centre = (min + max) * 0.5;
  Vec3 x(1, 0, 0);
  Vec3 y = gravity == Vec3::Zero() ? Vec3(0, 1, 0) : Vec3(-gravity);
  y.normalize();
  if (1.0 - std::abs(x.dot(y)) < 0.001) x = Vec3(0, 1, 0);
  Vec3 z = x.cross(y).normalized();
  x = y.cross(z).normalized();
  f.rotation.col(0) = x, f.rotation.col(1) = y, f.rotation.col(2) = z;
  const double dist = (min - centre).norm() * 3.0;
  f.position = centre + z * dist;
  f.look_at = centre;
  return f;
}

}  // namespace

const BaseCamera* find_camera(const Node& node) {
  for (const auto& o : node.objects())
    if (const auto* c = dynamic_cast<const BaseCamera*>(o.get()))
      if (c->activated.get() && c->state() == ComponentState::valid) return c;
  for (const Node* child : node.children())
    if (const BaseCamera* c = find_camera(*child)) return c;
  return nullptr;
}

CameraFrame camera_frame(const Node& root, const Vec3& min, const Vec3& max, bool* from_scene) {
  const BaseCamera* cam = find_camera(root);
  CameraFrame f;
  const bool scene = cam && !cam->wants_default_view();
  if (scene) {
    f.position = cam->position.get();
    f.rotation = quat_matrix(cam->orientation.get());
    f.fov_deg = cam->field_of_view.get();
    f.ortho = cam->orthographic();
    f.look_at = cam->look_at.get();
  } else {
    f = default_frame(root.gravity.get(), min, max);
    if (cam) {
      f.fov_deg = cam->field_of_view.get();
      f.ortho = cam->orthographic();
    }
  }
  if (from_scene) *from_scene = scene;
  return f;
}

View viewport_view(const ExtraViewport& vp, const Vec3& min, const Vec3& max, double aspect) {
  const Mat3 r = quat_matrix(vp.orientation);
  View v;
  v.view.setIdentity();
  v.view.topLeftCorner<3, 3>() = r.cast<float>();
  v.view.topRightCorner<3, 1>() = (-(r * vp.position)).cast<float>();
  v.eye = vp.position;
  v.from_scene_camera = true;
  double z_near = vp.z_near, z_far = vp.z_far;
  if (std::abs(z_near) < 1e-4 || std::abs(z_far) < 1e-4) {
    z_near = 1e10, z_far = -1e10;
    for (int c = 0; c < 8; ++c) {
      const Vec3 p(c & 1 ? min.x() : max.x(), c & 2 ? min.y() : max.y(), c & 4 ? min.z() : max.z());
      const double z = -(r * p - vp.position).z();
      z_near = std::min(z_near, z), z_far = std::max(z_far, z);
    }
    if (z_near <= 0) z_near = 1;
    if (z_far >= 1000.0) z_far = 1000.0;
    if (z_near > 0 && z_far < 1000) {
      z_near *= 0.8, z_far *= 1.2;
      if (z_near < z_far * 0.01) z_near = z_far * 0.01;
      if (z_near < 0.1) z_near = 0.1;
      if (z_far < 2.0) z_far = 2.0;
    }
  }
  const double s = 1.0 / std::tan(vp.fovy * M_PI / 180 * 0.5);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = s / (aspect > 0 ? aspect : 1.0);
  p(1, 1) = s;
  p(2, 2) = -(z_far + z_near) / (z_far - z_near);
  p(2, 3) = -2.0 * z_far * z_near / (z_far - z_near);
  p(3, 2) = -1.0;
  v.projection = p.cast<float>();
  return v;
}

View view_for(const Node& root, const Vec3& min, const Vec3& max, int width, int height) {
  bool scene = false;
  const CameraFrame f = camera_frame(root, min, max, &scene);
  View v = view_of(f, root, min, max, width, height);
  v.from_scene_camera = scene;
  return v;
}

View view_of(const CameraFrame& f, const Node& root, const Vec3& min, const Vec3& max, int width, int height) {
  View v;
  const BaseCamera* cam = find_camera(root);
  v.eye = f.position;

  // World → eye: the inverse of the camera's rigid frame.
  const Mat3 rt = f.rotation.transpose();
  const Vec3 t = -(rt * f.position);
  v.view.setIdentity();
  v.view.topLeftCorner<3, 3>() = rt.cast<float>();
  v.view.topRightCorner<3, 1>() = t.cast<float>();

  // Clip planes: BaseCamera::computeZ from the bounding box, or the camera's own.
  double z_near, z_far;
  const Vec3 centre = (min + max) * 0.5;
  const double radius = std::max((max - min).norm() * 0.5, 1e-9);
  if (!cam || cam->compute_z_clip.get()) {
    const double to_centre = (f.position - centre).norm();
    z_near = to_centre - radius;
    z_far = (z_near + 2 * radius) * 1.1;
    z_near *= 0.01;
    const double z_min = 0.01 * 5 * radius;
    if (z_near < z_min) z_near = z_min;
    if (z_far <= z_near) z_far = z_near + 2 * radius;
  } else {
    z_near = cam->z_near.get();
    z_far = cam->z_far.get();
    if (!(z_near > 0 && z_far > z_near)) z_near = 0.01, z_far = 100;  // SOFA refuses them with an error
  }

  const double aspect = height > 0 ? double(width) / height : 1.0;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  if (!f.ortho) {
    const double s = 1.0 / std::tan(f.fov_deg * M_PI / 180 * 0.5);
    p(0, 0) = s / aspect;
    p(1, 1) = s;
    p(2, 2) = -(z_far + z_near) / (z_far - z_near);
    p(2, 3) = -2.0 * z_far * z_near / (z_far - z_near);
    p(3, 2) = -1.0;
  } else {
    // BaseCamera::getProjectionMatrix (orthographic): the half height seen at lookAt's depth.
    const double xf = aspect >= 1 ? aspect : 1.0, yf = aspect >= 1 ? 1.0 : 1.0 / aspect;
    const double depth = std::abs((rt * (f.look_at - f.position))[2]);
    const double half = std::tan(M_PI / 180.0 * f.fov_deg / 2.0) * depth;
    p(0, 0) = 1.0 / (half * xf);
    p(1, 1) = 1.0 / (half * yf);
    p(2, 2) = -2.0 / (z_far - z_near);
    p(2, 3) = -(z_far + z_near) / (z_far - z_near);
    p(3, 3) = 1.0;
  }
  v.projection = p.cast<float>();
  return v;
}

}  // namespace sinew::render
