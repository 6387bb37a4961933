// TriangleOctreeCollisionModel: a TriangleCollisionModel that also keeps
// what RayTraceNarrowPhase casts rays with (spec/interaction.md §3.3; SOFA's
// TriangleOctreeCollisionModel): an octree of its triangles, built on demand
// from the current positions and dropped at every detection, the normal of
// each vertex and the box of the whole surface.
//
// SOFA's order of updates is kept because contacts depend on it: at each
// detection the vertex normals are summed from the triangle normals of the
// previous detection, and triangle 0 takes part in neither the vertex
// normals, nor the box (which starts at point 0), nor the normal update (its
// normal stays the one computed when the triangles were set). A model with
// moving="false" keeps all of these from its first detection.
//
// Under BVHNarrowPhase it behaves as a TriangleCollisionModel (SOFA's would
// only test triangle 0 there: its bounding tree has a single cube).
#pragma once

#include <vector>

#include "collision/cube_tree.h"
#include "collision/model/triangle_collision_model.h"
#include "math/triangle_octree.h"

namespace sinew {

class TriangleOctreeCollisionModel final : public TriangleCollisionModel {
 public:
  TriangleOctreeCollisionModel() { always_compute_normals_ = true; }

  Field<bool> draw_octree{this, "drawOctree", false, "draw the octree's cells (viewer)", "Visualization"};

  void compute_bounding_tree(int depth) override;

  // The octree of the current positions (built on first use after a detection).
  const TriangleOctree& octree() const;
  // Unit normal of each point (zero for a point of no triangle but triangle 0).
  const std::vector<Vec3>& vertex_normals() const { return vertex_normals_; }
  // Box of point 0 and the points of triangles 1 … (SOFA's single cube) [length].
  const Aabb& surface_box() const { return surface_box_; }
  // Current position of point v (v < point_count()).
  const Vec3& point(unsigned v) const { return x_[v]; }
  std::size_t point_count() const { return x_.size(); }

 protected:
  bool init_model() override;

 private:
  mutable TriangleOctree octree_;
  mutable bool octree_warned_ = false;
  std::vector<Vec3> vertex_normals_;
  Aabb surface_box_;
};

}  // namespace sinew
