#include "collision/model/line_collision_model.h"

#include <algorithm>

#include "collision/model/element_checks.h"
#include "collision/model/point_collision_model.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool LineCollisionModel::init_model() {
  topology.set(model_topology(*this, topology.get()));
  if (!topology.get()) {
    msg_error("needs a topology (a mesh topology in its node or above, or the 'topology' link) to give its edges");
    return false;
  }
  points_ = node()->find_local<PointCollisionModel>();
  x_ = positions();
  update_from_topology();
  return true;
}

// Edges follow the topology: rebuilt when its edge list changed. True when rebuilt.
bool LineCollisionModel::update_from_topology() {
  const MeshTopologyBase& t = *topology;
  tris_ = &t.triangles();
  tris_around_edge_ = &t.triangles_around_edge();
  edges_around_vertex_ = &t.edges_around_vertex();
  const std::uint64_t v = t.elements_version(MeshTopologyBase::Elements::edges);
  if (v == edges_version_ && edges_.size() == t.edges().size()) return false;
  edges_version_ = v;
  edges_ = t.edges();
  return true;
}

void LineCollisionModel::compute_bounding_tree(int depth) {
  x_ = positions();
  const bool changed = update_from_topology();
  if (changed || tree_.size() != edges_.size()) tree_.resize(0);
  if (!moving.value() && tree_.built() && !changed) return;
  tree_.resize(edges_.size());
  if (edges_.empty()) return;
  const double d = contact_distance.value();
  const std::size_t n = x_.size();
  for (unsigned i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    Aabb box;
    if (e[0] >= n || e[1] >= n) {
      box = skipped_box(*this, "edge", i, "a point index beyond the state's size");
    } else {
      box.min = x_[e[0]].cwiseMin(x_[e[1]]) - Vec3::Constant(d);
      box.max = x_[e[0]].cwiseMax(x_[e[1]]) + Vec3::Constant(d);
      widen_to_end(box, {e[0], e[1]}, d);
      if (!finite_box(box))
        box = skipped_box(*this, "edge", i, "a non-finite position");
      else if (e[0] == e[1] || x_[e[0]] == x_[e[1]])
        box = skipped_box(*this, "edge", i, "coincident end points");
    }
    tree_.set_box(i, box);
  }
  tree_.update(depth);
}

local_min_distance::LineNeighbourhood LineCollisionModel::lmd_neighbourhood(unsigned i) const {
  if (!tris_) const_cast<LineCollisionModel*>(this)->update_from_topology();
  const auto& around = *tris_around_edge_;
  const std::size_t n = x_.size();
  if (i < around.size() && around[i].size() == 2) {
    const Triangle& t0 = (*tris_)[around[i][0]];
    const Triangle& t1 = (*tris_)[around[i][1]];
    if (std::max({t0[0], t0[1], t0[2], t1[0], t1[1], t1[2]}) < n)
      return local_min_distance::two_triangles(elem(i), t0, {x_[t0[0]], x_[t0[1]], x_[t0[2]]},
                                               {x_[t1[0]], x_[t1[1]], x_[t1[2]]}, both_side.value());
  }
  local_min_distance::LineNeighbourhood nb;
  nb.both_side = both_side.value();
  return nb;
}

bool LineCollisionModel::element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const {
  if (!self_collision.value() || other.node() != node()) return true;
  if (!tris_) const_cast<LineCollisionModel*>(this)->update_from_topology();
  const auto& around = *edges_around_vertex_;
  static const MeshTopologyBase::IndexList none;
  auto edges_at = [&](unsigned v) -> const MeshTopologyBase::IndexList& {
    return v < around.size() ? around[v] : none;
  };
  const unsigned p11 = edges_[i][0], p12 = edges_[i][1];
  if (&other == this) {
    const unsigned p21 = edges_[j][0], p22 = edges_[j][1];
    if (p11 == p21 || p11 == p22 || p12 == p21 || p12 == p22) return false;
    // Lines sharing an adjacent edge do not collide.
    for (unsigned a : {p11, p12})
      for (unsigned e1 : edges_at(a))
        for (unsigned b : {p21, p22})
          for (unsigned e2 : edges_at(b))
            if (e1 == e2) return false;
    return true;
  }
  if (&other == static_cast<const CollisionModelBase*>(points_)) {
    if (j == p11 || j == p12) return false;
    for (unsigned a : {p11, p12})
      for (unsigned e : edges_at(a))
        if (e < edges_.size() && (j == edges_[e][0] || j == edges_[e][1])) return false;
    return true;
  }
  if (other.kind() == Kind::point || other.kind() == Kind::line) return true;
  return other.element_can_collide(j, *this, i);
}

void register_line_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "LineCollisionModel";
  info.category = "Collision/Geometry";
  info.description = "collision model of the edges of a topology over a Vec3d state";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Vec3d") return nullptr;
    return std::make_unique<LineCollisionModel>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
