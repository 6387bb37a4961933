// LocalMinDistance element tests and validity filters (spec/interaction.md §2.7).
//
// Same arithmetic as SOFA (normal equations, literal thresholds, skin
// summation order: SOFA's "e1" is the point or sphere in mixed pairs). Unlike
// MinProximity, coincident points are not guarded: the normal is then 0/0.
// The filters keep only contacts whose direction leaves the surface on its
// outer side (inside cones around the local normals), which is what lets
// LocalMinDistance work on closed meshes without picking the far side.
#include "collision/intersect/local_min_distance_tests.h"

#include <cmath>
#include <limits>

#include "collision/intersect/proximity_math.h"

namespace sinew::local_min_distance {

using namespace intersect_detail;

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// SOFA's Vec::normalize(): divides by the norm only above machine epsilon.
void normalize(Vec3& v) {
  const double n = norm(v);
  if (n > std::numeric_limits<double>::epsilon()) v /= n;
}

Vec3 normalized(Vec3 v) {
  normalize(v);
  return v;
}

// Cone half-opening used by the filters: the side direction's agreement with
// the mean normal, scaled and clamped at zero, widened by angleCone.
double cone(const Params& prm, const Vec3& n_mean, const Vec3& side) {
  double c = dot(n_mean, side) * prm.cone_factor;
  if (c < 0) c = 0.0;
  return c + prm.angle_cone;
}

// value := |v|, normal := v/|v| (no guard), then value −= contact.
void set_normal(DetectionOutput& d, const Vec3& v, double contact) {
  d.value = norm(v);
  d.normal = v / d.value;
  d.value -= contact;
}

// Triangle–point projection, interior only (edges and corners belong to L–P / P–P).
bool project_interior(const TriangleElem& t, const Vec3& p, Vec3& q) {
  const Vec3 AB = t.b - t.a;
  const Vec3 AC = t.c - t.a;
  const Vec3 AP = p - t.a;
  const double a00 = dot(AB, AB);
  const double a11 = dot(AC, AC);
  const double a01 = dot(AB, AC);
  const double b0 = dot(AP, AB);
  const double b1 = dot(AP, AC);
  const double det = a00 * a11 - a01 * a01;
  const double alpha = (b0 * a11 - b1 * a01) / det;
  const double beta = (b1 * a00 - b0 * a01) / det;
  if (alpha < 0.000001 || beta < 0.000001 || alpha + beta > 0.999999) return false;
  q = t.a + AB * alpha + AC * beta;
  return true;
}

// Segment–point projection: refused on a degenerate segment and outside the interior window (no clamping).
bool project_interior(const LineElem& l, const Vec3& p, Vec3& q) {
  const Vec3 AB = l.b - l.a;
  const Vec3 AP = p - l.a;
  if (norm(AB) < 0.000000000001 * norm(AP)) return false;
  const double alpha = dot(AP, AB) / dot(AB, AB);
  if (alpha < 0.000001 || alpha > 0.999999) return false;
  q = l.a + AB * alpha;
  return true;
}

}  // namespace

Vec3 unit_normal(const Vec3& x0, const Vec3& x1, const Vec3& x2) { return normalized(cross(x1 - x0, x2 - x0)); }

LineNeighbourhood two_triangles(const LineElem& l, const std::array<unsigned, 3>& t0_vertices,
                                const std::array<Vec3, 3>& t0, const std::array<Vec3, 3>& t1, bool both_side) {
  const auto& t = t0_vertices;
  const unsigned i1 = l.v[0], i2 = l.v[1];
  // t0 is left when it runs along the edge in the edge's own direction;
  // otherwise t1 is taken as left without checking it.
  const bool t0_left = (i1 == t[0] && i2 == t[1]) || (i1 == t[1] && i2 == t[2]) || (i1 == t[2] && i2 == t[0]);
  const auto& right = t0_left ? t1 : t0;
  const auto& left = t0_left ? t0 : t1;
  LineNeighbourhood n;
  n.both_side = both_side;
  n.two_triangles = true;
  n.right_normal = unit_normal(right[0], right[1], right[2]);
  n.left_normal = unit_normal(left[0], left[1], left[2]);
  return n;
}

bool valid_point(const Params& prm, const PointElem& p, const PointNeighbourhood& nb, const Vec3& pq) {
  if (!prm.filter_intersection || !nb.line_model_above) return true;
  const Vec3& pt = p.p;
  Vec3 n_mean = Vec3::Zero();
  for (const Vec3& n : nb.triangle_normals) n_mean += n;
  // A point of a wire (no triangle): the mean of the directions arriving along its edges.
  if (nb.triangle_normals.empty())
    for (const Vec3& other : nb.edge_neighbours) n_mean += normalized(pt - other);
  const double pq_norm = norm(pq);
  if (norm(n_mean) > 0.0000000001) {
    normalize(n_mean);
    if (dot(n_mean, pq) < -prm.angle_cone * pq_norm && !nb.both_side) return false;
  }
  // Each edge bounds a cone the direction must stay within.
  for (const Vec3& other : nb.edge_neighbours) {
    const Vec3 l = normalized(pt - other);
    if (dot(l, pq) < -cone(prm, n_mean, l) * pq_norm) return false;
  }
  return true;
}

bool valid_line(const Params& prm, const LineElem& line, const LineNeighbourhood& nb, const Vec3& pq) {
  if (!prm.filter_intersection) return true;
  const Vec3 ab = normalized(line.b - line.a);
  if (nb.two_triangles) {
    const Vec3& n1 = nb.right_normal;
    const Vec3& n2 = nb.left_normal;
    const Vec3 t1 = normalized(cross(n1, ab));  // in the right triangle, away from the edge
    const Vec3 t2 = normalized(cross(ab, n2));  // in the left triangle, away from the edge
    Vec3 n_mean = n1;
    n_mean += n2;
    normalize(n_mean);
    if (dot(n_mean, pq) < 0 && !nb.both_side) return false;
    const double pq_norm = norm(pq);
    if (dot(t1, pq) < -cone(prm, n_mean, t1) * pq_norm) return false;
    if (dot(t2, pq) < -cone(prm, n_mean, t2) * pq_norm) return false;
    return true;
  }
  // Boundary or free edge: only directions perpendicular to it (a non-perpendicular
  // one means the L–L solve fell back to the parallel midpoints).
  const Vec3 n = normalized(pq);
  return !(std::fabs(dot(ab, n)) > prm.angle_cone + 0.0001);
}

bool valid_triangle(const Params& prm, const TriangleElem& t, bool both_side, const Vec3& pq) {
  if (!prm.filter_intersection || both_side) return true;
  // Only the side the vertex order faces (unnormalised normal: the sign is all that matters).
  return dot(cross(t.b - t.a, t.c - t.a), pq) >= 0.0;
}

int point_point(const Params& prm, const PointElem& e1, const PointNeighbourhood& n1, const PointElem& e2,
                const PointNeighbourhood& n2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const Vec3 PQ = e2.p - e1.p;
  if (norm2(PQ) >= alarm * alarm) return 0;
  if (!prm.use_lmd_filters && (!valid_point(prm, e1, n1, PQ) || !valid_point(prm, e2, n2, -PQ))) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  d.point1 = e1.p;
  d.point2 = e2.p;
  set_normal(d, PQ, prm.contact + e1.info.cd + e2.info.cd);
  return 1;
}

int line_point(const Params& prm, const LineElem& e1, const LineNeighbourhood& n1, const PointElem& e2,
               const PointNeighbourhood& n2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.info.cd + e1.info.cd;
  Vec3 Q;
  if (!project_interior(e1, e2.p, Q)) return 0;
  const Vec3 PQ = Q - e2.p;  // from the point to the line
  if (norm2(PQ) >= alarm * alarm) return 0;
  const Vec3 QP = -PQ;
  if (!prm.use_lmd_filters && (!valid_point(prm, e2, n2, PQ) || !valid_line(prm, e1, n1, QP))) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e2.info.index);
  d.point1 = Q;
  d.point2 = e2.p;
  set_normal(d, QP, prm.contact + e2.info.cd + e1.info.cd);
  return 1;
}

int line_line(const Params& prm, const LineElem& e1, const LineNeighbourhood& n1, const LineElem& e2,
              const LineNeighbourhood& n2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.info.cd + e2.info.cd;
  const Vec3 AB = e1.b - e1.a;
  const Vec3 CD = e2.b - e2.a;
  const Vec3 AC = e2.a - e1.a;
  const double a00 = dot(AB, AB);
  const double a11 = dot(CD, CD);
  const double a01 = -dot(CD, AB);
  const double b0 = dot(AB, AC);
  const double b1 = -dot(CD, AC);
  const double det = a00 * a11 - a01 * a01;
  double alpha = 0.5;  // parallel: the midpoints (then the free-edge filter usually refuses)
  double beta = 0.5;
  if (det < -1.0e-30 || det > 1.0e-30) {
    alpha = (b0 * a11 - b1 * a01) / det;
    beta = (b1 * a00 - b0 * a01) / det;
    if (alpha < 1e-15 || alpha > (1.0 - 1e-15) || beta < 1e-15 || beta > (1.0 - 1e-15)) return 0;
  }
  const Vec3 P = e1.a + AB * alpha;
  const Vec3 Q = e2.a + CD * beta;
  const Vec3 PQ = Q - P;
  if (norm2(PQ) >= alarm * alarm) return 0;
  if (!prm.use_lmd_filters && (!valid_line(prm, e1, n1, PQ) || !valid_line(prm, e2, n2, -PQ))) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  d.point1 = P;
  d.point2 = Q;
  set_normal(d, PQ, prm.contact + e1.info.cd + e2.info.cd);
  return 1;
}

int triangle_point(const Params& prm, const TriangleElem& e1, bool both_side1, const PointElem& e2,
                   const PointNeighbourhood& n2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.info.cd + e1.info.cd;
  Vec3 Q;
  if (!project_interior(e1, e2.p, Q)) return 0;
  const Vec3 PQ = Q - e2.p;
  if (norm2(PQ) >= alarm * alarm) return 0;
  const Vec3 QP = -PQ;
  if (!prm.use_lmd_filters && (!valid_point(prm, e2, n2, PQ) || !valid_triangle(prm, e1, both_side1, QP))) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e2.info.index);
  d.point1 = Q;
  d.point2 = e2.p;
  set_normal(d, QP, prm.contact + e2.info.cd + e1.info.cd);
  return 1;
}

int triangle_sphere(const Params& prm, const TriangleElem& e1, bool both_side1, const SphereElem& e2,
                    std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.r + e2.info.cd + e1.info.cd;
  Vec3 Q;
  if (!project_interior(e1, e2.c, Q)) return 0;
  const Vec3 PQ = Q - e2.c;
  if (norm2(PQ) >= alarm * alarm) return 0;
  const Vec3 QP = -PQ;
  // Spheres have no filter (always valid).
  if (!prm.use_lmd_filters && !valid_triangle(prm, e1, both_side1, QP)) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e2.info.index);
  d.point1 = Q;
  d.point2 = e2.c;  // the centre, even though the radius is in the distances
  set_normal(d, QP, prm.contact + e2.r + e2.info.cd + e1.info.cd);
  return 1;
}

int line_sphere(const Params& prm, const LineElem& e1, const LineNeighbourhood& n1, const SphereElem& e2,
                std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e2.r + e2.info.cd + e1.info.cd;
  Vec3 Q;
  if (!project_interior(e1, e2.c, Q)) return 0;
  const Vec3 PQ = Q - e2.c;
  const Vec3 QP = -PQ;
  if (norm2(PQ) >= alarm * alarm) return 0;
  if (!prm.use_lmd_filters && !valid_line(prm, e1, n1, QP)) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e2.info.index);
  d.point1 = Q;
  d.point2 = e2.c;
  set_normal(d, QP, prm.contact + e2.r + e2.info.cd + e1.info.cd);
  return 1;
}

int sphere_point(const Params& prm, const SphereElem& e1, const PointElem& e2, const PointNeighbourhood& n2,
                 std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.r + e1.info.cd + e2.info.cd;
  const Vec3 PQ = e2.p - e1.c;
  if (norm2(PQ) >= alarm * alarm) return 0;
  if (!prm.use_lmd_filters && !valid_point(prm, e2, n2, -PQ)) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  d.point1 = e1.c;
  d.point2 = e2.p;
  set_normal(d, PQ, prm.contact + e1.r + e1.info.cd + e2.info.cd);
  return 1;
}

int sphere_sphere(const Params& prm, const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out) {
  const double alarm = prm.alarm + e1.r + e1.info.cd + e2.r + e2.info.cd;
  const Vec3 PQ = e2.c - e1.c;
  if (norm2(PQ) >= alarm * alarm) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  d.point1 = e1.c;
  d.point2 = e2.c;
  set_normal(d, PQ, prm.contact + e1.r + e1.info.cd + e2.r + e2.info.cd);
  return 1;
}

}  // namespace sinew::local_min_distance
