#include "engine/box_roi.h"

#include <cmath>

#include "core/registry.h"
#include "core/state_creator.h"
#include "io/sofa_quat.h"
#include "math/sofa_vec.h"

namespace sinew {

BoxROI::BoxROI(StateType type) : BaseROI(type) {
  add_input(&box);
  add_input(&oriented_box);
  draw_roi.add_alias("drawBoxes");
  quads.add_alias("quad");
  compute_quads.add_alias("computeQuad");
  quads_in_roi.add_alias("quadInROI");
}

bool order_box_corners(std::vector<VecN<6>>& boxes) {
  bool swapped = false;
  for (VecN<6>& b : boxes)
    for (int a = 0; a < 3; ++a)
      if (b[a] > b[a + 3]) std::swap(b[a], b[a + 3]), swapped = true;
  return swapped;
}

void BoxROI::normalize_boxes() {
  boxes_ = box.get();
  if (order_box_corners(boxes_)) box.edit() = boxes_;  // SOFA writes the ordered boxes back
}

void BoxROI::roi_init() {
  if (!box.is_set() && !oriented_box.is_set()) box.set({(VecN<6>() << 0, 0, 0, 1, 1, 1).finished()});
  if (spatial_dim() != 3 && oriented_box.is_set() && !oriented_box.get().empty())
    msg_warning("oriented boxes are not supported in " + std::to_string(spatial_dim()) + "D");
}

bool BoxROI::roi_do_update() {
  normalize_boxes();
  oriented_.clear();
  if (spatial_dim() == 3)
    for (const VecN<10>& b : oriented_box.get()) {
      OrientedBox o;
      const Vec3 p0(b[0], b[1], b[2]), p1(b[3], b[4], b[5]), p2(b[6], b[7], b[8]);
      const double depth = b[9];
      Vec3 normal = io::cross3((p1 - p0), p2 - p0);
      sofa_normalize(normal);
      const Vec3 p3 = p0 + (p2 - p1);
      const Vec3 p6 = p2 + normal * depth;
      Vec3 plane0 = io::cross3((p1 - p0), normal);
      sofa_normalize(plane0);
      Vec3 plane1 = io::cross3((p2 - p3), p6 - p3);
      sofa_normalize(plane1);
      Vec3 plane2 = io::cross3((p3 - p0), normal);
      sofa_normalize(plane2);
      Vec3 plane3 = io::cross3((p2 - p1), p6 - p2);
      sofa_normalize(plane3);
      o.p0 = p0;
      o.p2 = p2;
      o.normal = normal;
      o.plane0 = plane0;
      o.plane1 = plane1;
      o.plane2 = plane2;
      o.plane3 = plane3;
      o.width = std::fabs(sofa_dot(p2 - p0, plane0));
      o.length = std::fabs(sofa_dot(p2 - p0, plane2));
      o.depth = depth;
      oriented_.push_back(o);
    }
  return !boxes_.empty() || !oriented_box.get().empty();
}

bool BoxROI::point_in_roi(const double* p) const {
  const int d = spatial_dim();
  for (const VecN<6>& b : boxes_) {
    bool in = true;
    for (int i = 0; i < d; ++i)
      if (p[i] < b[i] || p[i] > b[i + 3]) {
        in = false;
        break;
      }
    if (in) return true;
  }
  if (d == 3)
    for (const OrientedBox& o : oriented_) {
      const Vec3 pv0(p[0] - o.p0[0], p[1] - o.p0[1], p[2] - o.p0[2]);
      const Vec3 pv1(p[0] - o.p2[0], p[1] - o.p2[1], p[2] - o.p2[2]);
      if (std::fabs(sofa_dot(pv0, o.plane0)) <= o.width && std::fabs(sofa_dot(pv1, o.plane1)) <= o.width &&
          std::fabs(sofa_dot(pv0, o.plane2)) <= o.length && std::fabs(sofa_dot(pv1, o.plane3)) <= o.length &&
          std::fabs(sofa_dot(pv0, o.normal)) <= std::fabs(o.depth / 2))
        return true;
    }
  return false;
}

void register_box_roi(Registry& r) {
  ComponentInfo info;
  info.name = "BoxROI";
  info.category = "Engine/Select";
  info.description = "selects the points and elements inside axis-aligned or oriented boxes";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<BoxROI>();
  r.add(std::move(info));
}

}  // namespace sinew
