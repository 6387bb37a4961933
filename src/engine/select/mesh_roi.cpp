#include "engine/select/mesh_roi.h"

#include <utility>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"
#include "io/mesh_loader.h"

namespace sinew {

MeshROI::MeshROI(StateType type)
    : BaseROI(type),
      roi_position(this, "ROIposition", empty_coords(type), "points of the ROI mesh (default: the local state's "
                                                            "rest_position, else the local mesh loader's position)",
                   "Inputs", "length") {
  add_input(&roi_position);
  add_input(&roi_edges);
  add_input(&roi_triangles);
  add_input(&compute_mesh_roi);
  add_output(&box);
  // SOFA's MeshROI was never strict and keeps that default.
  strict.set(false);
  strict.unset();
}

void MeshROI::roi_init() {
  Node& n = *node();
  if (!roi_position.is_set() && !roi_position.parent()) {
    msg_warning("'ROIposition' is not set: the local state's rest_position (else the local loader's position) is "
                "used");
    if (auto* ms = n.find_local<MechanicalState>()) {
      if (BaseField* f = ms->find_field("rest_position")) roi_position.set_parent(f);
    } else if (auto* loader = n.find_local<MeshLoader>()) {
      roi_position.set_parent(&loader->position);
    }
  }
  if (!roi_edges.is_set() || !roi_triangles.is_set())
    if (auto* topo = n.find_local<MeshTopologyBase>()) {
      if (!roi_edges.is_set() && !roi_edges.parent() && compute_edges.get())
        if (BaseField* f = topo->find_field("edges")) roi_edges.set_parent(f);
      if (!roi_triangles.is_set() && !roi_triangles.parent() && compute_triangles.get())
        if (BaseField* f = topo->find_field("triangles")) roi_triangles.set_parent(f);
    }

  // Bounding box of the ROI mesh (kept when it has no points, as SOFA).
  const FlatVec& x = roi_position.get();
  VecN<6> b = box.get();
  const std::size_t w = static_cast<std::size_t>(x.width);
  mesh_x_.clear();
  for (std::size_t i = 0; i < x.size(); ++i) {
    Vec3 p = Vec3::Zero();
    for (std::size_t k = 0; k < std::min<std::size_t>(3, w); ++k) p[static_cast<int>(k)] = x.data[i * w + k];
    mesh_x_.push_back(p);
  }
  if (!mesh_x_.empty()) {
    for (int k = 0; k < 3; ++k) b[k] = b[k + 3] = mesh_x_[0][k];
    for (const Vec3& q : mesh_x_)
      for (int k = 0; k < 3; ++k) {
        b[k] = std::min(b[k], q[k]);
        b[k + 3] = std::max(b[k + 3], q[k]);
      }
  }
  for (int k = 0; k < 3; ++k)
    if (b[k] > b[k + 3]) std::swap(b[k], b[k + 3]);
  box.set(b);

  mesh_t_ = roi_triangles.get();
  roi_ready_ = true;
  for (const Triangle& t : mesh_t_)
    for (unsigned v : t)
      if (v >= mesh_x_.size()) {
        msg_error("ROItriangles refers to point " + std::to_string(v) + ", beyond the " +
                  std::to_string(mesh_x_.size()) + " points of ROIposition: nothing is selected");
        roi_ready_ = false;
        return;
      }
}

namespace {
// Whether pt lies on the inner side of edge AB for a triangle of normal N.
bool same_order(const Vec3& A, const Vec3& B, const Vec3& pt, const Vec3& N) {
  Vec3 v;
  v[0] = (B[1] - A[1]) * (pt[2] - A[2]) - (pt[1] - A[1]) * (B[2] - A[2]);
  v[1] = (B[2] - A[2]) * (pt[0] - A[0]) - (pt[2] - A[2]) * (B[0] - A[0]);
  v[2] = (B[0] - A[0]) * (pt[1] - A[1]) - (pt[0] - A[0]) * (B[1] - A[1]);
  return !(v[0] * N[0] + v[1] * N[1] + v[2] * N[2] < 0);
}
}  // namespace

bool MeshROI::point_in_roi(const double* q) const {
  if (!compute_mesh_roi.get()) return true;
  if (!roi_ready_) return false;
  const Vec3 p(q[0], q[1], q[2]);
  const VecN<6>& b = box.value();
  if (!(p[0] >= b[0] && p[0] <= b[3] && p[1] >= b[1] && p[1] <= b[4] && p[2] >= b[2] && p[2] <= b[5])) return false;
  // Ray towards a point 100 units (SOFA's float 100.0f) beyond the nearer corner of the box.
  const Vec3 lo(b[0], b[1], b[2]), hi(b[3], b[4], b[5]);
  const Vec3 dir = (lo - p).squaredNorm() < (hi - p).squaredNorm() ? Vec3((lo.array() - 100.0).matrix() - p)
                                                                    : Vec3((hi.array() + 100.0).matrix() - p);
  int through = 0;
  for (const Triangle& t : mesh_t_) {
    const Vec3& p0 = mesh_x_[t[0]];
    const Vec3& p1 = mesh_x_[t[1]];
    const Vec3& p2 = mesh_x_[t[2]];
    Vec3 N;
    N[0] = (p1[1] - p0[1]) * (p2[2] - p1[2]) - (p1[2] - p0[2]) * (p2[1] - p1[1]);
    N[1] = (p1[2] - p0[2]) * (p2[0] - p1[0]) - (p1[0] - p0[0]) * (p2[2] - p1[2]);
    N[2] = (p1[0] - p0[0]) * (p2[1] - p1[1]) - (p1[1] - p0[1]) * (p2[0] - p1[0]);
    const double dot = N.dot(dir);
    if (dot == 0) continue;
    const double d = N.dot(p0 - p) / dot;
    if (d < 0) continue;  // the triangle is behind the point
    const Vec3 hit = p + d * dir;
    if (same_order(p0, p1, hit, N) && same_order(p1, p2, hit, N) && same_order(p2, p0, hit, N)) ++through;
  }
  return through % 2 != 0;
}

void register_mesh_roi(Registry& r) {
  ComponentInfo info;
  info.name = "MeshROI";
  info.category = "Engine/Select";
  info.description = "selects the points and elements inside a closed triangle mesh";
  info.templates = {"Vec3d", "Rigid3d", "Vec6d"};
  info.default_template = "Vec3d";
  info.create = state_creator<MeshROI>();
  r.add(std::move(info));
}

}  // namespace sinew
