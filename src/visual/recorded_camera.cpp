#include "visual/recorded_camera.h"

#include <cmath>

#include <Eigen/Geometry>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

// SOFA's Quat(axis, angle).rotate(v): a zero axis leaves v as it is.
Vec3 rotate(const Vec3& axis, double angle, const Vec3& v) {
  if (axis.norm() == 0) return v;
  return Eigen::AngleAxisd(angle, axis.normalized()) * v;
}

// Orientation of a camera at `pos` looking at `target` with `tangent` along its x (SOFA's
// frame: z away from the target, y = z × tangent, x = y × z).
VecN<4> orientation_towards(const Vec3& pos, const Vec3& target, const Vec3& tangent) {
  const Vec3 z = -(target - pos);
  const Vec3 y = z.cross(tangent);
  const Vec3 x = y.cross(z);
  VecN<4> q = quat_from_frame(x.normalized(), y.normalized(), z.normalized());
  return q / q.norm();
}

Eigen::Quaterniond quat(const VecN<4>& q) { return Eigen::Quaterniond(q[3], q[0], q[1], q[2]); }

}  // namespace

void RecordedCamera::init() {
  BaseCamera::init();
  next_step_ = start_time.get();
  first_rotation_ = first_translation_ = first_navigation_ = true;
}

void RecordedCamera::reset() {
  next_step_ = start_time.get();
  if (rotation_mode.get()) configure_rotation();
  if (translation_mode.get()) configure_translation();
  if (navigation_mode.get()) configure_navigation();
}

double RecordedCamera::span() const {
  const double s = end_time.get() - start_time.get();
  return s == 0.0 ? 200.0 : s;
}

void RecordedCamera::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  const Node* n = node();
  if (!n) return;
  const double t = n->time.get(), dt = n->dt.get();
  if (t < next_step_) return;
  next_step_ += dt;
  if (first_rotation_ && rotation_mode.get()) configure_rotation();
  if (rotation_mode.get()) move_rotation(t);
  if (first_translation_ && translation_mode.get()) configure_translation();
  if (translation_mode.get()) move_translation(t);
  if (first_navigation_ && navigation_mode.get()) configure_navigation();
  if (navigation_mode.get()) move_navigation(t);
}

void RecordedCamera::configure_rotation() {
  const Vec3 p = rotation_start_point.get();
  position.set(p);
  look_at.set(rotation_look_at.get());
  distance.set((look_at.get() - p).norm());
  const Vec3 tangent = camera_up.is_set() && camera_up.get().norm() > 1e-6
                           ? Vec3(-(p - look_at.get()).cross(camera_up.get()))
                           : Vec3(-(p - rotation_center.get()).cross(rotation_axis.get()));
  orientation.set(orientation_towards(p, look_at.get(), tangent));
  first_rotation_ = false;
}

void RecordedCamera::move_rotation(double time) {
  const double angle = 2 * M_PI * (time - start_time.get()) / span();
  const Vec3 c = rotation_center.get();
  const Vec3 p = c + rotate(rotation_axis.get(), angle, rotation_start_point.get() - c);
  position.set(p);
  const Vec3 tangent = camera_up.is_set() && camera_up.get().norm() > 1e-6
                           ? Vec3(-(p - look_at.get()).cross(camera_up.get()))
                           : Vec3(-(p - c).cross(rotation_axis.get()));
  orientation.set(orientation_towards(p, look_at.get(), tangent));
}

void RecordedCamera::initialize_view_up() {
  const auto& pts = camera_positions.get();
  if (!camera_positions.is_set() || pts.size() < 2) return;
  const Vec3 z = (pts[1] - pts[0]).normalized();
  // The axis "most perpendicular" to the first segment (the last of equals wins, as SOFA).
  Vec3 up(1, 0, 0);
  double best = z.cross(up).norm();
  for (int i = 1; i < 3; ++i) {
    const Vec3 ref = Vec3::Unit(i);
    if (z.cross(ref).norm() >= best) best = z.cross(ref).norm(), up = ref;
  }
  camera_up.set(up);
}

void RecordedCamera::configure_translation() {
  const auto& pts = camera_positions.get();
  if (!camera_positions.is_set() || pts.size() < 2) return;
  position.set(pts[0]);
  look_at.set(pts[1]);
  initialize_view_up();
  const Vec3 z = pts[0] - pts[1], y = camera_up.get(), x = y.cross(z);
  VecN<4> q = quat_from_frame(x.normalized(), y.normalized(), z.normalized());
  orientation.set(q / q.norm());
  first_translation_ = false;
}

void RecordedCamera::move_translation(double time) {
  const std::vector<Vec3> pts = camera_positions.get();
  if (!camera_positions.is_set() || pts.empty()) return;
  const std::size_t n = pts.size();
  const double total = span();
  const double per = n > 1 ? total / static_cast<double>(n - 1) : total;
  const double local = std::fmod(time - start_time.get(), total);
  const double index = std::floor(local / per);
  if (!(index >= 0)) return;
  const auto k = static_cast<std::size_t>(index);
  const double ratio = std::fmod(local, per) / per;
  if (camera_up.get().norm() < 1e-6) initialize_view_up();
  if (k + 1 < n) {
    look_at.set(pts[k + 1]);
    const Vec3 p0 = pts[k];
    position.set(p0 + (pts[k + 1] - p0) * ratio);
    const Vec3 z = -(pts[k + 1] - p0);
    const Vec3 x = camera_up.get().cross(z), y = z.cross(x);
    camera_up.set(y.normalized());
    VecN<4> q = quat_from_frame(x.normalized(), y.normalized(), z.normalized());
    orientation.set(q / q.norm());
  } else if (k + 1 == n) {
    position.set(pts[k]);
    look_at.set(pts[k]);
  }
}

void RecordedCamera::configure_navigation() {
  const auto& pts = camera_positions.get();
  const auto& qs = camera_orientations.get();
  if (pts.size() < 2 || qs.size() != pts.size()) return;
  position.set(pts[0]);
  orientation.set(qs[0]);
  first_navigation_ = false;
}

void RecordedCamera::move_navigation(double time) {
  const std::vector<Vec3> pts = camera_positions.get();
  const std::vector<VecN<4>> qs = camera_orientations.get();
  if (pts.size() < 2 || qs.size() != pts.size()) return;
  const std::size_t n = pts.size();
  const double total = span(), per = total / static_cast<double>(n - 1);
  const double local = std::fmod(time - start_time.get(), total);
  const double index = std::floor(local / per);
  if (!(index >= 0)) return;
  const auto k = static_cast<std::size_t>(index);
  const double ratio = std::fmod(local, per) / per;
  if (k + 1 < n) {
    position.set(pts[k] + (pts[k + 1] - pts[k]) * ratio);
    const Eigen::Quaterniond q = quat(qs[k]).slerp(ratio, quat(qs[k + 1]));
    orientation.set(VecN<4>(q.x(), q.y(), q.z(), q.w()));
    // SOFA's getLookAtFromOrientation from the segment's start.
    look_at.set(pts[k] + quat_matrix(orientation.get()) * Vec3(0, 0, -distance.get()));
  } else if (k + 1 == n) {
    position.set(pts[k]);
    orientation.set(qs[k]);
  }
}

std::vector<Vec3> RecordedCamera::rotation_path() const {
  std::vector<Vec3> out(100);
  const Vec3 c = rotation_center.get();
  for (int i = 0; i < 100; ++i) out[i] = c + rotate(rotation_axis.get(), 2 * M_PI / 100 * i, rotation_start_point.get() - c);
  return out;
}

}  // namespace sinew
