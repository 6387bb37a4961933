#include "engine/transform/vertex2_frame.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/registry.h"
#include "math/quat.h"
#include "math/sofa_vec.h"

namespace sinew {

namespace {
FlatVec rigid_list() {
  FlatVec v;
  v.width = 7;
  return v;
}
}  // namespace

Vertex2Frame::Vertex2Frame() : frames(this, "frames", rigid_list(), "frame of each vertex", "Outputs") {
  add_input(&position);
  add_input(&tex_coords);
  add_input(&normals);
  add_input(&rotation);
  add_input(&rotation_angle);
  add_input(&use_normals);
  add_input(&invert_normals);
  add_output(&frames);
}

void Vertex2Frame::do_update() {
  const std::vector<Vec3>& x = position.get();
  const std::vector<Vec3>& nrm = normals.get();
  const std::size_t n = x.size();
  if (n == 0) return;  // SOFA: nothing yet, outputs kept
  const double eps = std::numeric_limits<double>::epsilon();
  const int axis_id = rotation.get();
  const double angle = rotation_angle.get() * std::numbers::pi / 180;
  auto orientation = [&](const Vec3& xa, const Vec3& ya, const Vec3& za) {
    Vec3 a = Vec3::Zero();
    if (axis_id == 0) a = xa;
    else if (axis_id == 1) a = ya;
    else if (axis_id == 2) a = za;
    const Quat q2 = quat_from_axis_angle(a, angle);
    Mat3 m;
    for (int i = 0; i < 3; ++i) {
      m(i, 0) = xa[i];
      m(i, 1) = ya[i];
      m(i, 2) = za[i];
    }
    return quat_mul(q2, quat_from_matrix(m));
  };

  FlatVec out = frames.value();
  out.width = 7;
  out.data.resize(n * 7);
  auto put = [&](std::size_t i, const Vec3& c, const Quat& q) {
    double* f = &out.data[i * 7];
    f[0] = c[0];
    f[1] = c[1];
    f[2] = c[2];
    q.store(f + 3);
  };
  if (use_normals.get()) {
    if (nrm.size() < n) {
      msg_error("useNormals needs one normal per vertex (" + std::to_string(nrm.size()) + " normals for " +
                std::to_string(n) + " vertices): nothing computed");
      return;
    }
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 z = invert_normals.get() ? Vec3(-nrm[i]) : nrm[i];
      sofa_normalize(z);
      Vec3 y(0.0, 1.0, 0.0);
      if (1.0 - std::fabs(sofa_dot(y, z)) <= eps) y = Vec3(0.0, 0.0, 1.0);
      Vec3 xa = sofa_cross(y, z);
      sofa_normalize(xa);
      y = sofa_cross(z, xa);
      sofa_normalize(y);
      put(i, x[i], orientation(xa, y, z));
    }
  } else {
    if (n <= 1) {
      msg_error("without normals at least two vertices are needed: nothing computed");
      return;
    }
    Quat last;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      Vec3 xa = x[i + 1] - x[i];
      sofa_normalize(xa);
      Vec3 z(1.0, 0.0, 0.0);
      if (1.0 - std::fabs(sofa_dot(z, xa)) <= eps) z = Vec3(0.0, 0.0, 1.0);
      Vec3 y = sofa_cross(z, xa);
      sofa_normalize(y);
      z = sofa_cross(xa, y);
      sofa_normalize(z);
      last = orientation(xa, y, z);
      put(i, x[i], last);
    }
    put(n - 1, x[n - 1], last);
  }
  frames.set(std::move(out));
}

void register_vertex2_frame(Registry& r) {
  ComponentInfo info;
  info.name = "Vertex2Frame";
  info.category = "Engine/Transform";
  info.description = "a rigid frame at each vertex of a mesh, oriented by its normal or the next vertex";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<Vertex2Frame>(); };
  r.add(std::move(info));
}

}  // namespace sinew
