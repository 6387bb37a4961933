#include "viewer/camera_control.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/node.h"
#include "visual/camera.h"
#include "visual/recorded_camera.h"

namespace sinew::viewer {

namespace {

// SOFA's Trackball::ComputeQuaternion from the viewport's centre to (x, y) (viewport units,
// y up): the two points on a sphere of radius 0.8 blended into a hyperbolic sheet, the
// rotation about their cross product by twice the arcsine of half their distance over the
// radius. False for no rotation.
bool trackball(double x, double y, Vec3& axis, double& angle) {
  if (x == 0 && y == 0) return false;
  constexpr double r = 0.8;
  auto z_of = [](double px, double py) {
    const double d = std::sqrt(px * px + py * py);
    if (d < r * 0.70710678118654752440) return std::sqrt(r * r - d * d);
    const double t = r / 1.41421356237309504880;
    return t * t / d;
  };
  const Vec3 p1(0, 0, z_of(0, 0)), p2(x, y, z_of(x, y));
  const Vec3 a = p2.cross(p1);
  const double t = std::clamp((p1 - p2).norm() / (2.0 * r), -1.0, 1.0);
  if (a.norm() < std::numeric_limits<double>::epsilon()) return false;  // Quat::axisToQuat's identity
  axis = a.normalized();
  angle = 2.0 * std::asin(t);
  return true;
}

// SOFA's trackball coordinates of the cursor at (x, y) after a press at (x0, y0) in a w × h
// viewport, in floats and in InteractiveCamera's order of operations: x right, y up, ±1
// across the viewport.
void drag_units(int x, int y, int x0, int y0, int w, int h, double& u, double& v) {
  const float fw = static_cast<float>(w), fh = static_cast<float>(h);
  u = (2.0f * (static_cast<float>(x) + (static_cast<float>(-x0) + fw / 2.0f)) - fw) / fw;
  v = (fh - 2.0f * (static_cast<float>(y) + (static_cast<float>(-y0) + fh / 2.0f))) / fh;
}

}  // namespace

Navigation navigation_of(const Node& root) {
  Navigation n;
  const BaseCamera* cam = render::find_camera(root);
  if (!cam) return n;
  n.fixed_look_at = cam->fixed_look_at.get();
  if (const auto* i = dynamic_cast<const InteractiveCamera*>(cam)) {
    n.zoom_speed = i->zoom_speed.get(), n.pan_speed = i->pan_speed.get(), n.pivot = i->pivot.get();
  } else if (const auto* r = dynamic_cast<const RecordedCamera*>(cam)) {
    n.law = Navigation::Law::recorded;
    n.zoom_speed = r->zoom_speed.get(), n.pan_speed = r->pan_speed.get(), n.pivot = r->pivot.get();
  } else {
    n.law = Navigation::Law::none;  // SOFA's Camera::manageEvent does nothing
  }
  return n;
}

void CameraControl::reset(const render::CameraFrame& frame, const Navigation& navigation) {
  frame_ = frame;
  nav_ = navigation;
  mode_ = Mode::none;
}

void CameraControl::set_scene_box(const Vec3& min, const Vec3& max) {
  centre_ = (min + max) * 0.5;
  radius_ = 0.5 * (max - min).norm();
}

Vec3 CameraControl::pivot_of(const render::CameraFrame& f) const {
  if (nav_.law == Navigation::Law::recorded) return nav_.pivot == 1 ? Vec3::Zero() : centre_;
  switch (nav_.pivot) {
    case 0: return f.look_at;
    case 1: return f.position;
    case 3: return Vec3::Zero();
    default: return centre_;
  }
}

void CameraControl::press(Mode mode, double x, double y) {
  if (nav_.law == Navigation::Law::none) return;
  mode_ = mode;
  last_x_ = static_cast<int>(x), last_y_ = static_cast<int>(y);
  start_ = frame_;
}

void CameraControl::translate(const Vec3& t, bool look_at_too) {
  frame_.position += t;
  if (look_at_too) frame_.look_at += t;
}

// InteractiveCamera's zoom: `distance` along the camera's z (negative: forwards); the point
// looked at is pushed ahead by `step` when the camera passed it.
void CameraControl::zoom_by(double distance, double step) {
  const Mat3& R = frame_.rotation;
  translate(R * Vec3(0, 0, distance), false);
  const Vec3 ahead = R * Vec3(0, 0, -step) + frame_.position;
  if ((frame_.look_at - frame_.position).dot(ahead - frame_.position) < 0 && !nav_.fixed_look_at)
    frame_.look_at = ahead;
}

void CameraControl::move(double xd, double yd, int width, int height) {
  if (mode_ == Mode::none || width <= 0 || height <= 0) return;
  const int x = static_cast<int>(xd), y = static_cast<int>(yd);
  const bool recorded = nav_.law == Navigation::Law::recorded;
  const Mat3& R = frame_.rotation;
  switch (mode_) {
    case Mode::trackball: {
      // InteractiveCamera turns the frame of the press by the whole drag; RecordedCamera the
      // current frame by the last motion.
      const render::CameraFrame& from = recorded ? frame_ : start_;
      double u, v, angle;
      Vec3 axis;
      drag_units(x, y, last_x_, last_y_, width, height, u, v);
      if (!trackball(u, v, axis, angle)) {
        if (!recorded) frame_ = start_;
        break;
      }
      // BaseCamera::rotateWorldAroundPoint: the world turns by −angle about the axis (in the
      // camera's frame) around the pivot, so the camera turns by angle around it.
      const Vec3 p = pivot_of(from);
      const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, from.rotation * axis));
      const double distance = (from.look_at - from.position).norm();
      const Eigen::Quaterniond q = (turn * Eigen::Quaterniond(from.rotation)).normalized();
      const Vec3 position = p + turn * (from.position - p);
      frame_.rotation = q.toRotationMatrix();
      frame_.position = position;
      if (!nav_.fixed_look_at) frame_.look_at = position + frame_.rotation * Vec3(0, 0, -distance);
      break;
    }
    case Mode::pan: {
      const Vec3 t = R * Vec3(last_x_ - x, y - last_y_, 0.0) * nav_.pan_speed * (recorded ? 1.0 : 0.01 * radius_);
      translate(t, recorded || !nav_.fixed_look_at);
      break;
    }
    case Mode::zoom:
      if (recorded) {
        translate(R * Vec3(0, 0, -nav_.zoom_speed * (y - last_y_) / height), true);
      } else {
        const double step = nav_.zoom_speed * (0.01 * radius_) / height;
        zoom_by(step * -(y - last_y_), step);
      }
      break;
    case Mode::none: break;
  }
  if (mode_ != Mode::trackball || recorded) last_x_ = x, last_y_ = y;
}

void CameraControl::wheel(double offset, int height) {
  if (nav_.law == Navigation::Law::none || height <= 0) return;
  const int delta = static_cast<int>(offset * 10.0);  // SofaGLFWWindow::scrollEvent
  if (nav_.law == Navigation::Law::recorded) {
    translate(frame_.rotation * Vec3(0, 0, -nav_.zoom_speed * (delta * 0.5) / height), true);
    return;
  }
  const double step = nav_.zoom_speed * (0.01 * radius_) / height;
  zoom_by(step * -(delta * 0.5), step);
}

Ray ray_through(const render::View& view, double x, double y, int width, int height) {
  const Eigen::Matrix4d inv = (view.projection.cast<double>() * view.view.cast<double>()).inverse();
  const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height;
  Eigen::Vector4d a = inv * Eigen::Vector4d(nx, ny, -1.0, 1.0);
  Eigen::Vector4d b = inv * Eigen::Vector4d(nx, ny, 1.0, 1.0);
  Ray r;
  r.origin = a.head<3>() / a[3];
  r.dir = (b.head<3>() / b[3] - r.origin).normalized();
  return r;
}

bool project(const render::View& view, const Vec3& p, int width, int height, double& x, double& y) {
  const Eigen::Vector4d c =
      view.projection.cast<double>() * view.view.cast<double>() * Eigen::Vector4d(p[0], p[1], p[2], 1.0);
  if (c[3] <= 0) return false;
  x = (c[0] / c[3] + 1.0) * 0.5 * width - 0.5;
  y = (1.0 - c[1] / c[3]) * 0.5 * height - 0.5;
  return true;
}

}  // namespace sinew::viewer
