#include "collision/model/point_collision_model.h"

#include "collision/model/element_checks.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool PointCollisionModel::init_model() {
  if (!topology.get()) topology.set(node()->get_mesh_topology_link());
  x_ = positions();
  return true;
}

void PointCollisionModel::compute_bounding_tree(int depth) {
  x_ = positions();
  ++stamp_;
  const bool resized = tree_.size() != x_.size();
  if (resized) tree_.resize(0);
  if (!moving.value() && tree_.built() && !resized) return;  // a fixed obstacle is bounded once
  tree_.resize(x_.size());
  if (!x_.empty()) {
    const double d = contact_distance.value();
    for (unsigned i = 0; i < x_.size(); ++i) {
      Aabb box{x_[i] - Vec3::Constant(d), x_[i] + Vec3::Constant(d)};
      widen_to_end(box, {i}, d);
      if (!finite_box(box)) box = skipped_box(*this, "point", i, "a non-finite position");
      tree_.set_box(i, box);
    }
    tree_.update(depth);
  }
  if (compute_normals.value()) update_normals();
}

void PointCollisionModel::update_normals() {
  // Average of the unit normals of the triangles around each point (SOFA's
  // PointCollisionModel::updateNormals); tetra faces are not handled there either
  // when triangles exist.
  normals_.assign(x_.size(), Vec3::Zero());
  const MeshTopologyBase* t = topology.get();
  if (!t) return;
  for (const Triangle& tri : t->triangles()) {
    if (tri[0] >= x_.size() || tri[1] >= x_.size() || tri[2] >= x_.size()) continue;
    const Vec3 n = (x_[tri[1]] - x_[tri[0]]).cross(x_[tri[2]] - x_[tri[0]]);
    for (unsigned v : tri) normals_[v] += n;
  }
  for (Vec3& n : normals_) sofa_normalize(n);
}

void PointCollisionModel::build_lmd() const {
  lmd_stamp_ = stamp_;
  // The filter applies when a line model is found in this node or above (SOFA's upward search).
  lmd_line_above_ = false;
  for (const Node* n = node(); n && !lmd_line_above_; n = n->parent())
    for (const auto& o : n->objects())
      if (auto* m = dynamic_cast<const CollisionModelBase*>(o.get()); m && m->kind() == Kind::line)
        lmd_line_above_ = true;
  const std::size_t n = x_.size();
  lmd_normals_.clear();
  lmd_others_.clear();
  lmd_normal_start_.assign(n + 1, 0);
  lmd_other_start_.assign(n + 1, 0);
  const MeshTopologyBase* t = topology.get();
  // Lists fetched once: each read of a topology list goes through its field's link checks.
  static const std::vector<MeshTopologyBase::IndexList> no_lists;
  static const std::vector<Triangle> no_triangles;
  static const std::vector<Edge> no_edges;
  const auto& tav = t ? t->triangles_around_vertex() : no_lists;
  const auto& eav = t ? t->edges_around_vertex() : no_lists;
  const auto& triangles = t ? t->triangles() : no_triangles;
  const auto& edges = t ? t->edges() : no_edges;
  for (unsigned i = 0; i < n; ++i) {
    lmd_normal_start_[i] = static_cast<unsigned>(lmd_normals_.size());
    lmd_other_start_[i] = static_cast<unsigned>(lmd_others_.size());
    if (!t) continue;
    if (i < tav.size())
      for (unsigned k : tav[i]) {
        const Triangle& tri = triangles[k];
        if (tri[0] < n && tri[1] < n && tri[2] < n)
          lmd_normals_.push_back(local_min_distance::unit_normal(x_[tri[0]], x_[tri[1]], x_[tri[2]]));
      }
    if (i < eav.size())
      for (unsigned k : eav[i]) {
        const Edge& e = edges[k];
        const unsigned other = e[0] == i ? e[1] : e[0];
        if (other < n) lmd_others_.push_back(x_[other]);
      }
  }
  lmd_normal_start_[n] = static_cast<unsigned>(lmd_normals_.size());
  lmd_other_start_[n] = static_cast<unsigned>(lmd_others_.size());
}

void PointCollisionModel::prepare_for_sharing(bool neighbourhoods) const {
  if (const MeshTopologyBase* t = topology.get()) {
    t->edges_around_vertex();
    t->triangles_around_vertex();
  }
  if (neighbourhoods && lmd_stamp_ != stamp_) build_lmd();
}

local_min_distance::PointNeighbourhood PointCollisionModel::lmd_neighbourhood(unsigned i) const {
  if (lmd_stamp_ != stamp_) build_lmd();
  local_min_distance::PointNeighbourhood nb;
  nb.line_model_above = lmd_line_above_;
  nb.both_side = both_side.value();
  nb.triangle_normals = std::span<const Vec3>(lmd_normals_)
                            .subspan(lmd_normal_start_[i], lmd_normal_start_[i + 1] - lmd_normal_start_[i]);
  nb.edge_neighbours =
      std::span<const Vec3>(lmd_others_).subspan(lmd_other_start_[i], lmd_other_start_[i + 1] - lmd_other_start_[i]);
  return nb;
}

bool PointCollisionModel::element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const {
  if (!self_collision.value() || other.node() != node()) return true;
  if (&other != this) return other.kind() == Kind::point ? true : other.element_can_collide(j, *this, i);
  if (i <= j) return false;  // each unordered pair once
  const MeshTopologyBase* t = topology.get();
  if (!t) return true;
  // Points that share a neighbour, or are neighbours, do not collide.
  const auto around1 = vertices_around_vertex(*t, i);
  const auto around2 = vertices_around_vertex(*t, j);
  for (unsigned v1 : around1)
    for (unsigned v2 : around2)
      if (v1 == v2 || v1 == j || i == v2) return false;
  return true;
}

void register_point_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "PointCollisionModel";
  info.category = "Collision/Geometry";
  info.description = "collision model of the points of a Vec3d state";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Vec3d") return nullptr;
    return std::make_unique<PointCollisionModel>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
