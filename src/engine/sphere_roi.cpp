#include "engine/sphere_roi.h"

#include <cmath>

#include "core/registry.h"
#include "core/state_creator.h"
#include "io/sofa_quat.h"
#include "math/sofa_vec.h"

namespace sinew {

SphereROI::SphereROI(StateType type) : BaseROI(type) {
  for (BaseField* f : std::initializer_list<BaseField*>{&centers, &radii, &direction, &normal, &edge_angle, &tri_angle})
    add_input(f);
  draw_roi.add_alias("isVisible");
  draw_roi.add_alias("drawSphere");
  tri_angle.add_alias("angle");
  indices.add_alias("pointIndices");
  position.add_alias("rest_position");
}

bool SphereROI::roi_do_update() {
  c_ = centers.get();
  r_ = radii.get();
  if (c_.empty()) return false;
  if (c_.size() != r_.size()) {
    if (r_.size() == 1) {
      r_.assign(c_.size(), r_[0]);
      radii.edit() = r_;  // SOFA writes the broadcast radii back
    } else {
      msg_warning("number of sphere centres (" + std::to_string(c_.size()) + ") and radii (" +
                  std::to_string(r_.size()) + ") do not match");
      return false;
    }
  }
  if (edge_angle.get() > 0) {
    Vec3 d = direction.get();
    sofa_normalize(d);
    direction.edit() = d;
  }
  if (tri_angle.get() > 0) {
    Vec3 n = normal.get();
    sofa_normalize(n);
    normal.edit() = n;
  }
  dir_ = direction.get();
  normal_ = normal.get();
  return true;
}

bool SphereROI::point_in_roi(const double* p) const {
  for (std::size_t j = 0; j < c_.size(); ++j) {
    const double dx = p[0] - c_[j][0], dy = p[1] - c_[j][1], dz = p[2] - c_[j][2];
    if (dx * dx + dy * dy + dz * dz <= r_[j] * r_[j]) return true;
  }
  return false;
}

bool SphereROI::edge_extra(const Edge& e) const {
  const double a = edge_angle.value();
  if (!(a > 0)) return true;
  const double* x0 = point(e[0]);
  const double* x1 = point(e[1]);
  Vec3 n(x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]);
  sofa_normalize(n);
  return std::fabs(n[0] * dir_[0] + n[1] * dir_[1] + n[2] * dir_[2]) < std::fabs(std::cos(a * M_PI / 180.0));
}

bool SphereROI::triangle_extra(const Triangle& t) const {
  const double a = tri_angle.value();
  if (!(a > 0)) return true;
  const double* x0 = point(t[0]);
  const double* x1 = point(t[1]);
  const double* x2 = point(t[2]);
  const Vec3 u(x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]);
  const Vec3 v(x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]);
  Vec3 n = io::cross3(u, v);
  sofa_normalize(n);
  return n[0] * normal_[0] + n[1] * normal_[1] + n[2] * normal_[2] < std::cos(a * M_PI / 180.0);
}

void register_sphere_roi(Registry& r) {
  ComponentInfo info;
  info.name = "SphereROI";
  info.category = "Engine/Select";
  info.description = "selects the points and elements inside spheres (optionally by edge direction / triangle normal)";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<SphereROI>();
  r.add(std::move(info));
}

}  // namespace sinew
