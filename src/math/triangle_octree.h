// TriangleOctree: SOFA's octree of triangles for ray casting
// (sofa::helper::TriangleOctree, used by TriangleOctreeCollisionModel,
// RayTraceNarrowPhase and RandomPointDistributionInSurface).
//
// The octree spans the fixed cube [-800, 800]³ (SOFA's CUBE_SIZE; triangles
// not inside it entirely are left out, counted by `outside()`). Each triangle
// is stored in every cell of the level whose cell size is the power-of-two
// fraction of 1600 at or above the triangle's largest box extent, at each
// grid corner of that level inside the triangle's box (SOFA's fillOctree).
// `trace` walks the cells a ray crosses, nearest first (the parametric
// traversal of Revelles et al.), and returns the nearest triangle hit in the
// first cell holding one, with the triangles stored at the cells above it.
//
// Nodes live in one array and the triangles of each node in one array, in
// insertion order: rebuilding every step allocates nothing once warm.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "math/types.h"

namespace sinew {

class TriangleOctree {
 public:
  using Triangle = std::array<unsigned, 3>;  // point indices (core's Triangle)
  static constexpr double kCubeSize = 800;  // half the side of the root cell [length]

  struct TraceResult {
    int tid = -1;           // triangle hit, -1: none
    double t = 0, u = 0, v = 0;  // ray parameter, barycentric coordinates of the hit on (p2, p3)
  };

  // Builds the octree of `triangles` over `positions` (both must outlive the
  // traces). Triangles with an index beyond the positions are left out.
  void build(std::span<const Triangle> triangles, std::span<const Vec3> positions);
  void clear();
  bool built() const { return !nodes_.empty(); }
  // Triangles left out of the last build (not inside the root cube, or bad indices).
  std::size_t outside() const { return outside_; }

  // The nearest triangle the ray origin + t·direction (t > ε) crosses, as SOFA
  // finds it; -1 when none. `result` holds the hit's t, u, v.
  int trace(Vec3 origin, Vec3 direction, TraceResult& result) const;

  std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Node {
    double x = 0, y = 0, z = 0, size = 0;  // corner and side of the cell
    int child[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    bool is_leaf = true;
    unsigned first = 0, count = 0;  // triangles: objects_[first, first + count)
  };
  struct Ray {
    Vec3 origin, direction;  // reflected into the positive octant (cell choice)
    Vec3 origin1, direction1;  // as given (triangle tests)
  };
  void insert(double x, double y, double z, double inc, int tri);
  int trace_node(int node, const Ray& ray, double tx0, double ty0, double tz0, double tx1, double ty1, double tz1,
                 unsigned a, unsigned b, TraceResult& result) const;
  int nearest_triangle(int node, int first_candidate, const Ray& ray, TraceResult& result) const;
  bool hit(int tri, const Ray& ray, double& t, double& u, double& v) const;

  std::span<const Triangle> tris_;
  std::span<const Vec3> x_;
  std::vector<Node> nodes_;
  std::vector<std::pair<int, int>> inserted_;  // (node, triangle) in insertion order
  std::vector<int> objects_;                   // triangles per node, in insertion order
  std::size_t outside_ = 0;
};

// SOFA's ray–triangle test (Möller–Trumbore; geometry::Triangle::rayIntersection):
// true when the ray crosses triangle (n0, n1, n2) at t ≥ ε with barycentric
// coordinates u (on n1), v (on n2) within [−ε, 1 + ε]; ε is the double epsilon.
bool ray_triangle_intersection(const Vec3& n0, const Vec3& n1, const Vec3& n2, const Vec3& origin,
                               const Vec3& direction, double& t, double& u, double& v);

}  // namespace sinew
