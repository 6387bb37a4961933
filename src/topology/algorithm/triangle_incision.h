// Incision of a triangle surface along a path (SOFA's TriangleSetGeometryAlgorithms:
// computeIntersectedPointsList / computeIntersectedObjectsList, SplitAlongPath,
// InciseAlongEdgeList), used by TopologicalChangeProcessor's `INCISE=` blocks.
//
// A cut from a to b is done in three steps, as SOFA does them:
//  1. the path: the edges the segment [a, b] crosses, walking from triangle to
//     triangle (each crossing as an edge and a barycentric coordinate on it),
//     framed by the start (a triangle and a's barycentric coordinates, or the
//     last point of the previous cut) and the end (b's triangle, or its vertex
//     when b sits on it);
//  2. the split: one new point per crossed edge and per end inside a triangle,
//     the crossed triangles replaced by smaller ones so that the path is made of
//     edges (points, edges, then triangles added; the old triangles removed);
//  3. the incision: the points along those edges are duplicated (except an end
//     inside the mesh, which stays shared) and the triangles on one side take the
//     copies, so that the two sides no longer share the path.
// Numbering (new points, edges, triangles, removal order) follows SOFA's, since the
// states, masses and force fields that follow depend on it.
//
// The snapped vertices move in the states only (as SOFA's movePointsProcess); the masses do not
// follow the move (see PointSetTopologyModifier::move_points).
#pragma once

#include <string>
#include <vector>

#include "math/types.h"

namespace sinew {

class MeshTopologyBase;
class MechanicalState;
class TriangleSetTopologyModifier;

namespace incision {

inline constexpr unsigned kInvalid = ~0u;

// The objects a path goes through (SOFA's sofa::geometry::ElementType subset).
enum class Elem { point, edge, triangle };

// What the algorithms work on: the triangle container, the state holding the current positions
// (read again after each change: it grows with the new points) and the modifier that edits both.
struct Mesh {
  MeshTopologyBase* topology = nullptr;
  MechanicalState* state = nullptr;
  TriangleSetTopologyModifier* modifier = nullptr;
  Vec3 position(unsigned i) const;
};

// SOFA's computeTriangleBarycoefs (compute3PointsBarycoefs on the current positions): (1/3, 1/3,
// 1/3) for a flat triangle.
Vec3 triangle_barycoefs(const Mesh& m, unsigned tri, const Vec3& p);
// The same for the triangle of points i0, i1, i2 (SOFA's compute3PointsBarycoefs).
Vec3 barycoefs_of_points(const Mesh& m, const Vec3& p, unsigned i0, unsigned i1, unsigned i2);
// SOFA's isPointInsideTriangle without the neighbour search: strictly inside up to -1e-12.
bool is_point_inside_triangle(const Mesh& m, unsigned tri, const Vec3& p);
// TopologicalChangeProcessor::findElementIndex: the triangle holding `p` (AABB then inside test;
// else the projection of p on each triangle's plane), preferring `old_triangle`; kInvalid if none.
unsigned find_element_index(const Mesh& m, const Vec3& p, unsigned old_triangle);

// SOFA's computeIntersectedObjectsList: the path from a (triangle `tri_a`, or point `last_point`
// when valid) to b (triangle `tri_b`). `tri_a` may be corrected (a start on last_point looks
// through its triangles). False when the walk does not reach tri_b (`why` says why).
struct Path {
  std::vector<Elem> kinds;
  std::vector<unsigned> indices;
  std::vector<Vec3> barycoefs;  // triangle: a's coefficients; edge: (coordinate on the edge, 0, 0)
};
bool intersected_objects_list(const Mesh& m, unsigned last_point, const Vec3& a, const Vec3& b, unsigned& tri_a,
                              unsigned& tri_b, Path& path, std::string* why);

// SOFA's SnapAlongPath: the vertices (not on the border) that two or more path objects lie
// within `eps` of replace them in the path; `points2snap` gets one row per such vertex: (vertex,
// x, y, z of the mean position it will move to).
void snap_along_path(const Mesh& m, Path& path, std::vector<std::vector<double>>& points2snap, double eps);

// SOFA's SnapBorderPath: the ends of `path` that are triangles (not `pa`/`pb` when `snapped`
// lists them) snap onto a close vertex or border edge (epsilon: epsilonSnapBorder). May shorten
// the path and move `a`.
void snap_border_path(const Mesh& m, unsigned pa, Vec3& a, unsigned pb, Vec3& b, Path& path,
                      const std::vector<unsigned>& snapped, double eps);

// SOFA's SplitAlongPath: snaps the path (snap_along_path when `eps_path` ≠ 0, then
// snap_border_path when `eps_border` ≠ 0), splits, then moves the snapped vertices onto the path.
// `new_edges`: the edges making the path, in path order. Returns the number of points the path
// created, or -1 on an inconsistent path (`why`).
int split_along_path(Mesh& m, unsigned ind_a, Vec3& a, unsigned ind_b, Vec3& b, Path& path,
                     std::vector<unsigned>& new_edges, double eps_path, double eps_border, std::string* why);

// SOFA's InciseAlongEdgeList: duplicates the points of the connected edge list `edges` and gives
// the copies to the triangles on one side. `end_points`: the ends of the cut left inside the mesh
// (not duplicated); `reach_border` when the cut ends on the border. False (nothing changed, `why`)
// when the edges are not connected or an edge does not have exactly two triangles.
bool incise_along_edge_list(Mesh& m, const std::vector<unsigned>& edges, std::vector<unsigned>& new_points,
                            std::vector<unsigned>& end_points, bool& reach_border, std::string* why);

}  // namespace incision
}  // namespace sinew
