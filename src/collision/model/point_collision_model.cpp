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
  const bool resized = tree_.size() != x_.size();
  if (resized) tree_.resize(0);
  if (!moving.value() && tree_.built() && !resized) return;  // a fixed obstacle is bounded once
  tree_.resize(x_.size());
  if (!x_.empty()) {
    const double d = contact_distance.value();
    for (unsigned i = 0; i < x_.size(); ++i) {
      Aabb box{x_[i] - Vec3::Constant(d), x_[i] + Vec3::Constant(d)};
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
