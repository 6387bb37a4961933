#include "viewer/camera_control.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace sinew::viewer {

namespace {

// Shoemake/Bell trackball: a pixel on a unit sphere blended into a hyperbolic sheet,
// in camera coordinates (x right, y up, z towards the viewer).
Vec3 on_trackball(double x, double y, int width, int height) {
  const double s = std::min(width, height) * 0.5;
  const double px = (x - width * 0.5) / s, py = (height * 0.5 - y) / s;
  const double r2 = px * px + py * py;
  const double z = r2 <= 0.5 ? std::sqrt(1.0 - r2) : 0.5 / std::sqrt(r2);
  return Vec3(px, py, z).normalized();
}

}  // namespace

void CameraControl::reset(const render::CameraFrame& frame, const Vec3& pivot) {
  frame_ = frame;
  pivot_ = pivot;
}

void CameraControl::rotate(double x0, double y0, double x1, double y1, int width, int height) {
  if (width <= 0 || height <= 0) return;
  const Vec3 a = on_trackball(x0, y0, width, height), b = on_trackball(x1, y1, width, height);
  const Vec3 axis = a.cross(b);
  const double n = axis.norm();
  if (n < 1e-12) return;
  const double angle = std::atan2(n, a.dot(b)) * 2.0;  // the scene follows the cursor: twice the arc
  // The scene turns by `angle` about `axis` (camera coordinates): the camera turns the
  // other way around the pivot.
  const Mat3 turn_cam = Eigen::AngleAxisd(-angle, axis / n).toRotationMatrix();
  const Mat3& R = frame_.rotation;
  const Mat3 turn_world = R * turn_cam * R.transpose();
  frame_.position = pivot_ + turn_world * (frame_.position - pivot_);
  frame_.look_at = pivot_ + turn_world * (frame_.look_at - pivot_);
  Mat3 r = turn_world * R;
  // Keep the frame orthonormal after many small turns.
  const Eigen::Quaterniond q(r);
  frame_.rotation = q.normalized().toRotationMatrix();
}

void CameraControl::pan(double dx, double dy, int width, int height) {
  if (height <= 0) return;
  const Mat3& R = frame_.rotation;
  const double depth = std::max(std::abs(R.col(2).dot(frame_.position - pivot_)), 1e-9);
  const double per_pixel = 2.0 * depth * std::tan(frame_.fov_deg * M_PI / 360.0) / height;
  const Vec3 shift = (-dx * R.col(0) + dy * R.col(1)) * per_pixel;
  frame_.position += shift;
  frame_.look_at += shift;
}

void CameraControl::zoom(double steps) {
  const double f = std::pow(0.9, steps);
  const Vec3 target = frame_.look_at;
  Vec3 offset = frame_.position - target;
  // Looking at the camera's own position (a scene camera without lookAt): zoom along the view.
  if (offset.norm() < 1e-12) offset = frame_.rotation.col(2) * std::max((frame_.position - pivot_).norm(), 1.0);
  frame_.position = target + offset * f;
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
