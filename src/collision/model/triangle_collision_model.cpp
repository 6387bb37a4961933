#include "collision/model/triangle_collision_model.h"

#include "collision/model/element_checks.h"
#include "collision/model/point_collision_model.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool TriangleCollisionModel::init_model() {
  topology.set(model_topology(*this, topology.get()));
  if (!topology.get()) {
    msg_error("needs a topology (a mesh topology in its node or above, or the 'topology' link) to give its triangles");
    return false;
  }
  points_ = node()->find_local<PointCollisionModel>();
  x_ = positions();
  update_from_topology();
  return true;
}

// Triangles follow the topology: the topology's triangles, then per quad
// (a, b, c, d) the triangles (b, c, a) and (d, a, c). True when rebuilt.
bool TriangleCollisionModel::update_from_topology() {
  const MeshTopologyBase& t = *topology;
  const auto vt = t.elements_version(MeshTopologyBase::Elements::triangles);
  const auto vq = t.elements_version(MeshTopologyBase::Elements::quads);
  const std::size_t n = t.triangles().size() + 2 * t.quads().size();
  if (vt == tris_version_ && vq == quads_version_ && n == tris_.size()) return false;
  tris_version_ = vt;
  quads_version_ = vq;
  tris_ = t.triangles();
  n_topology_tris_ = tris_.size();
  for (const Quad& q : t.quads()) {
    tris_.push_back({q[1], q[2], q[0]});
    tris_.push_back({q[3], q[0], q[2]});
  }
  normals_.assign(tris_.size(), Vec3::Zero());
  compute_flags();
  return true;
}

// Each vertex and edge belongs to the first triangle around it (§2.6).
void TriangleCollisionModel::compute_flags() {
  const MeshTopologyBase& t = *topology;
  flags_.assign(tris_.size(), 0);
  if (n_topology_tris_ == 0) return;
  const auto& around_vertex = t.triangles_around_vertex();
  const auto& edges_in = t.edges_in_triangle();
  const auto& around_edge = t.triangles_around_edge();
  for (unsigned i = 0; i < n_topology_tris_; ++i) {
    int f = 0;
    for (int j = 0; j < 3; ++j) {
      const unsigned v = tris_[i][j];
      if (v < around_vertex.size() && !around_vertex[v].empty() && around_vertex[v][0] == i) f |= kFlagP1 << j;
    }
    if (i < edges_in.size())
      for (int j = 0; j < 3; ++j) {
        const unsigned e = edges_in[i][j];
        if (e >= around_edge.size() || around_edge[e].empty()) continue;
        if (around_edge[e][0] == i) f |= kFlagE23 << j;
        if (around_edge[e].size() == 1) f |= kFlagBE23 << j;
      }
    flags_[i] = f;
  }
}

void TriangleCollisionModel::compute_bounding_tree(int depth) {
  x_ = positions();
  const bool changed = update_from_topology();
  if (changed || tree_.size() != tris_.size()) tree_.resize(0);
  if (!moving.value() && tree_.built() && !changed) return;  // normals of fixed obstacles are frozen too (SOFA)
  tree_.resize(tris_.size());
  if (tris_.empty()) return;
  const double d = contact_distance.value();
  const bool normals = compute_normals.value() || always_compute_normals_ || !tree_.built();
  const std::size_t n = x_.size();
  for (unsigned i = 0; i < tris_.size(); ++i) {
    const Triangle& t = tris_[i];
    Aabb box;
    if (t[0] >= n || t[1] >= n || t[2] >= n) {
      tree_.set_box(i, skipped_box(*this, "triangle", i, "a point index beyond the state's size"));
      continue;
    }
    const Vec3 &p1 = x_[t[0]], &p2 = x_[t[1]], &p3 = x_[t[2]];
    box.min = p1.cwiseMin(p2).cwiseMin(p3) - Vec3::Constant(d);
    box.max = p1.cwiseMax(p2).cwiseMax(p3) + Vec3::Constant(d);
    widen_to_end(box, {t[0], t[1], t[2]}, d);
    const Vec3 cross = (p2 - p1).cross(p3 - p1);
    if (normals) {
      normals_[i] = cross;
      sofa_normalize(normals_[i]);
    }
    if (!finite_box(box))
      box = skipped_box(*this, "triangle", i, "a non-finite position");
    else if (cross.squaredNorm() == 0.0)
      box = skipped_box(*this, "triangle", i, "zero area (degenerate)");
    tree_.set_box(i, box);
  }
  tree_.update(depth);
}

void TriangleCollisionModel::update_normals() {
  const std::size_t n = x_.size();
  for (unsigned i = 0; i < tris_.size(); ++i) {
    const Triangle& t = tris_[i];
    if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
    normals_[i] = (x_[t[1]] - x_[t[0]]).cross(x_[t[2]] - x_[t[0]]);
    sofa_normalize(normals_[i]);
  }
}

bool TriangleCollisionModel::element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const {
  if (!self_collision.value() || other.node() != node()) return true;
  if (&other == static_cast<const CollisionModelBase*>(points_)) {
    const Triangle& t = tris_[i];
    if (j == t[0] || j == t[1] || j == t[2]) return false;
  }
  return true;
}

void register_triangle_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleCollisionModel";
  info.category = "Collision/Geometry";
  info.description = "collision model of the triangles (and quads, split in two) of a topology over a Vec3d state";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Vec3d") return nullptr;
    return std::make_unique<TriangleCollisionModel>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
