#include "engine/plane_roi.h"

#include <cmath>

#include "core/engine.h"
#include "core/node.h"
#include "core/registry.h"
#include "core/roles.h"
#include "io/mesh_loader.h"

#include <Eigen/Geometry>

namespace sinew {

namespace {

FlatVec flat(int width) {
  FlatVec v;
  v.width = width;
  return v;
}

// One slab: SOFA's computePlane, then isPointInPlane.
struct Slab {
  Vec3 p0, p2, vdepth, plane0, plane1, plane2, plane3;
  double depth = 0, width = 0, length = 0;

  explicit Slab(const double* p) {
    p0 = Vec3(p[0], p[1], p[2]);
    const Vec3 p1(p[3], p[4], p[5]);
    p2 = Vec3(p[6], p[7], p[8]);
    depth = p[9];
    vdepth = (p1 - p0).cross(p2 - p0);
    normalize(vdepth);
    const Vec3 p3 = p0 + (p2 - p1);
    const Vec3 p4 = p0 + vdepth * (depth / 2);
    const Vec3 p6 = p2 + vdepth * (depth / 2);
    plane0 = (p1 - p0).cross(p4 - p0);
    normalize(plane0);
    plane1 = (p2 - p3).cross(p6 - p3);
    normalize(plane1);
    plane2 = (p3 - p0).cross(p4 - p0);
    normalize(plane2);
    plane3 = (p2 - p1).cross(p6 - p2);
    normalize(plane3);
    width = std::fabs((p2 - p0).dot(plane0));
    length = std::fabs((p2 - p0).dot(plane2));
  }
  // SOFA's Vec::normalize: divides only above machine epsilon.
  static void normalize(Vec3& v) {
    const double n = v.norm();
    if (n > std::numeric_limits<double>::epsilon()) v /= n;
  }
  bool contains(const Vec3& p) const {
    const Vec3 pv0 = p - p0, pv1 = p - p2;
    return std::fabs(pv0.dot(plane0)) <= width && std::fabs(pv1.dot(plane1)) <= width &&
           std::fabs(pv0.dot(plane2)) <= length && std::fabs(pv1.dot(plane3)) <= length &&
           std::fabs(pv0.dot(vdepth)) <= std::fabs(depth / 2);
  }
};

}  // namespace

PlaneROI::PlaneROI(StateType type)
    : position(this, "position", flat(state_type_info(type).coord_width),
               "rest positions of the points (default: the context's state rest_position, else a loader's position)",
               "Inputs", "length"),
      points_in_roi(this, "pointsInROI", flat(state_type_info(type).coord_width), "points in the ROI", "Outputs",
                    "length") {
  position.add_alias("rest_position");
  draw_boxes.add_alias("isVisible");
  for (BaseField* f : std::initializer_list<BaseField*>{&position, &edges, &triangles, &tetrahedra}) add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{&indices, &edge_indices, &triangle_indices,
                                                        &tetrahedron_indices, &points_in_roi, &edges_in_roi,
                                                        &triangles_in_roi, &tetrahedra_in_roi})
    add_output(f);
}

void PlaneROI::init() {
  if (plane.value().size() % 10 != 0) {
    msg_error("plane needs 10 values per slab (3 points and a depth); got " + std::to_string(plane.value().size()));
    set_state(ComponentState::invalid);
    return;
  }
  Node& n = *node();
  if (!position.is_set() && !position.parent()) {
    // The context's state (this node, then up), else a mesh loader (this node, then up).
    if (MechanicalState* ms = n.get_mechanical_state()) {
      if (BaseField* f = ms->find_field("rest_position")) position.set_parent(f);
    } else if (MeshLoader* loader = n.find_up<MeshLoader>()) {
      position.set_parent(&loader->position);
    } else {
      msg_error("no positions: set 'position' or put a MechanicalObject or mesh loader above the PlaneROI");
      set_state(ComponentState::invalid);
      return;
    }
  }
  if (MeshTopologyBase* topo = n.find_up<MeshTopologyBase>()) {
    auto link = [&](auto& field, bool wanted, const char* name) {
      if (!field.is_set() && !field.parent() && wanted)
        if (BaseField* f = topo->find_field(name)) field.set_parent(f);
    };
    if (!edges.is_set() || !triangles.is_set()) {
      link(edges, compute_edges.value(), "edges");
      link(triangles, compute_triangles.value(), "triangles");
      link(tetrahedra, compute_tetrahedra.value(), "tetrahedra");
    }
  }
  set_dirty();
  update();
}

void PlaneROI::do_update() {
  const std::vector<double>& p = plane.get();
  if (p.empty() || p.size() % 10 != 0) return;
  std::vector<Slab> slabs;
  for (std::size_t k = 0; k < p.size(); k += 10) slabs.emplace_back(&p[k]);
  const FlatVec& x = position.get();
  const std::size_t n = x.size(), w = static_cast<std::size_t>(x.width);
  auto point = [&](unsigned i) { return Vec3(x.data[i * w], x.data[i * w + 1], x.data[i * w + 2]); };
  auto inside = [&](const Vec3& q) {
    for (const Slab& s : slabs)
      if (s.contains(q)) return true;
    return false;
  };
  auto& ids = indices.edit();
  auto& pts = points_in_roi.edit();
  ids.clear();
  pts.data.clear();
  pts.width = x.width;
  for (unsigned i = 0; i < n; ++i)
    if (inside(point(i))) {
      ids.push_back(i);
      pts.data.insert(pts.data.end(), x.data.begin() + i * w, x.data.begin() + (i + 1) * w);
    }
  // An element is in when all its points are in one same slab (SOFA tests slab by slab).
  bool bad = false;
  auto select = [&](const auto& elems, bool wanted, auto& out_ids, auto& out_elems) {
    auto& oi = out_ids.edit();
    auto& oe = out_elems.edit();
    oi.clear();
    oe.clear();
    if (!wanted) return;
    for (unsigned e = 0; e < elems.size(); ++e) {
      bool ok = true;
      for (unsigned v : elems[e]) ok = ok && v < n;
      if (!ok) {
        bad = true;
        continue;
      }
      for (const Slab& s : slabs) {
        bool all = true;
        for (unsigned v : elems[e]) all = all && s.contains(point(v));
        if (all) {
          oi.push_back(e);
          oe.push_back(elems[e]);
          break;
        }
      }
    }
  };
  select(edges.get(), compute_edges.value(), edge_indices, edges_in_roi);
  select(triangles.get(), compute_triangles.value(), triangle_indices, triangles_in_roi);
  select(tetrahedra.get(), compute_tetrahedra.value(), tetrahedron_indices, tetrahedra_in_roi);
  if (bad) msg_error("some elements refer to points beyond the " + std::to_string(n) + " positions: skipped");
}

void register_plane_roi(Registry& r) {
  ComponentInfo info;
  info.name = "PlaneROI";
  info.category = "Engine/Select";
  info.description = "points and elements inside slabs given by three points and a depth";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType st;
    if (!state_type_from_name(t, st) || (st != StateType::vec3 && st != StateType::rigid3)) return nullptr;
    return std::make_unique<PlaneROI>(st);
  };
  r.add(std::move(info));
}

}  // namespace sinew
