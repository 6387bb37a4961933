#include "collision/model/triangle_octree_collision_model.h"

#include "collision/model/element_checks.h"
#include "core/registry.h"

namespace sinew {

bool TriangleOctreeCollisionModel::init_model() {
  if (!TriangleCollisionModel::init_model()) return false;
  update_normals();  // SOFA computes them when the triangles are set, at init
  return true;
}

void TriangleOctreeCollisionModel::compute_bounding_tree(int depth) {
  octree_.clear();  // rebuilt by the ray-trace narrow phase from this detection's positions
  x_ = positions();
  const bool changed = update_from_topology();
  if (changed) update_normals();
  const bool frozen = !moving.value() && tree_.built() && !changed;
  if (!frozen) {
    // Vertex normals from the normals of the previous detection, then the box,
    // both over triangles 1 … (SOFA's loop starts at 1, its box at point 0).
    const std::size_t n = x_.size();
    vertex_normals_.assign(n, Vec3::Zero());
    if (n > 0) surface_box_ = {x_[0], x_[0]};
    for (unsigned i = 1; i < tris_.size(); ++i) {
      const Triangle& t = tris_[i];
      if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
      for (unsigned v : t) vertex_normals_[v] += normals_[i];
      for (unsigned v : t)
        for (int c = 0; c < 3; ++c) {
          if (x_[v][c] > surface_box_.max[c]) surface_box_.max[c] = x_[v][c];
          if (x_[v][c] < surface_box_.min[c]) surface_box_.min[c] = x_[v][c];
        }
    }
  }
  const Vec3 n0 = normals_.empty() ? Vec3::Zero() : normals_[0];
  TriangleCollisionModel::compute_bounding_tree(depth);  // the BVH, and the normals of this detection
  if (!normals_.empty()) normals_[0] = n0;
  if (!frozen)
    for (Vec3& v : vertex_normals_) sofa_normalize(v);
}

const TriangleOctree& TriangleOctreeCollisionModel::octree() const {
  if (!octree_.built()) {
    octree_.build(tris_, x_);
    if (octree_.outside() > 0)
      warn_once(std::to_string(octree_.outside()) +
                " triangle(s) are left out of the octree: outside the cube [-800, 800]^3 it spans, of no extent, "
                "non-finite or with point indices beyond the state (rays do not find them, as in SOFA)");
  }
  return octree_;
}

void register_triangle_octree_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleOctreeCollisionModel";
  info.aliases = {"TriangleOctreeModel"};
  info.category = "Collision/Geometry";
  info.description =
      "triangle collision model that also keeps an octree of its triangles and vertex normals, for "
      "RayTraceNarrowPhase";
  info.create = creator<TriangleOctreeCollisionModel>();
  r.add(std::move(info));
}

}  // namespace sinew
