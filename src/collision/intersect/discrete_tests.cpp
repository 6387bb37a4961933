// DiscreteIntersection element tests (spec/interaction.md §2.3).
#include "collision/intersect/discrete_tests.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/intersect/proximity_math.h"

namespace sinew::discrete {

using namespace intersect_detail;

int sphere_sphere(const SphereElem& e1, const SphereElem& e2, double alarm, double contact,
                  std::vector<DetectionOutput>& out) {
  const double r = e1.r + e2.r;
  const double reach = alarm + r;
  const Vec3 d12 = e2.c - e1.c;
  const double dist2 = norm2(d12);
  // Inclusive bound (`>` rejects), unlike the proximity point tests' strict `<`.
  if (dist2 > reach * reach) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  const double dist = std::sqrt(dist2);
  // No guard for coincident centres: SOFA divides by zero too (normal NaN).
  d.normal = d12 / dist;
  // Each sphere's point faces the other one (rigid: surface point; Vec3: centre).
  d.point1 = e1.contact_point(-d.normal);
  d.point2 = e2.contact_point(d.normal);
  d.value = dist - r - contact;
  return 1;
}

int sphere_sphere(const SphereElem& e1, const SphereElem& e2, std::vector<DetectionOutput>& out) {
  // DiscreteIntersection has no distances of its own and ignores the models' skins.
  return sphere_sphere(e1, e2, 0.0, 0.0, out);
}

int triangle_line(const TriangleElem& e1, const LineElem& e2, std::vector<DetectionOutput>& out) {
  // Solve A + u·AB + v·AC = P + w·PQ.
  const Vec3 AB = e1.b - e1.a, AC = e1.c - e1.a, PQ = e2.b - e2.a;
  Mat3 M;
  M.col(0) = AB;
  M.col(1) = AC;
  M.col(2) = -PQ;
  const double det = M.determinant();
  if (det >= -std::numeric_limits<double>::epsilon() && det <= std::numeric_limits<double>::epsilon()) return 0;
  const Vec3 bary = M.inverse() * (e2.a - e1.a);
  if (bary[0] < 0 || bary[1] < 0 || bary[0] + bary[1] > 1) return 0;  // outside the triangle
  if (bary[2] < 0 || bary[2] > 1) return 0;                           // outside the segment
  const Vec3 X = e2.a + PQ * bary[2];
  DetectionOutput& d = out.emplace_back();
  d.elem1 = e1.info.index;
  d.elem2 = e2.info.index;
  d.id = e2.info.index;
  d.point1 = X;
  d.point2 = X;
  d.normal = e1.normal;
  d.value = 0;
  return 1;
}

int tetrahedron_point(const TetrahedronElem& e1, const PointElem& e2, bool same_state,
                      std::vector<DetectionOutput>& out) {
  const Vec3& n = e2.n;
  if (n == Vec3::Zero()) return 0;  // an interior point, or no normals computed
  if (same_state) {
    const unsigned i = e2.info.index;
    if (i == e1.v[0] || i == e1.v[1] || i == e1.v[2] || i == e1.v[3]) return 0;
  }
  Mat3 m;  // barycentric → world, columns p1−p0, p2−p0, p3−p0
  m.col(0) = e1.p[1] - e1.p[0];
  m.col(1) = e1.p[2] - e1.p[0];
  m.col(2) = e1.p[3] - e1.p[0];
  const Mat3 to_bary = m.inverse();
  const Vec3 b0 = to_bary * (e2.p - e1.p[0]);
  if (b0[0] < 0 || b0[1] < 0 || b0[2] < 0 || b0[0] + b0[1] + b0[2] > 1) return 1;  // outside (SOFA counts it)
  // Distance l along −n to the first face met.
  const Vec3 bdir = to_bary * (-n);
  double l1 = 1.0e10;
  for (int c = 0; c < 3; ++c)
    if (bdir[c] < -1.0e-10) l1 = std::min(l1, -b0[c] / bdir[c]);
  const double bd = bdir[0] + bdir[1] + bdir[2];
  if (bd > 1.0e-10) l1 = std::min(l1, (1 - (b0[0] + b0[1] + b0[2])) / bd);
  if (l1 >= 1.0e9) l1 = 0;
  DetectionOutput& d = out.emplace_back();
  d.elem1 = e1.info.index;
  d.elem2 = e2.info.index;
  d.id = e2.info.index;
  d.point1 = e2.p - n * l1;
  d.point2 = e2.p;
  d.normal = -n;
  d.value = -l1;
  return 1;
}

}  // namespace sinew::discrete
