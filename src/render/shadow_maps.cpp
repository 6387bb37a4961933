#include "render/shadow_maps.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace sinew::render {

namespace {

// Rotation rows of a frame whose z axis is `z` (the light looks along −z).
Eigen::Matrix3d frame_rows(Vec3 z) {
  z.normalize();
  Vec3 y(0, 1, 0);
  if (std::abs(z.x()) < 1e-7 && std::abs(z.z()) < 1e-7) y = z.y() > 0 ? Vec3(0, 0, -1) : Vec3(0, 0, 1);
  const Vec3 x = y.cross(z).normalized();
  y = z.cross(x).normalized();
  Eigen::Matrix3d r;
  r.row(0) = x.transpose(), r.row(1) = y.transpose(), r.row(2) = z.transpose();
  return r;
}

Eigen::Matrix4d view_matrix(const Eigen::Matrix3d& rows, const Vec3& eye) {
  Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
  v.topLeftCorner<3, 3>() = rows;
  v.topRightCorner<3, 1>() = -rows * eye;
  return v;
}

}  // namespace

std::optional<LightView> light_view(const LightSource& s, const Vec3& min, const Vec3& max) {
  if (!(min.array() <= max.array()).all()) return std::nullopt;
  Vec3 corners[8];
  for (int i = 0; i < 8; ++i) corners[i] = Vec3(i & 1 ? max.x() : min.x(), i & 2 ? max.y() : min.y(), i & 4 ? max.z() : min.z());
  const double diagonal = std::max((max - min).norm(), 1e-6);
  LightView out;
  if (s.type == LightSource::Type::spot) {
    const Vec3 eye(s.position[0], s.position[1], s.position[2]);
    Vec3 dir(s.spot_direction[0], s.spot_direction[1], s.spot_direction[2]);
    if (dir.norm() == 0) return std::nullopt;
    dir.normalize();
    const Eigen::Matrix4d view = view_matrix(frame_rows(-dir), eye);
    double dmin = HUGE_VAL, dmax = -HUGE_VAL;
    for (const Vec3& c : corners) {
      const double d = (c - eye).dot(dir);
      dmin = std::min(dmin, d), dmax = std::max(dmax, d);
    }
    double far = s.z_far > 0 ? s.z_far : dmax * 1.01;
    double near = s.z_near > 0 ? s.z_near : std::max(dmin * 0.99, far * 1e-3);
    if (!(far > 0) || !(near > 0) || near >= far) return std::nullopt;
    const double half = std::min(static_cast<double>(s.cutoff), 85.0) * M_PI / 180.0;
    const double f = 1.0 / std::tan(half);
    Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
    p(0, 0) = f, p(1, 1) = f;
    p(2, 2) = -(far + near) / (far - near), p(2, 3) = -2 * far * near / (far - near);
    p(3, 2) = -1;
    out.view_projection = (p * view).cast<float>();
    out.perspective = true;
    out.far = static_cast<float>(far);
    return out;
  }
  if (s.type != LightSource::Type::directional) return std::nullopt;
  Vec3 dir(s.position[0], s.position[1], s.position[2]);  // the way the light travels, as SOFA's shader reads it
  if (dir.norm() == 0) return std::nullopt;
  dir.normalize();
  const Vec3 centre = 0.5 * (min + max);
  const Vec3 eye = centre - dir * diagonal;
  const Eigen::Matrix4d view = view_matrix(frame_rows(-dir), eye);
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const Vec3& c : corners) {
    const Vec3 e = (view * c.homogeneous()).head<3>();
    lo = lo.cwiseMin(e), hi = hi.cwiseMax(e);
  }
  const double margin = 0.01 * diagonal;
  lo.array() -= margin, hi.array() += margin;
  double near = s.z_near > 0 ? s.z_near : -hi.z(), far = s.z_far > 0 ? s.z_far : -lo.z();
  if (!(far > near)) return std::nullopt;
  Eigen::Matrix4d p = Eigen::Matrix4d::Identity();
  p(0, 0) = 2 / (hi.x() - lo.x()), p(0, 3) = -(hi.x() + lo.x()) / (hi.x() - lo.x());
  p(1, 1) = 2 / (hi.y() - lo.y()), p(1, 3) = -(hi.y() + lo.y()) / (hi.y() - lo.y());
  p(2, 2) = -2 / (far - near), p(2, 3) = -(far + near) / (far - near);
  out.view_projection = (p * view).cast<float>();
  out.perspective = false;
  out.far = static_cast<float>(far);
  return out;
}

int shadow_map_size(unsigned texture_size, int width, int height) {
  if (texture_size > 0) return static_cast<int>(std::min(texture_size, 8192u));
  for (int s : {1024, 512, 256})
    if (width >= s && height >= s) return s;
  return 128;
}

}  // namespace sinew::render
