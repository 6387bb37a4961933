// Element tests of LocalMinDistance (spec/interaction.md §2.7), with its
// validity filters. Each test appends 0 or 1 DetectionOutput and returns how
// many it appended; e1 belongs to model 1 of the pair.
//
// The filters look at the mesh around an element (triangles around a point,
// the two triangles along an edge, the models' bothSide flags). The narrow
// phase fills the plain structs below from the element's collision topology;
// the tests only read them (spans over caller-owned arrays, no allocation).
// Elements are assumed active (SOFA's default activer); callers skip
// inactive pairs before calling.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "collision/detection_output.h"
#include "collision/intersect/elements.h"

namespace sinew::local_min_distance {

struct Params {
  double alarm = 1.0;    // alarmDistance [length]
  double contact = 0.5;  // contactDistance [length]
  bool filter_intersection = true;
  double angle_cone = 0.0;       // angleCone: widening of the filter cones [cosine-like, dimensionless]
  double cone_factor = 0.5;      // coneFactor
  bool use_lmd_filters = false;  // true: the filters are left to an external component (none applied here)
};

// What the filter of a point element reads.
struct PointNeighbourhood {
  // A Line collision model is found from the point model's node or an ancestor
  // (SOFA's upward context search). Without one the point is always valid.
  bool line_model_above = false;
  bool both_side = false;  // the point model's bothSide
  // unit_normal() of each triangle around the point, in topology order.
  std::span<const Vec3> triangle_normals;
  // Position of the other end of each edge around the point, in topology order.
  std::span<const Vec3> edge_neighbours;
};

// What the filter of a line element (an edge of the topology) reads.
struct LineNeighbourhood {
  bool both_side = false;  // the line model's bothSide
  // Exactly two triangles around the edge: the cone test with their unit
  // normals. "Left" is the triangle listing the edge's vertex 0 then vertex 1
  // consecutively (see two_triangles()). Otherwise (boundary or free edge) the
  // contact direction must be perpendicular to the edge.
  bool two_triangles = false;
  Vec3 right_normal = Vec3::Zero();
  Vec3 left_normal = Vec3::Zero();
};

// SOFA's triangle normal: normalize((x1−x0)×(x2−x0)) (left unnormalised when
// its norm is below machine epsilon).
Vec3 unit_normal(const Vec3& x0, const Vec3& x1, const Vec3& x2);

// The two-triangle neighbourhood of edge `l` from the first two triangles of
// its shell (topology order): t0 and its vertex indices decide which is left.
LineNeighbourhood two_triangles(const LineElem& l, const std::array<unsigned, 3>& t0_vertices,
                                const std::array<Vec3, 3>& t0, const std::array<Vec3, 3>& t1, bool both_side);

// Validity filters: may a contact leave this element's contact point along
// `pq` (from this element towards the other one)?
bool valid_point(const Params&, const PointElem& p, const PointNeighbourhood&, const Vec3& pq);
bool valid_line(const Params&, const LineElem& l, const LineNeighbourhood&, const Vec3& pq);
bool valid_triangle(const Params&, const TriangleElem& t, bool both_side, const Vec3& pq);

int point_point(const Params&, const PointElem& e1, const PointNeighbourhood& n1, const PointElem& e2,
                const PointNeighbourhood& n2, std::vector<DetectionOutput>& out);
int line_point(const Params&, const LineElem& e1, const LineNeighbourhood& n1, const PointElem& e2,
               const PointNeighbourhood& n2, std::vector<DetectionOutput>& out);
int line_line(const Params&, const LineElem& e1, const LineNeighbourhood& n1, const LineElem& e2,
              const LineNeighbourhood& n2, std::vector<DetectionOutput>& out);
int triangle_point(const Params&, const TriangleElem& e1, bool both_side1, const PointElem& e2,
                   const PointNeighbourhood& n2, std::vector<DetectionOutput>& out);
int triangle_sphere(const Params&, const TriangleElem& e1, bool both_side1, const SphereElem& e2,
                    std::vector<DetectionOutput>& out);
int line_sphere(const Params&, const LineElem& e1, const LineNeighbourhood& n1, const SphereElem& e2,
                std::vector<DetectionOutput>& out);
int sphere_point(const Params&, const SphereElem& e1, const PointElem& e2, const PointNeighbourhood& n2,
                 std::vector<DetectionOutput>& out);
int sphere_sphere(const Params&, const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out);

}  // namespace sinew::local_min_distance
